// Tc2_Utilities' native part: F_strun_FormatArg formats one argument of
// FB_FormatString (stdlib/libraries/Tc2_Utilities/format_string.st) by one
// %-specification, printf's rules for flags, width, precision and type.
// A specification that does not fit the argument gives the one-character
// string $01, which the block reports as an error.
#include <cstdio>
#include <cstring>
#include <string>

#include "interpreter/builtins/libraries/library_natives.h"
#include "interpreter/builtins/string_nodes.h"

namespace strun::stdlib::bind {

namespace {

using exec::Ctx;

// E_ArgType (format_string.st).
enum ArgType : int { kByte = 1, kWord, kDword, kReal, kLreal, kSint, kInt, kDint, kUsint, kUint, kUdint, kString, kBool, kBig, kUlarge, kUhuge, kLarge, kHuge, kLword };

std::string formatOne(std::string_view spec, int type, const uint8_t* data) {
    const std::string bad = "\x01";
    if (spec.size() < 2 || spec.front() != '%' || spec.size() > 32) return bad;
    const char conv = spec.back();
    std::string flags(spec.substr(1, spec.size() - 2));
    for (char f : flags)
        if (!std::strchr("-+ #0123456789.", f)) return bad;
    char out[512];
    int n = -1;
    const bool isFloat = type == kReal || type == kLreal;
    const bool isSigned = type == kSint || type == kInt || type == kDint || type == kLarge;
    const bool isInteger = !isFloat && type != kString && type != kBool && type != 0 && type != kBig && type != kUhuge && type != kHuge;
    int64_t si = 0;
    uint64_t ui = 0;
    switch (type) {
        case kByte: case kUsint: case kBool: ui = exec::loadAs<uint8_t>(data); si = static_cast<int64_t>(ui); break;
        case kWord: case kUint: ui = exec::loadAs<uint16_t>(data); si = static_cast<int64_t>(ui); break;
        case kDword: case kUdint: ui = exec::loadAs<uint32_t>(data); si = static_cast<int64_t>(ui); break;
        case kLword: case kUlarge: ui = exec::loadAs<uint64_t>(data); si = static_cast<int64_t>(ui); break;
        case kSint: si = exec::loadAs<int8_t>(data); ui = static_cast<uint64_t>(si); break;
        case kInt: si = exec::loadAs<int16_t>(data); ui = static_cast<uint64_t>(si); break;
        case kDint: si = exec::loadAs<int32_t>(data); ui = static_cast<uint64_t>(si); break;
        case kLarge: si = exec::loadAs<int64_t>(data); ui = static_cast<uint64_t>(si); break;
        default: break;
    }
    const std::string prefix = "%" + flags;
    switch (conv) {
        case 'd':
        case 'i':
            if (!isInteger && type != kBool) return bad;
            n = std::snprintf(out, sizeof out, (prefix + "lld").c_str(), static_cast<long long>(isSigned ? si : static_cast<int64_t>(ui)));
            break;
        case 'u':
        case 'x':
        case 'X':
        case 'o':
            if (!isInteger) return bad;
            n = std::snprintf(out, sizeof out, (prefix + "ll" + conv).c_str(), static_cast<unsigned long long>(ui));
            break;
        case 'b': {
            if (!isInteger) return bad;
            std::string bits;
            for (uint64_t v = ui; v; v >>= 1) bits.insert(bits.begin(), char('0' + (v & 1)));
            if (bits.empty()) bits = "0";
            n = std::snprintf(out, sizeof out, (prefix + "s").c_str(), bits.c_str());
            break;
        }
        case 'f':
        case 'e':
        case 'E':
        case 'g':
        case 'G': {
            double v = type == kReal ? exec::loadAs<float>(data) : type == kLreal ? exec::loadAs<double>(data) : isSigned ? double(si) : double(ui);
            if (!isFloat && !isInteger) return bad;
            n = std::snprintf(out, sizeof out, (prefix + conv).c_str(), v);
            break;
        }
        case 's': {
            if (type == kString) {
                n = std::snprintf(out, sizeof out, (prefix + "s").c_str(), reinterpret_cast<const char*>(data));
            } else if (type == kBool) {
                n = std::snprintf(out, sizeof out, (prefix + "s").c_str(), ui ? "TRUE" : "FALSE");
            } else {
                return bad;
            }
            break;
        }
        case 'c':
            if (!isInteger) return bad;
            n = std::snprintf(out, sizeof out, (prefix + "c").c_str(), static_cast<int>(ui & 0xFF));
            break;
        default: return bad;
    }
    if (n < 0) return bad;
    return std::string(out, std::min<size_t>(static_cast<size_t>(n), sizeof out - 1));
}

struct FormatArgNode final : exec::Expr {
    Expr* spec;
    Expr* type;
    Expr* data;
    uint32_t off;
    FormatArgNode(Expr* s, Expr* t, Expr* d, uint32_t o) : spec(s), type(t), data(d), off(o) {}
    uint8_t* addr(Ctx& c) override {
        const auto* p = reinterpret_cast<const uint8_t*>(static_cast<intptr_t>(data->i(c)));
        // The argument's aData: 256 bytes inside the project's memory (the block passes ADR of it).
        std::string text = p && c.m->memory.contains(p, 256) ? formatOne(viewOf<char>(spec, c), static_cast<int>(type->i(c)), p) : "\x01";
        return writeString<char>(c, off, 255, std::string_view(text));
    }
};

}  // namespace

void registerTc2UtilitiesNatives(Checker& ck) {
    ck.addBuiltin("F_STRUN_FORMATARG", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"SPEC"}, {"TYPE"}, {"DATA"}}, a)) return ck.bad(call.loc);
        if (!isStringArg(a[0], false)) return argError(ck, a[0], call.name, "spec must be a STRING");
        Checked t = ck.coerce(a[1], ck.types().elementary(TK::DInt), a[1].loc, call.name.c_str());
        if (!t.ok) return t;
        Checked d = a[2];
        if (!(d.type && d.type->kind == TK::Pointer)) d = ck.coerce(d, ck.types().elementary(TK::ULInt), d.loc, call.name.c_str());
        if (!d.ok) return d;
        const Type* rt = ck.types().string(255, false);
        auto* n = ck.pool().make<FormatArgNode>(a[0].node, t.node, d.node, ck.allocTemp(rt->size));
        return makeResult(ck, n, rt, call, a, false);
    });
}

}  // namespace strun::stdlib::bind
