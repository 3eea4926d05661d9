// Conversions the checker leaves to the library: every X_TO_STRING,
// X_TO_WSTRING, STRING_TO_X, WSTRING_TO_X and the overloaded TO_STRING /
// TO_WSTRING; BCD (*_BCD_TO_*, *_TO_BCD_*, BCD_TO_*, TO_BCD_*); TO/FROM_BIG/
// LITTLE_ENDIAN; IS_VALID; IS_VALID_BCD.
#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "interpreter/builtins/bind_support.h"
#include "interpreter/builtins/convert_nodes.h"
#include "interpreter/builtins/register_groups.h"
#include "interpreter/builtins/string_nodes.h"

namespace strun::stdlib::bind {

namespace {

// Conversion-name spellings of the elementary types (long forms included).
const char* const kTypeNames[] = {
    "BOOL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "BYTE", "WORD", "DWORD", "LWORD",
    "REAL", "LREAL", "TIME", "LTIME", "DATE", "LDATE", "TOD", "LTOD", "DT", "LDT", "TIME_OF_DAY", "LTIME_OF_DAY",
    "DATE_AND_TIME", "LDATE_AND_TIME", "CHAR", "WCHAR",
};

bool valueClassOf(const Type* t, ValueClass& out) {
    TK k = t->kind == TK::Enum ? t->base->kind : t->kind;
    switch (k) {
        case TK::Bool: out = ValueClass::Bool; return true;
        case TK::Real: out = ValueClass::Real; return true;
        case TK::LReal: out = ValueClass::LReal; return true;
        case TK::Time: out = t->unsignedDuration ? ValueClass::TimeUnsigned : ValueClass::Time; return true;
        case TK::LTime: out = t->unsignedDuration ? ValueClass::LTimeUnsigned : ValueClass::LTime; return true;
        case TK::Date: out = ValueClass::Date; return true;
        case TK::LDate: out = ValueClass::LDate; return true;
        case TK::Tod: out = ValueClass::Tod; return true;
        case TK::LTod: out = ValueClass::LTod; return true;
        case TK::Dt: out = ValueClass::Dt; return true;
        case TK::LDt: out = ValueClass::LDt; return true;
        case TK::Char: out = ValueClass::Char; return true;
        case TK::WChar: out = ValueClass::WChar; return true;
        case TK::String: out = ValueClass::String; return true;
        case TK::WString: out = ValueClass::WString; return true;
        default: break;
    }
    if (sema::isSignedInt(k)) { out = ValueClass::Signed; return true; }
    if (sema::isUnsignedInt(k) || sema::isBitString(k)) { out = ValueClass::Unsigned; return true; }
    return false;
}

// Longest text a value of class k formats to (LTIME#-106751d23h47m16s854ms775us808ns is 39).
int64_t textLength(ValueClass k, const Type* t) {
    if (k == ValueClass::String) return int64_t(t->maxLen);
    if (k == ValueClass::WString) return 3 * int64_t(t->maxLen);  // UTF-8: up to 3 bytes per UTF-16 unit
    return 64;
}

// TO_STRING of an enumeration with {attribute 'to_string'}: the value's name
// as declared; a value no enumerator has gives its number.
struct EnumNameNode final : exec::Expr {
    exec::Expr* in;
    const Type* enumType;
    bool wide;
    uint32_t off = 0, maxLen = 0;
    EnumNameNode(exec::Expr* e, const Type* t, bool w) : in(e), enumType(t), wide(w) {}
    uint8_t* addr(exec::Ctx& c) override {
        int64_t v = in->i(c);
        char number[24];
        std::string_view text;
        for (const auto& en : enumType->enumerators)
            if (en.value == v) { text = en.name; break; }
        if (text.empty()) {
            int n = std::snprintf(number, sizeof number, "%lld", static_cast<long long>(v));
            text = std::string_view(number, n > 0 ? static_cast<size_t>(n) : 0);
        }
        size_t n = std::min<size_t>(text.size(), maxLen);
        if (!wide) return writeString<char>(c, off, maxLen, text.substr(0, n));
        auto* dst = reinterpret_cast<char16_t*>(c.frame + off);
        for (size_t k = 0; k < n; ++k) dst[k] = static_cast<unsigned char>(text[k]);  // names are ASCII identifiers
        dst[n] = 0;
        return reinterpret_cast<uint8_t*>(dst);
    }
};

void addToString(Checker& ck, std::string_view name, const Type* from, bool wide) {
    struct ToStringData { const Type* from; bool wide; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [from, wide] = self.data<ToStringData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
        Checked x = a[0];
        if (from) {
            if (sema::isStringType(from->kind)) {
                if (x.type->kind != from->kind) return argError(ck, x, call.name, fmt::format("the input must be {}", from->name));
            } else {
                x = ck.coerce(x, from, x.loc, call.name.c_str());
                if (!x.ok) return x;
            }
        } else {
            x = ck.settle(x);
            // TO_STRING(pValue): a pointer is its address, an unsigned integer of
            // its width, as TwinCAT converts it (decision 0326).
            x = Checker::pointerAsAddress(x, ck.types().elementary(TK::ULInt));
        }
        if (!from && x.type->kind == TK::Enum && x.type->enumToString) {
            const Type* t = stringResultType(ck, wide, 80);
            auto* e = ck.pool().make<EnumNameNode>(x.node, x.type, wide);
            e->maxLen = t->maxLen;
            e->off = ck.allocTemp(t->size);
            return makeResult(ck, e, t, call, a, false);
        }
        ValueClass vc;
        if (!valueClassOf(x.type, vc)) return argError(ck, x, call.name, "the input must be an elementary value");
        const Type* t = stringResultType(ck, wide, textLength(vc, x.type));
        if (ck.compileOptions().twincatRealText && (vc == ValueClass::Real || vc == ValueClass::LReal))
            vc = vc == ValueClass::Real ? ValueClass::RealTwinCat : ValueClass::LRealTwinCat;
        exec::Expr* n;
        if (wide) {
            auto* w = ck.pool().make<ToStringNode<char16_t>>(x.node, vc);
            w->maxLen = t->maxLen;
            w->off = ck.allocTemp(t->size);
            n = w;
        } else {
            auto* s = ck.pool().make<ToStringNode<char>>(x.node, vc);
            s->maxLen = t->maxLen;
            s->off = ck.allocTemp(t->size);
            n = s;
        }
        return makeResult(ck, n, t, call, a);
    }, ToStringData{from, wide}));
}

// STRING_TO_X / WSTRING_TO_X; with `either`, the overloaded TO_X of a STRING or
// a WSTRING (TO_LREAL(sValue)), whose numeric sources checkConversionCall takes.
void addFromString(Checker& ck, std::string_view name, bool wide, const Type* to, bool either = false) {
    struct FromStringData { bool wide; const Type* to; bool either; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [wide, to, either] = self.data<FromStringData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
        const bool wideSource = either ? isStringArg(a[0], true) : wide;
        if (!isStringArg(a[0], wideSource))
            return argError(ck, a[0], call.name, either ? "the input must be a number, a STRING or a WSTRING" : fmt::format("the input must be {}", wide ? "WSTRING" : "STRING"));
        ValueClass vc;
        valueClassOf(to, vc);
        TK view = sema::integerView(to->kind);
        auto* n = ck.pool().make<FromStringNode>(a[0].node, wideSource, vc, sema::bitWidth(view), sema::isSignedInt(view));
        return makeResult(ck, n, to, call, a);
    }, FromStringData{wide, to, either}));
}

int bytesOf(TK k) { return sema::bitWidth(k) / 8; }

const Type* bitTypeForLiteral(Checker& ck, const Checked& a) {
    if (!a.untypedInt) return a.type;
    uint64_t v = static_cast<uint64_t>(a.constInt);
    return ck.types().elementary(v <= 0xFF ? TK::Byte : v <= 0xFFFF ? TK::Word : v <= 0xFFFFFFFFull ? TK::DWord : TK::LWord);
}

// BIT_BCD_TO_INT (from given) or BCD_TO_INT (from = null: any bit string).
void addBcdToInt(Checker& ck, std::string_view name, const Type* from, const Type* to) {
    struct BcdToIntData { const Type* from; const Type* to; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [from, to] = self.data<BcdToIntData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
        const Type* src = from ? from : bitTypeForLiteral(ck, a[0]);
        if (!sema::isBitString(src->kind)) return argError(ck, a[0], call.name, "the input must be a bit string (BCD)");
        Checked x = ck.coerce(a[0], src, a[0].loc, call.name.c_str());
        if (!x.ok) return x;
        TK view = sema::integerView(to->kind);
        auto* n = ck.pool().make<BcdToIntNode>(x.node, bytesOf(src->kind), sema::bitWidth(view), sema::isSignedInt(view));
        return makeResult(ck, n, to, call, a);
    }, BcdToIntData{from, to}));
}

// INT_TO_BCD_BIT (from given) or TO_BCD_BIT (from = null: any integer).
void addIntToBcd(Checker& ck, std::string_view name, const Type* from, const Type* to) {
    struct IntToBcdData { const Type* from; const Type* to; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [from, to] = self.data<IntToBcdData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
        Checked x = a[0];
        if (from) x = ck.coerce(x, from, x.loc, call.name.c_str());
        else if (!isIntegerArg(x)) return argError(ck, x, call.name, "the input must be an integer");
        else x = ck.settle(x);
        if (!x.ok) return x;
        auto* n = ck.pool().make<IntToBcdNode>(x.node, bytesOf(to->kind));
        return makeResult(ck, n, to, call, a);
    }, IntToBcdData{from, to}));
}

// CODESYS Util's BCD functions (decision 0386): INT_TO_BCD(I : INT) : BYTE
// (255 outside 0..99) and BCD_TO_INT(B : BYTE) : INT (-1 for a byte that is
// not BCD; here any bit string, as before), BYTE/WORD/DWORD_TO_BCD and
// BCD_TO_BYTE/WORD/DWORD (same width in and out; all ones outside the range,
// decision 0036). With --strict, INT_TO_BCD is IEC 61131-3's conversion with
// an ANY_BIT result, taken as WORD (Annex F's WEIGH returns it as a WORD).
void addUtilBcd(Checker& ck, std::string_view name, TK fromKind, TK toKind, bool toBcd, const char* formal) {
    struct UtilBcdData { TK fromKind; TK toKind; bool toBcd; const char* formal; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [fromKind, toKind, toBcd, formal] = self.data<UtilBcdData>();
        std::vector<Checked> a;
        std::string names = std::string(formal) + "|IN";
        if (!bindFixed(ck, call, {{names.c_str()}}, a)) return ck.bad(call.loc);
        TK target = toKind;
        if (toBcd && fromKind == TK::Int && ck.compileOptions().strict) target = TK::Word;
        const Type* from = ck.types().elementary(fromKind);
        const Type* to = ck.types().elementary(target);
        Checked x = ck.coerce(a[0], from, a[0].loc, call.name.c_str());
        if (!x.ok) return x;
        if (toBcd) return makeResult(ck, ck.pool().make<IntToBcdNode>(x.node, bytesOf(target)), to, call, a);
        TK view = sema::integerView(target);
        auto* n = ck.pool().make<BcdToIntNode>(x.node, bytesOf(fromKind), sema::bitWidth(view), sema::isSignedInt(view));
        return makeResult(ck, n, to, call, a);
    }, UtilBcdData{fromKind, toKind, toBcd, formal}));
}

void addByteOrder(Checker& ck, const char* name, ByteOrderFn fn) {
    struct ByteOrderData { ByteOrderFn fn; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [fn] = self.data<ByteOrderData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
        if (!isIntegerArg(a[0]) && !isBitArg(a[0])) return argError(ck, a[0], call.name, "the input must be an integer or a bit string");
        Checked x = ck.settle(a[0]);
        TK view = sema::integerView(x.type->kind);
        auto* n = ck.pool().make<ByteOrderNode>(x.node, fn, bytesOf(x.type->kind), sema::isSignedInt(view));
        return makeResult(ck, n, x.type, call, a);
    }, ByteOrderData{fn}));
}

Checked checkIsValid(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
    if (!a[0].untypedReal && !sema::isReal(a[0].type->kind)) return argError(ck, a[0], call.name, "the input must be REAL or LREAL");
    Checked x = ck.settle(a[0]);
    return makeResult(ck, ck.pool().make<IsValidRealNode>(x.node), ck.types().elementary(TK::Bool), call, a);
}

Checked checkIsValidBcd(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
    const Type* src = bitTypeForLiteral(ck, a[0]);
    if (!sema::isBitString(src->kind)) return argError(ck, a[0], call.name, "the input must be a bit string");
    Checked x = ck.coerce(a[0], src, a[0].loc, call.name.c_str());
    if (!x.ok) return x;
    return makeResult(ck, ck.pool().make<IsValidBcdNode>(x.node, bytesOf(src->kind)), ck.types().elementary(TK::Bool), call, a);
}

}  // namespace

void registerConvert(Checker& ck) {
    auto& types = ck.types();
    // The generated names are built in one buffer: the registry copies them.
    std::string buffer;
    buffer.reserve(64);
    auto name = [&buffer](std::string_view a, std::string_view b, std::string_view c = {}) -> std::string_view {
        buffer.assign(a).append(b).append(c);
        return buffer;
    };
    for (const char* n : kTypeNames) {
        const Type* t = types.byName(n);
        if (!t) continue;
        addToString(ck, name(n, "_TO_STRING"), t, false);
        addToString(ck, name(n, "_TO_WSTRING"), t, true);
        addFromString(ck, name("STRING_TO_", n), false, t);
        addFromString(ck, name("WSTRING_TO_", n), true, t);
        addFromString(ck, name("TO_", n), false, t, true);
    }
    addToString(ck, "STRING_TO_WSTRING", types.elementary(TK::String), true);
    addToString(ck, "WSTRING_TO_STRING", types.elementary(TK::WString), false);
    addToString(ck, "TO_STRING", nullptr, false);
    addToString(ck, "TO_WSTRING", nullptr, true);

    const TK bits[] = {TK::Byte, TK::Word, TK::DWord, TK::LWord};
    const TK ints[] = {TK::SInt, TK::Int, TK::DInt, TK::LInt, TK::USInt, TK::UInt, TK::UDInt, TK::ULInt};
    for (TK b : bits) {
        const Type* bt = types.elementary(b);
        addIntToBcd(ck, name("TO_BCD_", bt->name), nullptr, bt);
        for (TK i : ints) {
            const Type* it = types.elementary(i);
            addBcdToInt(ck, name(bt->name, "_BCD_TO_", it->name), bt, it);
            addIntToBcd(ck, name(it->name, "_TO_BCD_", bt->name), it, bt);
        }
    }
    for (TK i : ints) addBcdToInt(ck, name("BCD_TO_", types.elementary(i)->name), nullptr, types.elementary(i));
    addUtilBcd(ck, "INT_TO_BCD", TK::Int, TK::Byte, true, "I");
    addUtilBcd(ck, "BYTE_TO_BCD", TK::Byte, TK::Byte, true, "B");
    addUtilBcd(ck, "WORD_TO_BCD", TK::Word, TK::Word, true, "W");
    addUtilBcd(ck, "DWORD_TO_BCD", TK::DWord, TK::DWord, true, "X");
    addUtilBcd(ck, "BCD_TO_BYTE", TK::Byte, TK::Byte, false, "B");
    addUtilBcd(ck, "BCD_TO_WORD", TK::Word, TK::Word, false, "W");
    addUtilBcd(ck, "BCD_TO_DWORD", TK::DWord, TK::DWord, false, "X");

    addByteOrder(ck, "TO_BIG_ENDIAN", ByteOrderFn::ToBig);
    addByteOrder(ck, "FROM_BIG_ENDIAN", ByteOrderFn::FromBig);
    addByteOrder(ck, "TO_LITTLE_ENDIAN", ByteOrderFn::ToLittle);
    addByteOrder(ck, "FROM_LITTLE_ENDIAN", ByteOrderFn::FromLittle);
    ck.addBuiltin("IS_VALID", checkIsValid);
    ck.addBuiltin("IS_VALID_BCD", checkIsValidBcd);
}

}  // namespace strun::stdlib::bind
