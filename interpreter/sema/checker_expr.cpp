// Expressions: literals, names, members, subscripts, operators and the
// implicit conversions of IEC 61131-3.
#include <cmath>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "interpreter/exec/class_part_nodes.h"
#include "interpreter/exec/flex_ref_nodes.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/expr_observer.h"
#include "interpreter/sema/fuse.h"
#include "interpreter/sema/node_factory.h"
#include "stdlib/ascii_case.h"
#include "stdlib/literals.h"
#include "stdlib/time_literals.h"

namespace strun::sema {

using exec::CmpOp;

namespace {

bool fitsIn(int64_t v, bool untypedUnsignedBig, const Type* t) {
    TK k = t->kind == TK::Enum ? t->base->kind : t->kind;
    if (k == TK::Bool) return !untypedUnsignedBig && (v == 0 || v == 1);
    TK view = integerView(k);
    int bits = bitWidth(view);
    if (isSignedInt(view)) {
        if (untypedUnsignedBig) return false;
        if (bits >= 64) return true;
        int64_t lo = -(int64_t(1) << (bits - 1)), hi = (int64_t(1) << (bits - 1)) - 1;
        return v >= lo && v <= hi;
    }
    if (untypedUnsignedBig) return bits >= 64;
    if (v < 0) return false;
    if (bits >= 64) return true;
    return static_cast<uint64_t>(v) <= ((uint64_t(1) << bits) - 1);
}

// Natural type of an untyped integer literal: DINT, LINT or ULINT.
TK naturalIntKind(const Checked& c) {
    if (c.constInt >= std::numeric_limits<int32_t>::min() && c.constInt <= std::numeric_limits<int32_t>::max()) return TK::DInt;
    return TK::LInt;
}

}  // namespace

exec::Site Checker::site(const ast::Loc& loc) { return exec::Site{currentPouName_, loc.line, loc.file, loc.col}; }

// A STRING(len) or WSTRING(len) constant of the text's bytes (its code units
// for a WSTRING), zero-padded to the type's size.
Checked Checker::constantString(std::vector<uint8_t> bytes, size_t len, bool wide, const ast::Loc& loc) {
    Checked c;
    c.ok = true;
    c.isConst = true;
    c.loc = loc;
    c.type = types().string(static_cast<uint32_t>(std::max<size_t>(len, 1)), wide);
    bytes.resize(c.type->size, 0);
    c.node = pool().make<exec::ConstBytes>(std::move(bytes));
    c.node->type = c.type;
    return c;
}

Checked Checker::constInt(int64_t v, const Type* t, const ast::Loc& loc) {
    Checked c;
    c.ok = true;
    c.type = t;
    c.isConst = true;
    c.constInt = v;
    c.constReal = static_cast<double>(v);
    c.loc = loc;
    c.node = pool().make<exec::ConstInt>(v);
    c.node->type = t;
    return c;
}

Checked Checker::constReal(double v, const Type* t, const ast::Loc& loc) {
    Checked c;
    c.ok = true;
    c.type = t;
    c.isConst = true;
    if (t->kind == TK::Real) v = static_cast<double>(static_cast<float>(v));
    c.constReal = v;
    c.loc = loc;
    c.node = pool().make<exec::ConstReal>(v);
    c.node->type = t;
    return c;
}

Checked Checker::settle(Checked e) {
    if (e.untypedInt) {
        e.untypedInt = false;
        e.type = types().elementary(naturalIntKind(e));
        e.node->type = e.type;
    } else if (e.untypedReal) {
        e.untypedReal = false;
        e.type = types().elementary(TK::LReal);
        e.node->type = e.type;
    }
    return e;
}

// ---------------------------------------------------------------- literals

Checked Checker::checkLiteral(const ast::Expr& e) {
    auto fail = [&](diag::Code code, const std::string& why) {
        error(code, e.loc, why);
        return bad(e.loc);
    };
    switch (e.lit) {
        case ast::LitKind::Integer: {
            auto r = stdlib::parseIntegerLiteral(e.text);
            if (!r) return fail(diag::E0011, fmt::format("invalid integer literal '{}': {}", e.text.substr(0, 40), r.error()));
            Checked c = constInt(static_cast<int64_t>(r.value()), types().elementary(TK::LInt), e.loc);
            if (r.value() > static_cast<uint64_t>(std::numeric_limits<int64_t>::max())) {
                c.type = types().elementary(TK::ULInt);
                c.node->type = c.type;
                c.constReal = static_cast<double>(r.value());
                return c;  // only fits ULINT / LWORD
            }
            c.untypedInt = true;
            c.type = types().elementary(naturalIntKind(c));
            c.node->type = c.type;
            return c;
        }
        case ast::LitKind::Real: {
            auto r = stdlib::parseRealLiteral(e.text);
            if (!r) return fail(diag::E0011, fmt::format("invalid real literal '{}': {}", e.text.substr(0, 40), r.error()));
            Checked c = constReal(r.value(), types().elementary(TK::LReal), e.loc);
            c.untypedReal = true;
            return c;
        }
        case ast::LitKind::Bool: {
            bool v = upper(e.text) == "TRUE";
            return constInt(v, types().elementary(TK::Bool), e.loc);
        }
        case ast::LitKind::String:
        case ast::LitKind::WString: {
            bool wide = e.lit == ast::LitKind::WString;
            std::vector<uint8_t> bytes;
            size_t len = 0;
            if (wide) {
                auto r = stdlib::parseWideStringLiteral(e.text);
                if (!r) return fail(diag::E0011, fmt::format("invalid string literal: {}", r.error()));
                len = r.value().size();
                bytes.resize((len + 1) * 2);
                std::memcpy(bytes.data(), r.value().data(), len * 2);
            } else {
                auto r = stdlib::parseStringLiteral(e.text);
                if (!r) return fail(diag::E0011, fmt::format("invalid string literal: {}", r.error()));
                len = r.value().size();
                bytes.resize(len + 1);
                std::memcpy(bytes.data(), r.value().data(), len);
            }
            if (len > 65535) return fail(diag::E0007, "string literal longer than 65535 characters");
            return constantString(std::move(bytes), len, wide, e.loc);
        }
        case ast::LitKind::Duration: {
            std::string u = upper(e.text);
            bool isLong = u.rfind("LT", 0) == 0;
            bool saturated = false;
            uint64_t unsignedBits = 0;
            auto r = stdlib::parseDurationLiteral(e.text, isLong, &saturated, &unsignedBits);
            if (!r) return fail(diag::E0011, fmt::format("invalid duration literal '{}': {}", e.text.substr(0, 40), r.error()));
            // A TwinCAT project keeps LTIME unsigned: the literal's own bits (decision 0367).
            const Type* ltime = types().elementary(TK::LTime);
            if (saturated && ltime->unsignedDuration) return constInt(static_cast<int64_t>(unsignedBits), ltime, e.loc);
            if (saturated)  // TwinCAT's LTIME is unsigned; strun's is signed elsewhere (decisions 0092, 0367)
                warning(diag::W0005, e.loc, fmt::format("'{}' is beyond the largest LTIME (2^63-1 ns); it is taken as LTIME#106751d23h47m16s854ms775us807ns", e.text.substr(0, 60)));
            if (isLong) return constInt(r.value(), types().elementary(TK::LTime), e.loc);
            int64_t ms = r.value() / 1000000;
            // A TwinCAT project's TIME is unsigned: up to T#49d17h2m47s295ms as it is (decision 0367).
            const Type* time = types().elementary(TK::Time);
            if (time->unsignedDuration && ms > std::numeric_limits<int32_t>::max() && ms <= int64_t{std::numeric_limits<uint32_t>::max()})
                return constInt(ms, time, e.loc);
            // TwinCAT's and CODESYS' TIME is unsigned up to T#49d17h2m47s295ms; strun's
            // is signed (negative durations, the --dump format), so a literal above
            // T#24d20h31m23s647ms is taken as that, with a warning (decision 0277).
            if (ms > std::numeric_limits<int32_t>::max() && ms <= int64_t{std::numeric_limits<uint32_t>::max()}) {
                warning(diag::W0041, e.loc, fmt::format("'{}' is beyond the largest TIME (2^31-1 ms); it is taken as T#24d20h31m23s647ms",
                                           e.text.substr(0, 60)));
                ms = std::numeric_limits<int32_t>::max();
            }
            if (ms > std::numeric_limits<int32_t>::max() || ms < std::numeric_limits<int32_t>::min())
                return fail(diag::E0205, fmt::format("'{}' is outside the range of TIME (32-bit milliseconds); use LTIME", e.text));
            return constInt(ms, types().elementary(TK::Time), e.loc);
        }
        case ast::LitKind::Date:
        case ast::LitKind::TimeOfDay:
        case ast::LitKind::DateTime: {
            std::string u = upper(e.text);
            bool isLong = u[0] == 'L';
            stdlib::Result<int64_t> r = e.lit == ast::LitKind::Date ? stdlib::parseDateLiteral(e.text)
                                        : e.lit == ast::LitKind::TimeOfDay ? stdlib::parseTimeOfDayLiteral(e.text)
                                                                          : stdlib::parseDateTimeLiteral(e.text);
            if (!r) return fail(diag::E0011, fmt::format("invalid literal '{}': {}", e.text.substr(0, 40), r.error()));
            if (isLong) {
                TK k = e.lit == ast::LitKind::Date ? TK::LDate : e.lit == ast::LitKind::TimeOfDay ? TK::LTod : TK::LDt;
                return constInt(r.value(), types().elementary(k), e.loc);
            }
            if (e.lit == ast::LitKind::TimeOfDay) return constInt(r.value() / 1000000, types().elementary(TK::Tod), e.loc);
            int64_t secs = r.value() / 1000000000;
            if (r.value() < 0 || secs > 0xFFFFFFFFll)
                return fail(diag::E0205, fmt::format("'{}' is outside the range of {} (1970..2106); use the L-form", e.text,
                                        e.lit == ast::LitKind::Date ? "DATE" : "DT"));
            return constInt(secs, types().elementary(e.lit == ast::LitKind::Date ? TK::Date : TK::Dt), e.loc);
        }
        case ast::LitKind::Typed: {
            const Type* t = resolveNamedType(e.typePrefix, e.loc);
            if (!t) return bad(e.loc);
            const std::string& v = e.valueText;
            if (t->kind == TK::Enum) {
                if (const Enumerator* en = t->findEnumerator(upper(v))) return constInt(en->value, t, e.loc);
                enumValueError(e.loc, v, t);
                return bad(e.loc);
            }
            if (t->kind == TK::Bool) {
                std::string uv = upper(v);
                if (uv == "1" || uv == "TRUE") return constInt(1, t, e.loc);
                if (uv == "0" || uv == "FALSE") return constInt(0, t, e.loc);
                return fail(diag::E0011, fmt::format("invalid BOOL literal '{}'", v));
            }
            if (isReal(t->kind)) {
                auto r = stdlib::parseRealLiteral(v);
                if (!r) return fail(diag::E0011, fmt::format("invalid real literal '{}': {}", v, r.error()));
                return constReal(r.value(), t, e.loc);
            }
            if (isInteger(t->kind) || isBitString(t->kind)) {
                bool neg = !v.empty() && v[0] == '-';
                std::string_view body = v;
                if (!body.empty() && (body[0] == '-' || body[0] == '+')) body.remove_prefix(1);
                auto r = stdlib::parseIntegerLiteral(body);
                if (!r) return fail(diag::E0011, fmt::format("invalid integer literal '{}': {}", v, r.error()));
                uint64_t mag = r.value();
                bool big = mag > static_cast<uint64_t>(std::numeric_limits<int64_t>::max());
                int64_t val = neg ? static_cast<int64_t>(0 - mag) : static_cast<int64_t>(mag);
                if (neg && big && mag != (uint64_t(1) << 63)) return fail(diag::E0205, fmt::format("'{}#{}' is out of range", e.typePrefix, v));
                bool fits = fitsIn(val, big && !neg, t);
                if (!fits) return fail(diag::E0205, fmt::format("'{}#{}' is outside the range of {}", e.typePrefix, v, t->name));
                return constInt(val, t, e.loc);
            }
            if (isCharType(t->kind) && !v.empty() && v[0] != '\'' && v[0] != '"') {
                // `CHAR#16#80` (SIMATIC AX's md5): a character given by its code (decision 0434).
                auto r = stdlib::parseIntegerLiteral(v);
                if (!r) return fail(diag::E0011, fmt::format("invalid character code '{}#{}': {}", e.typePrefix, v, r.error()));
                const uint64_t limit = t->kind == TK::WChar ? 0xFFFF : 0xFF;
                if (r.value() > limit) return fail(diag::E0205, fmt::format("'{}#{}' is outside the range of {}", e.typePrefix, v, t->name));
                const std::string asText = t->kind == TK::WChar ? fmt::format("\"${:04X}\"", r.value()) : fmt::format("'${:02X}'", r.value());
                if (refusedByStrict(diag::E0011, e.loc, fmt::format("'{}#{}' (a character by its code) is a SIMATIC AX form; --strict needs {}#{}",
                                                                    e.typePrefix, v, e.typePrefix, asText)))
                    return bad(e.loc);
                return constInt(static_cast<int64_t>(r.value()), t, e.loc);
            }
            if (isStringType(t->kind) || isCharType(t->kind) || isTimeLike(t->kind) || isDateLike(t->kind)) {
                ast::Expr inner;
                inner.kind = ast::ExprKind::Literal;
                inner.loc = e.loc;
                inner.text = v;
                if (isStringType(t->kind) || isCharType(t->kind)) inner.lit = (t->kind == TK::WString || t->kind == TK::WChar) ? ast::LitKind::WString : ast::LitKind::String;
                else if (isTimeLike(t->kind)) { inner.lit = ast::LitKind::Duration; inner.text = (t->kind == TK::LTime ? "LTIME#" : "TIME#") + v; }
                else if (t->kind == TK::Date || t->kind == TK::LDate) { inner.lit = ast::LitKind::Date; inner.text = (t->kind == TK::LDate ? "LDATE#" : "DATE#") + v; }
                else if (t->kind == TK::Tod || t->kind == TK::LTod) { inner.lit = ast::LitKind::TimeOfDay; inner.text = (t->kind == TK::LTod ? "LTOD#" : "TOD#") + v; }
                else { inner.lit = ast::LitKind::DateTime; inner.text = (t->kind == TK::LDt ? "LDT#" : "DT#") + v; }
                if (isCharType(t->kind)) {
                    Checked s = checkLiteral(inner);
                    if (!s.ok) return s;
                    auto* bytes = static_cast<exec::ConstBytes*>(s.node);
                    int64_t ch = t->kind == TK::WChar ? (bytes->bytes[0] | (bytes->bytes[1] << 8)) : bytes->bytes[0];
                    return constInt(ch, t, e.loc);
                }
                Checked s = checkLiteral(inner);
                if (s.ok && isStringType(t->kind)) return coerce(s, t, e.loc, "literal");
                return s;
            }
            return fail(diag::E0011, fmt::format("'{}' cannot prefix a literal", e.typePrefix));
        }
    }
    return bad(e.loc);
}

// ---------------------------------------------------------------- names

VarSym* Checker::lookupVar(const std::string& key) {
    if (pou_) {
        for (PouInfo* p = pou_; p; p = p->parent) {
            auto it = p->vars.find(key);
            if (it != p->vars.end()) return it->second;
        }
        if (pou_->owner)
            for (PouInfo* p = pou_->owner; p; p = p->parent) {
                auto it = p->vars.find(key);
                if (it != p->vars.end()) return it->second;
            }
    }
    // strun's embedded library sees no user globals: a user's `max : INT` must not
    // change what MAX means inside stdlib/util.st (defect 1 of issue 8). It
    // sees its own (Tc3_Module's S_OK, Tc2_MC2's error codes).
    auto g = globals_.find(key);
    if (g == globals_.end()) return nullptr;
    if (pou_ && pou_->ast && libraryFiles_.count(pou_->ast->loc.file) && !libraryFiles_.count(g->second->loc.file)) return nullptr;
    return g->second;
}

template <class T>
using Index1Self = exec::Index1Var<T, exec::BaseKind::Self>;
template <class T>
using Index1Frame = exec::Index1Var<T, exec::BaseKind::Frame>;
template <class T>
using Index1Abs = exec::Index1Var<T, exec::BaseKind::Abs>;

namespace {
exec::Expr* directNode(exec::NodePool& pool, Checked::Direct d, uint32_t off, uint8_t* abs, const Type* t) {
    Rep rep = isAggregate(t) ? Rep::Void : repOf(t);
    switch (d) {
        case Checked::Direct::Self: return makeByRep<exec::SelfVar>(pool, rep, off);
        case Checked::Direct::Frame: return makeByRep<exec::FrameVar>(pool, rep, off);
        case Checked::Direct::Pending: return makeByRep<exec::PendingVar>(pool, rep, off);
        default: return makeByRep<exec::AbsVar>(pool, rep, abs + off);
    }
}
}  // namespace

exec::Expr* Checker::loadFrom(exec::Expr* place, const Type* t) {
    if (isAggregate(t)) return place;
    exec::Expr* n = makeByRep<exec::PlaceLoad>(pool(), repOf(t), place);
    n->type = t;
    return n;
}

Checked Checker::varAccess(VarSym* v, const ast::Loc& loc, bool fromOutside) {
    if (v->inferredPending && !typeInferredTempAhead(v)) {
        // IL: an instruction reads the current result before the body ever sets it (decision 0415).
        error(diag::E0008, loc, "the current result is read before any instruction sets it");
        return bad(loc);
    }
    if (v->inferredConflict) return bad(loc);
    v->used = true;
    if (v->global) v->global->used = true;
    // An inlined body's parameter that reads as its argument (decision 0403).
    for (const ArgSubstitute& s : argSubstitutes_)
        if (s.param == v) return substitutedArgument(s, loc);
    Checked c;
    c.ok = true;
    c.loc = loc;
    c.var = v;
    c.type = v->type;
    c.isPlace = true;
    if (v->constant) {
        c.readOnly = true;
        c.readOnlyWhy = v->byRef && v->section == ast::VarSection::Input
                            ? fmt::format("'{}' is an ARRAY[*] input, passed by reference and read-only", v->name)
                            : fmt::format("'{}' is a CONSTANT", v->name);
    }
    if (v->hasConstValue) {
        c.isConst = true;
        c.constInt = v->constInt;
        c.constReal = v->constReal;
    }
    if (v->hasConstValue && (isIntRep(v->type) || isRealRep(v->type)) && !addressOperand_) {
        // A CONSTANT with a constant initial value is its value everywhere,
        // except under ADR()/REF(), which take its storage's address (decision 0475).
        exec::Expr* k = isRealRep(v->type) ? static_cast<exec::Expr*>(pool().make<exec::ConstReal>(v->constReal))
                                           : pool().make<exec::ConstInt>(v->constInt);
        k->type = v->type;
        c.node = k;
        return c;
    }
    Checked::Direct d = v->storage == Storage::Self ? Checked::Direct::Self
                        : v->storage == Storage::Frame ? Checked::Direct::Frame
                                                       : Checked::Direct::Abs;
    // A body inlined into a caller (decision 0317): its frame is an area of the caller's.
    const uint32_t offset = v->offset + (d == Checked::Direct::Frame ? frameBias_ : 0);
    if (d == Checked::Direct::Abs && !v->abs && v->constText) {
        // A STRING CONSTANT of the list being declared, named in a later
        // constant's initial value (`cTopic := CONCAT(cMain, cDevice)`): its value (decision 0331).
        c.isConst = true;
        c.node = v->constText;
        return c;
    }
    if (d == Checked::Direct::Abs && !v->abs) {
        // A global of the list being declared, named in a later declaration's
        // type (`s : STRING(max)` with a plain VAR_GLOBAL max): it has no
        // storage yet, and only a constant can size a type (found by fuzzing).
        error(diag::E0401, loc, fmt::format("'{}' is not a constant: a type's size or bounds can only use constants", v->name));
        return bad(loc);
    }
    if (v->byRef && v->type->flexible) {
        exec::Expr* slot = directNode(pool(), d, offset, v->abs, types().elementary(TK::Void));
        c.flexDesc = slot;
        c.node = pool().make<exec::RefSlotPlace>(slot, site(loc), 1u);
    } else if (v->byRef) {
        exec::Expr* slot = directNode(pool(), d, offset, v->abs, types().elementary(TK::Void));
        // A VAR_IN_OUT CONSTANT string may be bound to a shorter string (or a
        // literal's temporary) and is never written: only its first byte
        // must lie in the project's memory (decision 0286).
        const bool anyLength = v->constant && isStringType(v->type->kind);
        exec::Expr* ref = pool().make<exec::RefSlotPlace>(slot, site(loc), anyLength ? 1u : static_cast<uint32_t>(v->type->size));
        c.node = loadFrom(ref, v->type);
    } else if (v->bit >= 0) {
        exec::Expr* byte = directNode(pool(), Checked::Direct::Abs, 0, v->abs, types().elementary(TK::Void));
        c.node = pool().make<exec::BitPlace<uint8_t>>(byte, v->bit);
    } else {
        c.direct = d;
        c.directOffset = offset;
        c.directAbs = v->abs;
        c.node = directNode(pool(), d, offset, v->abs, v->type);
    }
    c.node->type = v->type;
    return autoDeref(std::move(c));
}

// The address a VAR_IN_OUT is bound to (its slot's content, 0 while unbound),
// as a POINTER TO its type: `__ISVALIDREF(inOut)` (TwinCAT; decision 0326).
Checked Checker::inOutBinding(const VarSym* v, const ast::Loc& loc) {
    const Checked::Direct d = v->storage == Storage::Self ? Checked::Direct::Self
                              : v->storage == Storage::Frame ? Checked::Direct::Frame
                                                             : Checked::Direct::Abs;
    const uint32_t offset = v->offset + (d == Checked::Direct::Frame ? frameBias_ : 0);
    Checked c;
    c.ok = true;
    c.loc = loc;
    c.type = types().pointer(v->type);
    c.node = directNode(pool(), d, offset, v->abs, c.type);
    c.node->type = c.type;
    return c;
}

// `x` declared by several named global lists: the error names every list.
void Checker::ambiguousGlobal(const VarSym* v, const ast::Loc& loc, const std::string& written) {
    std::string lists;
    for (const VarSym* g : model_.globals)
        if (g->sharedName && stdlib::equalsIgnoreCase(g->name, v->name)) lists += (lists.empty() ? "" : ", ") + g->listName + "." + g->name;
    error(diag::E0108, loc, fmt::format("'{}' is declared in several global lists; write one of {}", written, lists));
}

Checked Checker::checkName(const ast::Expr& e) {
    if (e.pointerTo) {
        error(diag::E0107, e.loc, fmt::format("'POINTER TO {}' is a type, not a value: only __NEW and SIZEOF take it", e.name));
        return bad(e.loc);
    }
    std::string key = upper(e.name);
    if (qualifiedAccess_ && !qualifiedList_.empty()) {
        // `GVL.x`, `__SYSTEM.Constants.x`, and a library's namespace in front of its list (`Lib.GVL.x`).
        auto it = listGlobals_.find(qualifiedList_ + "." + key);
        if (const auto dot = qualifiedList_.rfind('.'); it == listGlobals_.end() && dot != std::string::npos)
            it = listGlobals_.find(qualifiedList_.substr(dot + 1) + "." + key);
        if (it != listGlobals_.end() && !(pou_ && pou_->ast && libraryFiles_.count(pou_->ast->loc.file))) return varAccess(it->second, e.loc, false);
    }
    // Inside a global list, its own variables come first and need no
    // qualifier, also with {attribute 'qualified_only'} (decision 0455).
    if (!declaringList_.empty() && !qualifiedAccess_) {
        auto it = listGlobals_.find(upper(declaringList_) + "." + key);
        if (it != listGlobals_.end()) return varAccess(it->second, e.loc, false);
    }
    VarSym* v = lookupVar(key);
    if (!v || v->section == ast::VarSection::Global) {
        // The block's own property: a member, so before the globals (decision 0440).
        bool found = false;
        Checked p = ownProperty(key, e.loc, found);
        if (found) return p;
    }
    if (v) {
        // A base class's `VAR PRIVATE` member, named in a derived class (decision 0278).
        if (v->access == ast::Access::Private && v->section == ast::VarSection::Var && v->owner &&
            v->owner != (pou_ && pou_->owner ? pou_->owner : pou_) && v->owner != pou_) {
            error(diag::E0109, e.loc, fmt::format("'{}' is PRIVATE in '{}'", v->name, v->owner->name));
            return bad(e.loc);
        }
        if (v->section == ast::VarSection::Global && v->sharedName) {
            ambiguousGlobal(v, e.loc, e.name);
            return bad(e.loc);
        }
        if (!v->qualifiedOnlyList.empty() && !qualifiedAccess_ && v->section == ast::VarSection::Global) {
            error(diag::E0108, e.loc, fmt::format("'{}' is in global list '{}' with {{attribute 'qualified_only'}}: write {}.{}", e.name,
                                     v->qualifiedOnlyList, v->qualifiedOnlyList, e.name));
            return bad(e.loc);
        }
        return varAccess(v, e.loc, false);
    }
    if (!key.empty() && key[0] == '%') {
        // A direct address used in code: a BOOL for bit addresses, else the address's size.
        char size = key.size() > 2 && std::isalpha(static_cast<unsigned char>(key[2])) ? key[2] : 'X';
        TK k = size == 'B' ? TK::Byte : size == 'W' ? TK::Word : size == 'D' ? TK::DWord : size == 'L' ? TK::LWord : TK::Bool;
        if (key[1] == 'S' && key.find('.') != std::string::npos) k = TK::Bool;  // %SW8.0: a bit of a system word
        const Type* t = types().elementary(k);
        int bit = -1;
        uint8_t* p = mapAddress(e.name, t, e.loc, bit);
        if (!p) return bad(e.loc);
        Checked c;
        c.ok = true;
        c.loc = e.loc;
        c.type = t;
        c.isPlace = true;
        if (bit >= 0) {
            exec::Expr* byte = directNode(pool(), Checked::Direct::Abs, 0, p, types().elementary(TK::Void));
            c.node = pool().make<exec::BitPlace<uint8_t>>(byte, bit);
        } else {
            c.direct = Checked::Direct::Abs;
            c.directAbs = p;
            c.node = directNode(pool(), Checked::Direct::Abs, 0, p, t);
        }
        c.node->type = t;
        return c;
    }
    if (key == "NULL") {
        // IEC 61131-3 3rd edition: the null reference, assignable to any REF_TO / POINTER.
        Checked c = constInt(0, types().elementary(TK::ULInt), e.loc);
        c.untypedInt = true;
        return c;
    }
    const Type* et = nullptr;
    bool ambiguousEnum = false;
    if (const Enumerator* en = lookupEnumValue(key, &et, ambiguousEnum)) {
        if (ambiguousEnum) {
            error(diag::E0108, e.loc, fmt::format("'{}' is a value of several enumerations; qualify it (Type#{} or Type.{})", e.name, e.name, e.name));
            return bad(e.loc);
        }
        return constInt(en->value, et, e.loc);
    }
    if (const ProgramInstance* found = findProgram(key)) {
            const ProgramInstance& prog = *found;
            Checked c;
            c.ok = true;
            c.loc = e.loc;
            c.type = prog.pou->instanceType;
            c.isPlace = true;
            c.direct = Checked::Direct::Abs;
            c.directAbs = prog.memory;
            c.node = directNode(pool(), Checked::Direct::Abs, 0, prog.memory, c.type);
            c.node->type = c.type;
            return c;
        }
    if (pous_.count(key)) {
        error(diag::E0107, e.loc, fmt::format("'{}' is a POU, not a variable", e.name));
        return bad(e.loc);
    }
    if (Checked later = laterConstant(key, e.loc); later.ok) return later;
    // A variable declared with an unknown type: that error is the root cause.
    if (isUnresolved(key)) return bad(e.loc);
    suggest(error(diag::E0101, e.loc, fmt::format("undeclared identifier '{}'", e.name)), e.name, &Checker::visibleVariableNames);
    return bad(e.loc);
}

// CODESYS resolves declarations in any order: a VAR CONSTANT of the POU being
// laid out, declared further down (`arr : ARRAY[0..N] OF INT; ... N : INT := 3;`),
// is its folded initial value here.
// A constant of a global list, used before the lists are declared: in a TYPE
// (`ARRAY[1..GVL.cMax] OF ...`, `UINT(0..cMax)`), which is resolved first.
// The project's lists come before strun's library lists of the same name.
Checked Checker::earlyGlobalConstant(const std::string& key, const ast::Loc& loc) {
    if (globalsDeclared_ || pendingConstants_.count(key)) return bad(loc);
    for (int pass = 0; pass < 2; ++pass)
        for (const ast::GlobalList* list : globalLists_) {
            if ((libraryFiles_.count(list->loc.file) != 0) != (pass == 1)) continue;
            if (!qualifiedList_.empty() && upper(list->nameSpace) != qualifiedList_ &&
                !qualifiedList_.ends_with("." + upper(list->nameSpace)))
                continue;
            for (const auto& block : list->blocks) {
                if (!block.constant || block.section != ast::VarSection::Global) continue;
                for (const auto& decl : block.vars)
                    for (const auto& name : decl.names) {
                        if (upper(name) != key || !decl.type || !decl.init) continue;
                        const Type* t = resolveTypeSpec(decl.type.get(), name);
                        if (t && t->kind == TK::Struct) return earlyStructureConstant(decl, t, key, loc);
                        if (decl.init->kind != ast::InitKind::Expr || !decl.init->expr) continue;
                        if (!t || !(isIntRep(t) || isRealRep(t))) return bad(loc);
                        pendingConstants_.insert(key);
                        const bool wasQualified = qualifiedAccess_;
                        const std::string savedList = qualifiedList_;
                        qualifiedAccess_ = false;  // its initial value names what it names
                        qualifiedList_.clear();
                        Checked v = checkExpr(*decl.init->expr);
                        qualifiedAccess_ = wasQualified;
                        qualifiedList_ = savedList;
                        pendingConstants_.erase(key);
                        if (!v.ok) return bad(loc);
                        v = coerce(v, t, decl.init->expr->loc, "initial value");
                        if (!v.ok || !v.isConst) return bad(loc);
                        v.loc = loc;
                        return v;
                    }
            }
        }
    return bad(loc);
}

// A structured constant of a global list named in a TYPE's member default
// (LCLS ST_DbStateParams: `stBeamParams : ST_BeamParams := PMPS_GVL.cst0RateBeam;`):
// its initial image, as writeInitial gives it, for writeInitial to copy
// (decision 0462). Its own errors are reported where the list is declared.
Checked Checker::earlyStructureConstant(const ast::VarDecl& decl, const Type* t, const std::string& key, const ast::Loc& loc) {
    pendingConstants_.insert(key);
    const bool wasQualified = qualifiedAccess_;
    const std::string savedList = qualifiedList_;
    auto* savedRuntime = runtimeInits_;
    qualifiedAccess_ = false;
    qualifiedList_.clear();
    runtimeInits_ = nullptr;  // a constant has no run-time part
    const size_t messagesBefore = log_.messages().size();
    const size_t errorsBefore = log_.errorCount();
    std::vector<uint8_t> image(t->size, 0);
    writeDefault(image.data(), t);
    writeInitial(image.data(), t, decl.init.get(), decl.loc);
    const bool failed = log_.errorCount() != errorsBefore;
    log_.dropFrom(messagesBefore);
    qualifiedAccess_ = wasQualified;
    qualifiedList_ = savedList;
    runtimeInits_ = savedRuntime;
    pendingConstants_.erase(key);
    if (failed) return bad(loc);
    Checked c;
    c.ok = true;
    c.loc = loc;
    c.type = t;
    c.isConst = true;
    c.node = pool().make<exec::ConstBytes>(std::move(image));
    c.node->type = t;
    return c;
}

Checked Checker::laterConstant(const std::string& key, const ast::Loc& loc) {
    if (Checked global = earlyGlobalConstant(key, loc); global.ok) return global;
    if (!pou_ || !pou_->layingOut || !pou_->ast || pendingConstants_.count(key)) return bad(loc);
    for (const auto& block : pou_->ast->vars) {
        if (!block.constant) continue;
        for (const auto& decl : block.vars)
            for (const auto& name : decl.names) {
                if (upper(name) != key || !decl.type || !decl.init || decl.init->kind != ast::InitKind::Expr || !decl.init->expr) continue;
                const Type* t = resolveTypeSpec(decl.type.get(), pou_->name);
                if (!t || !(isIntRep(t) || isRealRep(t))) return bad(loc);
                pendingConstants_.insert(key);  // N : INT := N + 1 must not recurse
                Checked v = checkExpr(*decl.init->expr);
                pendingConstants_.erase(key);
                if (!v.ok) return bad(loc);
                v = coerce(v, t, decl.init->expr->loc, "initial value");
                if (!v.ok || !v.isConst) return bad(loc);
                v.loc = loc;
                constantsUsedEarly_.insert({pou_, key});
                return v;
            }
    }
    return bad(loc);
}

Checked Checker::memberOf(Checked base, const std::string& member, const ast::Loc& loc) {
    if (!base.ok) return base;
    const Type* t = base.type;
    // Auto-dereference of REFERENCE TO.
    if (t->kind == TK::Reference) {
        exec::Expr* place = pool().make<exec::DerefPlace>(base.node, site(loc), t->target->size);
        Checked d;
        d.ok = true;
        d.loc = loc;
        d.type = t->target;
        d.isPlace = true;
        d.node = loadFrom(place, t->target);
        base = d;
        t = t->target;
    }
    std::string key = upper(member);
    if (t->kind == TK::FunctionBlock) key = canonicalParameter(t->pou, key);
    if (key.size() > 2 && key[0] == '%' && key[1] == 'X') key = key.substr(2);  // x.%X3 is x.3
    if (key.size() > 2 && key[0] == '%' && (key[1] == 'B' || key[1] == 'W' || key[1] == 'D' || key[1] == 'L'))
        return partialAccess(base, key, member, loc);
    if ((isInteger(t->kind) || isBitString(t->kind)) && !key.empty() && !std::isdigit(static_cast<unsigned char>(key[0]))) {
        // CODESYS: w.BIT_FIVE with an integer CONSTANT as the bit number.
        VarSym* k = lookupVar(key);
        if (k && k->hasConstValue && isInteger(k->type->kind) && k->constInt >= 0 && k->constInt < 64) key = std::to_string(k->constInt);
    }
    if (!key.empty() && std::isdigit(static_cast<unsigned char>(key[0]))) {
        // Bit access x.3
        TK k = t->kind;
        if (!(isInteger(k) || isBitString(k))) {
            error(diag::E0207, loc, fmt::format("bit access needs an integer or bit-string value, not {}", typeName(t)));
            return bad(loc);
        }
        int bit = 0;
        for (char ch : key) {
            if (!std::isdigit(static_cast<unsigned char>(ch)) || bit > 64) { bit = 99; break; }
            bit = bit * 10 + (ch - '0');
        }
        if (bit >= bitWidth(k)) {
            error(diag::E0103, loc, fmt::format("bit {} does not exist in {}", member, typeName(t)));
            return bad(loc);
        }
        if (!base.isPlace) {
            error(diag::E0207, loc, "bit access needs a variable");
            return bad(loc);
        }
        Checked c = base;
        c.type = types().elementary(TK::Bool);
        c.direct = Checked::Direct::None;
        c.isConst = false;
        c.var = nullptr;
        c.loc = loc;
        Rep rep = repOf(t);
        exec::Expr* place = base.node;
        switch (rep) {
            case Rep::I8: case Rep::U8: c.node = pool().make<exec::BitPlace<uint8_t>>(place, bit); break;
            case Rep::I16: case Rep::U16: c.node = pool().make<exec::BitPlace<uint16_t>>(place, bit); break;
            case Rep::I32: case Rep::U32: c.node = pool().make<exec::BitPlace<uint32_t>>(place, bit); break;
            default: c.node = pool().make<exec::BitPlace<uint64_t>>(place, bit); break;
        }
        c.node->type = c.type;
        return c;
    }
    if (t->kind == TK::Interface) {
        bool found = false;
        Checked p = propertyAccess(base, key, loc, found);
        if (found) return p;
        error(diag::E0103, loc, fmt::format("interface '{}' has no property '{}'", typeName(t), member));
        return bad(loc);
    }
    if (t->kind != TK::Struct && t->kind != TK::FunctionBlock) {
        error(diag::E0103, loc, fmt::format("'{}' is not a member: {} has no members", member, typeName(t)));
        return bad(loc);
    }
    const Field* f = t->findField(key);
    if (!f && t->kind == TK::FunctionBlock) {
        bool found = false;
        Checked p = propertyAccess(base, key, loc, found);
        if (found) return p;
    }
    if (!f) {
        // A member declared with an unknown type: that error is the root cause.
        // Also one a base structure declared so (STRUCT EXTENDS, decision 0371).
        for (const Type* s = t; s; s = s->kind == TK::Struct ? s->parent : nullptr)
            if (unresolvedMembers_.count({s, key})) return bad(loc);
        if (t->kind == TK::FunctionBlock)
            for (const PouInfo* p = t->pou; p; p = p->parent)
                if (unresolvedVars_.count({p, key})) return bad(loc);
        std::vector<std::string> members;
        for (const Field& field : t->fields) members.push_back(field.name);
        // A mistyped method call (`fbMotor.Resett()`) reaches here too: its methods are candidates.
        if (t->kind == TK::FunctionBlock && t->pou)
            for (const PouInfo* p = t->pou; p; p = p->parent)
                for (const auto& [mkey, m] : p->methods)
                    if (m->name.rfind("__", 0) != 0) members.push_back(m->name);
        suggest(error(diag::E0103, loc, fmt::format("'{}' has no member '{}'", typeName(t), member)), member, members);
        return bad(loc);
    }
    Checked c;
    c.ok = true;
    c.loc = loc;
    c.isPlace = base.isPlace;
    c.readOnly = base.readOnly;
    c.readOnlyWhy = base.readOnlyWhy;
    c.hasCall = base.hasCall;
    const Type* ft = f->type;
    bool byRef = false;
    if (t->kind == TK::FunctionBlock && t->pou) {
        VarSym* mv = nullptr;
        for (PouInfo* p = t->pou; p && !mv; p = p->parent) {
            auto it = p->vars.find(key);
            if (it != p->vars.end()) mv = it->second;
        }
        // Ed.3 `VAR PUBLIC` / `VAR INTERNAL` are visible and writable outside, `VAR PRIVATE`
        // only in the class that declares them, `VAR PROTECTED` also in derived ones (decision 0278).
        const ast::Access access = mv && mv->section == ast::VarSection::Var ? mv->access : ast::Access::Default;
        if (access == ast::Access::Private || access == ast::Access::Protected) {
            const PouInfo* here = pou_ && pou_->owner ? pou_->owner : pou_;
            const bool visible = access == ast::Access::Private ? here == mv->owner : insideOwnInstance(mv->owner);
            if (!visible) {
                error(diag::E0109, loc, fmt::format("'{}' is {} in '{}'", mv->name, access == ast::Access::Private ? "PRIVATE" : "PROTECTED",
                                       mv->owner ? mv->owner->name : t->name));
                return bad(loc);
            }
        }
        if (mv && access == ast::Access::Default &&
            (mv->section == ast::VarSection::Var || mv->section == ast::VarSection::Temp ||
             mv->section == ast::VarSection::Stat || mv->section == ast::VarSection::Inst) &&
            t->pou->kind == ast::PouKind::FunctionBlock && !insideOwnInstance(t->pou)) {
            // TwinCAT and CODESYS let an instance's internal variables be read
            // from outside (`fb.count`, `ADR(fb.buffer)`); IEC 61131-3 does not
            // (decision 0206, revising 0072): an error with --strict only.
            if (options_.strict && !libraryFiles_.count(loc.file)) {
                error(diag::E0109, loc, fmt::format("'{}' is an internal variable of '{}'; only its inputs and outputs are visible outside", mv->name, t->name));
                return bad(loc);
            }
            c.readOnly = true;
            c.readOnlyWhy = fmt::format("'{}' is an internal variable of '{}'; it can be read from outside the instance, not written", mv->name, t->name);
        }
        if (mv) {
            mv->used = true;
            byRef = mv->byRef;
            if (byRef) ft = mv->type;
            // An input may be written from outside before the call (`fb.IN := TRUE;`):
            // CODESYS and TwinCAT accept it (decision 0072).
            if (mv->section == ast::VarSection::Output && t->pou->kind == ast::PouKind::FunctionBlock && !insideOwnInstance(t->pou)) {
                c.readOnly = true;
                c.readOnlyWhy = fmt::format("'{}' is an output of '{}'; outputs are read-only outside the instance", mv->name, t->name);
            }
            if (mv->constant) {
                c.readOnly = true;
                c.readOnlyWhy = fmt::format("'{}' is a CONSTANT", mv->name);
            }
        }
    }
    c.type = ft;
    if (byRef) {
        exec::Expr* slot = base.direct != Checked::Direct::None
                               ? directNode(pool(), base.direct, base.directOffset + f->offset, base.directAbs, types().voidType())
                               : pool().make<exec::OffsetPlace>(base.node, f->offset);
        if (ft->flexible) {
            // `THIS^.arr[i]` of the block's own VAR_IN_OUT ARRAY[*]: its slot holds
            // the descriptor, as for the bare name (varAccess; decision 0459).
            c.flexDesc = slot;
            c.node = pool().make<exec::RefSlotPlace>(slot, site(loc), 1u);
        } else {
            c.node = loadFrom(pool().make<exec::RefSlotPlace>(slot, site(loc), static_cast<uint32_t>(ft->size)), ft);
        }
    } else if (base.direct != Checked::Direct::None) {
        c.direct = base.direct;
        c.directOffset = base.directOffset + f->offset;
        c.directAbs = base.directAbs;
        c.node = directNode(pool(), c.direct, c.directOffset, c.directAbs, ft);
    } else {
        c.node = loadFrom(pool().make<exec::OffsetPlace>(base.node, f->offset), ft);
    }
    c.node->type = ft;
    return autoDeref(std::move(c));
}

// x.%B1, x.%W0, x.%D1, x.%L0: byte, word, double word or long word N of an
// integer or bit string (IEC 61131-3 3rd ed. partial access; N counts from
// the least significant end, as the value is stored little-endian).
Checked Checker::partialAccess(Checked base, const std::string& key, const std::string& member, const ast::Loc& loc) {
    const Type* t = base.type;
    TK k = t->kind;
    TK partKind = key[1] == 'B' ? TK::Byte : key[1] == 'W' ? TK::Word : key[1] == 'D' ? TK::DWord : TK::LWord;
    const Type* part = types().elementary(partKind);
    if (!(isInteger(k) || isBitString(k))) {
        error(diag::E0207, loc, fmt::format("partial access {} needs an integer or bit-string value, not {}", member, typeName(t)));
        return bad(loc);
    }
    uint64_t index = 0;
    for (size_t i = 2; i < key.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(key[i])) || index > 64) { index = 99; break; }
        index = index * 10 + static_cast<uint64_t>(key[i] - '0');
    }
    if ((index + 1) * part->size > t->size) {
        error(diag::E0103, loc, fmt::format("{} does not exist in {}", member, typeName(t)));
        return bad(loc);
    }
    if (!base.isPlace) {
        error(diag::E0207, loc, "partial access needs a variable");
        return bad(loc);
    }
    Checked c = base;
    c.type = part;
    c.isConst = false;
    c.var = nullptr;
    c.loc = loc;
    const auto offset = static_cast<uint32_t>(index * part->size);
    if (base.direct != Checked::Direct::None) {
        c.directOffset = base.directOffset + offset;
        c.node = directNode(pool(), c.direct, c.directOffset, c.directAbs, part);
    } else {
        c.direct = Checked::Direct::None;
        c.node = loadFrom(pool().make<exec::OffsetPlace>(base.node, offset), part);
    }
    c.node->type = part;
    return c;
}

Checked Checker::checkMember(const ast::Expr& e) {
    const ast::Expr& baseExpr = *e.kids[0];
    if (Checked eno; checkFbEnoRead(e, eno)) return eno;  // inst.ENO (decision 0358)
    if (isNamespace(baseExpr) && !lookupVar(upper(chainRoot(baseExpr).name))) {
        ast::Expr plain;
        plain.kind = ast::ExprKind::Name;
        plain.loc = e.nameLoc.line ? e.nameLoc : e.loc;
        plain.name = e.name;
        qualifiedAccess_ = true;
        qualifiedList_ = writtenPath(baseExpr);
        Checked c = checkName(plain);
        qualifiedAccess_ = false;
        qualifiedList_.clear();
        return c;
    }
    // Enum.Value, also with its library or namespace in front (SysFile.ACCESS_MODE.AM_READ).
    const bool qualifiedType = baseExpr.kind == ast::ExprKind::Member && isNamespace(*baseExpr.kids[0]);
    if (baseExpr.kind == ast::ExprKind::Name || qualifiedType) {
        std::string bkey = upper(baseExpr.name);
        if (qualifiedType || !lookupVar(bkey)) {
            if (!qualifiedType) {
                bkey = scopedKey(bkey);
            } else if (std::string scoped = scopedKey(writtenPath(baseExpr)); typeDecls_.count(scoped)) {
                bkey = scoped;  // FILE.MODE.MREAD beside a project's own MODE (decision 0324)
            }
            // Enum.Value
            if (typeDecls_.count(bkey)) {
                const Type* t = resolveTypeDecl(bkey, baseExpr.loc);
                if (t && t->kind == TK::Enum) {
                    if (const Enumerator* en = t->findEnumerator(upper(e.name))) return constInt(en->value, t, e.loc);
                    enumValueError(e.nameLoc.line ? e.nameLoc : e.loc, e.name, t);
                    return bad(e.loc);
                }
            }
        }
    }
    // Namespace.Enum.Value (`__SYSTEM.TYPE_CLASS.TYPE_INT`, decision 0302).
    if (baseExpr.kind == ast::ExprKind::Member && !baseExpr.kids.empty() && isNamespace(*baseExpr.kids[0])) {
        std::string bkey = upper(baseExpr.name);
        std::string qualified = bkey;
        for (const ast::Expr* p = baseExpr.kids[0].get(); p; p = p->kids.empty() ? nullptr : p->kids[0].get()) {
            qualified = upper(p->name) + "." + qualified;
            if (p->kind == ast::ExprKind::Name) break;
        }
        qualified = scopedKey(qualified);
        const std::string key = typeDecls_.count(qualified) ? qualified : bkey;
        if (typeDecls_.count(key)) {
            const Type* t = resolveTypeDecl(key, baseExpr.loc);
            if (t && t->kind == TK::Enum) {
                if (const Enumerator* en = t->findEnumerator(upper(e.name))) return constInt(en->value, t, e.loc);
                enumValueError(e.nameLoc.line ? e.nameLoc : e.loc, e.name, t);
                return bad(e.loc);
            }
        }
    }
    Checked base = checkMemberBase(baseExpr);
    return memberOf(base, e.name, e.nameLoc.line ? e.nameLoc : e.loc);
}

// What stands before `.member`: `THIS.x` (IEC 61131-3 Ed.3 and SIMATIC AX,
// where THIS is a reference) is CODESYS's `THIS^.x` (decision 0316), and
// `SUPER.Method()` is `SUPER^.Method()` (decision 0366).
Checked Checker::checkMemberBase(const ast::Expr& base) {
    if (base.kind == ast::ExprKind::This || base.kind == ast::ExprKind::Super) return checkThis(base, true);
    return checkExpr(base);
}

// The instance `base.M()` calls M of. `F().M()`, `fb.Now().ToLocal()`: the
// REFERENCE TO a block that a call returns is the block (fluent interfaces;
// decision 0442), as a REFERENCE variable is (autoDeref).
Checked Checker::checkMethodBase(const ast::Expr& base) {
    Checked c = checkMemberBase(base);
    if (c.ok && c.type->kind == TK::Reference && (c.type->target->kind == TK::FunctionBlock || c.type->target->kind == TK::Interface))
        return derefReference(c);
    return c;
}

Checked Checker::checkIndex(const ast::Expr& e) {
    Checked base = checkExpr(*e.kids[0]);
    if (!base.ok) return base;
    const Type* t = base.type;
    if (isStringType(t->kind) || t->kind == TK::Pointer) return checkStringOrPointerIndex(e, base);
    if (t->kind != TK::Array) {
        error(diag::E0204, e.loc, fmt::format("subscript on a value of type {}, which is not an array", typeName(t)));
        return bad(e.loc);
    }
    size_t nsub = e.kids.size() - 1;
    if (t->flexible) {
        if (!base.flexDesc) {
            error(diag::E0407, e.loc, "ARRAY[*] is only usable as a VAR_IN_OUT or VAR_INPUT parameter");
            return bad(e.loc);
        }
        if (e.kids.size() - 1 != t->dims.size()) {
            error(diag::E0204, e.loc, fmt::format("{} subscript(s) given, the array has {} dimension(s)", e.kids.size() - 1, t->dims.size()));
            return bad(e.loc);
        }
        auto* n = pool().make<exec::FlexIndexPlace>();
        n->desc = base.flexDesc;
        n->elemSize = t->elem->size;
        n->site = site(e.loc);
        // ref^[i] of a REF_TO ARRAY[*]: the same, after its NULL test (decision 0402).
        auto* viaRef = exec::nodeCast<exec::FlexRefDesc>(base.flexDesc);
        exec::FlexRefIndexPlace* r = nullptr;
        if (viaRef) {
            r = pool().make<exec::FlexRefIndexPlace>();
            r->slot = viaRef->slot;
            r->elemSize = n->elemSize;
            r->site = n->site;
        }
        Checked c;
        c.ok = true;
        c.loc = e.loc;
        c.type = t->elem;
        c.isPlace = true;
        c.readOnly = base.readOnly;  // VAR_IN_OUT CONSTANT, an ARRAY[*] input (decision 0395)
        c.readOnlyWhy = base.readOnlyWhy;
        c.hasCall = base.hasCall;
        for (size_t k = 1; k < e.kids.size(); ++k) {
            Checked ix = checkExpr(*e.kids[k]);
            if (!ix.ok) return bad(e.loc);
            if (!(isInteger(ix.type->kind) || isBitString(ix.type->kind) || ix.untypedInt)) {
                error(diag::E0204, e.kids[k]->loc, fmt::format("an array subscript must be an integer, not {}", typeName(ix.type)));
                return bad(e.loc);
            }
            c.hasCall = c.hasCall || ix.hasCall;
            n->index.push_back(settle(ix).node);
        }
        if (r) r->index = n->index;
        c.node = loadFrom(r ? static_cast<exec::Expr*>(r) : n, c.type);
        c.node->type = c.type;
        return c;
    }
    if (nsub != t->dims.size()) {
        error(diag::E0204, e.loc, fmt::format("{} subscript(s) given, the array has {} dimension(s)", nsub, t->dims.size()));
        return bad(e.loc);
    }
    std::vector<exec::IndexPlace::Dim> dims;
    uint64_t stride = t->elem->size;
    std::vector<uint64_t> strides(nsub);
    for (size_t k = nsub; k-- > 0;) {
        strides[k] = stride;
        stride *= static_cast<uint64_t>(t->dims[k].count());
    }
    bool allConst = base.direct != Checked::Direct::None;
    uint64_t constOffset = 0;
    bool hasCall = base.hasCall;
    for (size_t k = 0; k < nsub; ++k) {
        Checked ix = checkExpr(*e.kids[k + 1]);
        if (!ix.ok) return bad(e.loc);
        hasCall = hasCall || ix.hasCall;
        if (!(isInteger(ix.type->kind) || isBitString(ix.type->kind) || ix.type->kind == TK::Enum || ix.untypedInt)) {
            error(diag::E0204, e.kids[k + 1]->loc, fmt::format("an array subscript must be an integer, not {}", typeName(ix.type)));
            return bad(e.loc);
        }
        ix = settle(ix);
        if (ix.isConst) {
            if (ix.constInt < t->dims[k].lo || ix.constInt > t->dims[k].hi) {
                error(diag::E0204, e.kids[k + 1]->loc, fmt::format("subscript {} is outside the array bounds {}..{}", ix.constInt, t->dims[k].lo, t->dims[k].hi));
                return bad(e.loc);
            }
            constOffset += static_cast<uint64_t>(ix.constInt - t->dims[k].lo) * strides[k];
        } else {
            allConst = false;
        }
        dims.push_back({ix.node, t->dims[k].lo, t->dims[k].count(), strides[k]});
    }
    // PT^[i] through a pointer to an array: the pointer only has to lead into
    // project memory, and the element itself is checked (MemoryCheckedPlace).
    auto* deref = exec::nodeCast<exec::DerefPlace>(base.node);
    if (deref) deref->targetSize = 1;
    auto throughPointer = [&](exec::Expr* place) -> exec::Expr* {
        if (!deref) return place;
        return pool().make<exec::MemoryCheckedPlace>(place, deref, static_cast<uint32_t>(t->elem->size));
    };
    Checked c;
    c.ok = true;
    c.loc = e.loc;
    c.type = t->elem;
    c.isPlace = base.isPlace;
    c.readOnly = base.readOnly;
    c.readOnlyWhy = base.readOnlyWhy;
    c.hasCall = hasCall;
    if (allConst) {
        c.direct = base.direct;
        c.directOffset = base.directOffset + static_cast<uint32_t>(constOffset);
        c.directAbs = base.directAbs;
        c.node = directNode(pool(), c.direct, c.directOffset, c.directAbs, c.type);
    } else if (dims.size() == 1 && base.direct != Checked::Direct::None && base.direct != Checked::Direct::Pending) {
        Rep rep = isAggregate(c.type) ? Rep::Void : repOf(c.type);
        exec::Expr* n = nullptr;
        switch (base.direct) {
            case Checked::Direct::Self: n = makeByRep<Index1Self>(pool(), rep); break;
            case Checked::Direct::Frame: n = makeByRep<Index1Frame>(pool(), rep); break;
            default: n = makeByRep<Index1Abs>(pool(), rep); break;
        }
        auto* f = exec::nodeCast<exec::Index1Fields>(n);
        f->off = base.directOffset;
        f->abs = base.directAbs ? base.directAbs + base.directOffset : nullptr;
        f->index = dims[0].index;
        f->lo = dims[0].lo;
        f->count = dims[0].count;
        f->stride = dims[0].stride;
        f->site = site(e.loc);
        const exec::BaseKind kind = base.direct == Checked::Direct::Self ? exec::BaseKind::Self
                                    : base.direct == Checked::Direct::Frame ? exec::BaseKind::Frame : exec::BaseKind::Abs;
        if (exec::Expr* fused = fuseIndex1(pool(), rep, kind, *f)) n = fused;
        c.node = n;
    } else if (dims.size() == 1) {
        auto* n = pool().make<exec::Index1Place>();
        n->base = base.node;
        n->index = dims[0].index;
        n->lo = dims[0].lo;
        n->count = dims[0].count;
        n->stride = dims[0].stride;
        n->site = site(e.loc);
        c.node = loadFrom(throughPointer(n), c.type);
    } else {
        auto* n = pool().make<exec::IndexPlace>();
        n->base = base.node;
        n->dims = std::move(dims);
        n->site = site(e.loc);
        c.node = loadFrom(throughPointer(n), c.type);
    }
    c.node->type = c.type;
    return c;
}

// ---------------------------------------------------------------- dispatch

Checked Checker::checkExpr(const ast::Expr& e) {
    if (!observer_) return checkExprOfKind(e);
    Checked c = checkExprOfKind(e);
    observer_->checked(e, c, pou_);
    return c;
}

Checked Checker::checkExprOfKind(const ast::Expr& e) {
    // ADR()/REF() of a CONSTANT takes its storage (decision 0475) only for the
    // named variable itself: subscripts, arguments and operands inside the
    // operand fold their constants as usual.
    if (addressOperand_ && e.kind != ast::ExprKind::Name && e.kind != ast::ExprKind::Member) {
        addressOperand_ = false;
        Checked c = checkExprOfKind(e);
        addressOperand_ = true;
        return c;
    }
    switch (e.kind) {
        case ast::ExprKind::Literal: return checkLiteral(e);
        case ast::ExprKind::Name: return checkName(e);
        case ast::ExprKind::Member: return checkMember(e);
        case ast::ExprKind::Index: return checkIndex(e);
        case ast::ExprKind::Unary: return checkUnary(e);
        case ast::ExprKind::Binary: return checkBinary(e);
        // A call's REFERENCE TO result is the variable it refers to, as a
        // REFERENCE variable is (decision 0477): `st := F_GetRef();`.
        case ast::ExprKind::Call: return autoDeref(checkCall(e, false));
        case ast::ExprKind::Deref: {
            if (e.kids[0]->kind == ast::ExprKind::This || e.kids[0]->kind == ast::ExprKind::Super) return checkThis(*e.kids[0], true);
            Checked p = checkExpr(*e.kids[0]);
            if (!p.ok) return p;
            if (p.type->kind != TK::Pointer && p.type->kind != TK::Reference) {
                error(diag::E0201, e.loc, fmt::format("'^' needs a POINTER, not {}", typeName(p.type)));
                return bad(e.loc);
            }
            if (isFlexibleRef(p.type)) return derefFlexibleRef(p, e.loc);
            Checked c;
            c.ok = true;
            c.loc = e.loc;
            c.type = p.type->target;
            c.isPlace = true;
            c.hasCall = p.hasCall;
            c.node = loadFrom(pool().make<exec::DerefPlace>(p.node, site(e.loc), c.type->size), c.type);
            c.node->type = c.type;
            return c;
        }
        case ast::ExprKind::This:
        case ast::ExprKind::Super:
            return checkThis(e, false);
        case ast::ExprKind::Assign: return checkAssignmentValue(e);
    }
    return bad(e.loc);
}

Checked Checker::checkCondition(const ast::Expr& e, const char* what) {
    Checked c = checkExpr(e);
    if (!c.ok) return c;
    if (c.type->kind != TK::Bool) {
        error(diag::E0203, e.loc, fmt::format("{} must be BOOL, not {}", what, typeName(c.type)));
        return bad(e.loc);
    }
    return c;
}

// ---------------------------------------------------------------- conversions

namespace {
struct IntInfo { bool isSigned; int bits; };
IntInfo intInfo(TK k) {
    TK v = integerView(k);
    return {isSignedInt(v), bitWidth(v)};
}
TK intKindOf(bool isSigned, int bits) {
    switch (bits) {
        case 8: return isSigned ? TK::SInt : TK::USInt;
        case 16: return isSigned ? TK::Int : TK::UInt;
        case 32: return isSigned ? TK::DInt : TK::UDInt;
        default: return isSigned ? TK::LInt : TK::ULInt;
    }
}
TK bitKindOf(int bits) {
    switch (bits) {
        case 8: return TK::Byte;
        case 16: return TK::Word;
        case 32: return TK::DWord;
        default: return TK::LWord;
    }
}
// IEC 61131-3 implicit conversions (decision 0070): silent in both modes.
bool iecImplicit(const Type* from, const Type* to) {
    TK f = from->kind, t = to->kind;
    if (f == t) return true;
    if (isInteger(f) && isInteger(t)) {
        IntInfo a = intInfo(f), b = intInfo(t);
        if (a.isSigned == b.isSigned) return b.bits >= a.bits;
        return !a.isSigned && b.isSigned && b.bits > a.bits;  // USINT -> INT, not USINT -> SINT
    }
    if (isBitString(f) && isBitString(t)) return intInfo(t).bits >= intInfo(f).bits;
    if (f == TK::Bool && isBitString(t)) return true;
    if (isInteger(f) && isReal(t)) return true;
    if (f == TK::Real && t == TK::LReal) return true;
    if (f == TK::Time && t == TK::LTime) return true;
    return false;
}
// Integer <-> bit string without narrowing (`w : WORD := i`): CODESYS converts
// these silently, and so does strun in operands brought to a common type.
bool bitStringMix(const Type* from, const Type* to) {
    TK f = from->kind, t = to->kind;
    if (!((isInteger(f) || isBitString(f)) && (isInteger(t) || isBitString(t)))) return false;
    return intInfo(t).bits >= intInfo(f).bits;
}
// What CODESYS also converts implicitly (contract, "Implicit conversions"): any
// integer, bit string, REAL or LREAL to any other, in either direction.
bool codesysImplicit(const Type* from, const Type* to) {
    auto numeric = [](TK k) { return isInteger(k) || isBitString(k) || isReal(k); };
    return numeric(from->kind) && numeric(to->kind);
}
}  // namespace

Checked Checker::convert(Checked e, const Type* target, const ast::Loc& loc, bool truncate) {
    if (!e.ok) return e;
    e = settle(e);
    const Type* from = e.type;
    if (sameType(from, target) && !isStringType(target->kind)) {
        Checked r = e;
        r.type = target;
        return r;
    }
    TK f = from->kind == TK::Enum ? from->base->kind : from->kind;
    TK t = target->kind == TK::Enum ? target->base->kind : target->kind;
    Checked r;
    r.ok = true;
    r.loc = loc;
    r.type = target;
    r.hasCall = e.hasCall;
    exec::Expr* n = nullptr;
    auto intConv = [&](exec::Expr* src) { return makeIntByRep<exec::ConvIntInt>(pool(), repOf(target), src); };
    // Time/date scaling between encodings (TIME ms, LTIME ns, DATE/DT s, TOD ms, L-forms ns).
    bool fTimeDate = isTimeLike(f) || isDateLike(f);
    bool tTimeDate = isTimeLike(t) || isDateLike(t);
    if (target->kind == TK::Bool) {
        n = pool().make<exec::ConvToBool>(e.node, isReal(f));
    } else if (isReal(t)) {
        Rep rt = repOf(target);
        if (isReal(f)) n = makeRealByRep<exec::ConvRealReal>(pool(), rt, e.node);
        else {
            bool u64 = repOf(from) == Rep::U64;
            if (rt == Rep::F32) n = u64 ? static_cast<exec::Expr*>(pool().make<exec::ConvIntReal<float, uint64_t>>(e.node)) : pool().make<exec::ConvIntReal<float, int64_t>>(e.node);
            else n = u64 ? static_cast<exec::Expr*>(pool().make<exec::ConvIntReal<double, uint64_t>>(e.node)) : pool().make<exec::ConvIntReal<double, int64_t>>(e.node);
        }
    } else if (isReal(f)) {
        if (!(isIntRep(target))) {
            error(diag::E0201, loc, fmt::format("no conversion from {} to {}", typeName(from), typeName(target)));
            return bad(loc);
        }
        IntInfo ii = intInfo(t);
        n = fuseRealToInt(pool(), e.node, ii.bits, ii.isSigned, truncate);
        if (!n) n = pool().make<exec::ConvRealInt>(e.node, ii.bits, ii.isSigned, truncate);
    } else if (fTimeDate && tTimeDate) {
        if ((f == TK::Dt || f == TK::LDt) && (t == TK::Tod || t == TK::LTod)) {
            // The time of day in the source's unit, then rescaled (LDT ns -> TOD ms divides).
            int64_t perDay = f == TK::Dt ? 86400 : 86400000000000LL;
            exec::Expr* ofDay = pool().make<exec::WrapModulo>(e.node, perDay);
            int64_t sf = nanosPerUnit(f), st = nanosPerUnit(t);
            n = intConv(sf >= st ? static_cast<exec::Expr*>(pool().make<exec::ScaleUnits>(ofDay, sf / st, 1)) : pool().make<exec::ScaleUnits>(ofDay, 1, st / sf));
        } else if ((f == TK::Dt || f == TK::LDt) && (t == TK::Date || t == TK::LDate)) {
            int64_t perDay = f == TK::Dt ? 86400 : 86400000000000LL;
            exec::Expr* day = pool().make<exec::ScaleUnits>(e.node, perDay, perDay);
            int64_t sf = nanosPerUnit(f), st = nanosPerUnit(t);
            n = intConv(sf >= st ? static_cast<exec::Expr*>(pool().make<exec::ScaleUnits>(day, sf / st, 1)) : pool().make<exec::ScaleUnits>(day, 1, st / sf));
        } else {
            int64_t sf = nanosPerUnit(f), st = nanosPerUnit(t);
            exec::Expr* s = sf >= st ? static_cast<exec::Expr*>(pool().make<exec::ScaleUnits>(e.node, sf / st, 1))
                                     : static_cast<exec::Expr*>(pool().make<exec::ScaleUnits>(e.node, 1, st / sf));
            n = intConv(s);
        }
    } else if (isIntRep(from) && isIntRep(target)) {
        n = intConv(e.node);
    } else {
        error(diag::E0201, loc, fmt::format("no conversion from {} to {}", typeName(from), typeName(target)));
        return bad(loc);
    }
    n->type = target;
    r.node = n;
    if (e.isConst) return foldIfConst(r, {&e});
    return r;
}

Checked Checker::coerce(Checked e, const Type* target, const ast::Loc& loc, const char* what) {
    if (!e.ok || !target) return bad(loc);
    const Type* from = e.type;
    if (e.untypedInt) {
        TK t = target->kind;
        if (isInteger(t) || isBitString(t) || t == TK::Bool) {
            if (!fitsIn(e.constInt, false, target)) {
                // A literal that does not fit is an error; a constant expression
                // (127 + 1) wraps like the run-time arithmetic, with a warning (decision 0090).
                if (!e.foldedExpr || t == TK::Bool) {
                    error(diag::E0205, loc, fmt::format("constant {} is outside the range of {}", e.constInt, typeName(target)));
                    return bad(loc);
                }
                Checked wrapped = convert(settle(e), target, loc);
                if (!wrapped.ok) return wrapped;
                if (!lenient(diag::W0002, loc, fmt::format("constant {} does not fit {}; it wraps to {}", e.constInt, typeName(target), wrapped.constInt)))
                    return bad(loc);
                return wrapped;
            }
            Checked c = constInt(e.constInt, target, e.loc);
            return c;
        }
        if (isReal(t)) return constReal(static_cast<double>(e.constInt), target, e.loc);
        e = settle(e);
        from = e.type;
    }
    if (e.untypedReal) {
        if (isReal(target->kind)) return constReal(e.constReal, target, e.loc);
        e = settle(e);
        from = e.type;
    }
    if (isStringType(from->kind) && from->kind == target->kind && e.isConst && from->maxLen > target->maxLen && target->maxLen > 0)
        warning(diag::W0016, e.loc.line ? e.loc : loc, fmt::format("the string has {} characters; {} keeps only the first {}", from->maxLen,
                                                      typeName(target), target->maxLen));
    if (isStringType(target->kind) && isCharType(from->kind) && (target->kind == TK::WString) == (from->kind == TK::WChar) && !e.untypedInt) {
        // A CHAR widens to the STRING of that character (IEC Ed.3, SIMATIC AX; decision 0394).
        if (exec::Expr* n = charAsString(e, target)) {
            Checked c = e;
            c.type = types().string(1, target->kind == TK::WString);
            c.isPlace = false;
            c.isConst = false;
            c.var = nullptr;
            c.direct = Checked::Direct::None;
            c.node = n;
            c.node->type = c.type;
            return c;
        }
    }
    if (isCharType(target->kind) && isStringType(from->kind) && e.isConst) {
        // c : CHAR := 'A': a one-character string literal is that character.
        if (auto* bytes = exec::nodeCast<exec::ConstBytes>(e.node)) {
            bool wide = from->kind == TK::WString;
            int64_t first = wide ? (bytes->bytes[0] | (bytes->bytes[1] << 8)) : bytes->bytes[0];
            int64_t second = wide ? (bytes->bytes.size() > 3 ? (bytes->bytes[2] | (bytes->bytes[3] << 8)) : 0) : (bytes->bytes.size() > 1 ? bytes->bytes[1] : 0);
            if (first != 0 && second == 0 && (target->kind == TK::WChar || first < 256)) return constInt(first, target, e.loc);
        }
    }
    if (e.flexibleLiteral && isNumeric(from->kind) && (isNumeric(target->kind) || isBitString(target->kind)) && !sameType(from, target)) {
        Checked c = convert(e, target, loc);
        c.flexibleLiteral = false;
        return c;
    }
    if (sameType(from, target)) {
        if (isStringType(target->kind)) { e.type = from; return e; }
        e.type = target;
        return e;
    }
    if (isStringType(from->kind) && isStringType(target->kind)) {
        if (from->kind == target->kind) return e;
    }
    if (target->kind == TK::Pointer && (from->kind == TK::Pointer || (e.isConst && e.constInt == 0))) {
        e.type = target;  // POINTER TO x := ADR(...), any pointer, or 0
        return e;
    }
    // CODESYS: a POINTER and an unsigned integer of the pointer's width convert
    // into each other (temp : LWORD := pt; pt := temp), with a warning.
    auto pointerWide = [](const Type* t) { return t->kind == TK::ULInt || t->kind == TK::LWord; };
    if ((target->kind == TK::Pointer && pointerWide(from)) || (from->kind == TK::Pointer && pointerWide(target))) {
        const bool promotion = std::strcmp(what, "operand") == 0;  // `pt < end`: compared as addresses
        if (!promotion && !lenient(diag::W0001, loc, fmt::format("implicit conversion from {} to {}", typeName(from), typeName(target)))) return bad(loc);
        e.type = target;
        if (e.node) e.node->type = target;
        e.isPlace = false;
        e.var = nullptr;
        return e;
    }
    if (target->kind == TK::Reference && from->kind == TK::Reference && sameType(from->target, target->target)) return e;
    // THIS (the address of the own instance) for an interface its class
    // implements, as SIMATIC AX returns it (`Append := THIS;`, decision 0366):
    // checked as the instance THIS^ itself.
    if (target->kind == TK::Interface && from->kind == TK::Pointer && from->target && from->target->kind == TK::FunctionBlock &&
        e.node && exec::nodeCast<exec::SelfAddress>(e.node)) {
        Checked self = e;
        self.type = from->target;
        self.isPlace = true;
        self.node = pool().make<exec::SelfVar<void>>(0);
        self.node->type = from->target;
        return coerce(self, target, loc, what);
    }
    if (target->kind == TK::Interface && (from->kind == TK::FunctionBlock || from->kind == TK::Interface)) {
        // An interface value is the address of an instance whose class implements it.
        bool ok = false;
        if (from->kind == TK::FunctionBlock && from->pou) {
            for (PouInfo* p = from->pou; p && !ok; p = p->parent)
                for (const auto& n : p->ast->implements) {
                    NameScopeGuard scope(*this, p->ast->nameSpace, p->ast->loc.file);  // written in the block's namespace
                    PouInfo* itf = pouNamed(n);
                    if (!itf) continue;
                    std::vector<PouInfo*> all;
                    collectInterfaces(itf, all);
                    for (PouInfo* i : all) ok = ok || i == target->pou;
                }
            if (ok && !e.isPlace) ok = false;
        } else if (from->pou) {
            std::vector<PouInfo*> all;
            collectInterfaces(from->pou, all);
            for (PouInfo* i : all) ok = ok || i == target->pou;
        }
        if (!ok) {
            error(diag::E0405, loc, fmt::format("{}: {} does not implement {}", what, typeName(from), typeName(target)));
            return bad(loc);
        }
        Checked c = e;
        c.type = target;
        c.isPlace = false;
        c.direct = Checked::Direct::None;
        if (from->kind == TK::FunctionBlock) c.node = pool().make<exec::AddressOf>(e.node);
        c.node->type = target;
        return c;
    }
    if (target->kind == TK::Interface && e.isConst && e.constInt == 0) { e.type = target; return e; }
    if (target->kind == TK::Struct && from->kind == TK::Struct) {
        for (const Type* p = from->parent; p; p = p->parent)
            if (p == target) return e;  // derived struct to base: copies the base part
    }
    if (target->kind == TK::FunctionBlock && from->kind == TK::FunctionBlock && target->pou && from->pou && from->pou->parent) {
        // A derived class (or block) instance for its base class: the base
        // part is copied, the target keeps its class (decision 0392).
        for (PouInfo* p = from->pou->parent; p; p = p->parent)
            if (p == target->pou) {
                Checked c = e;
                c.type = target;
                c.isPlace = false;
                c.var = nullptr;
                c.direct = Checked::Direct::None;
                c.node = pool().make<exec::ClassPartOf>(e.node);
                c.node->type = target;
                return c;
            }
    }
    if (isElementary(from->kind) && isElementary(target->kind)) {
        if (iecImplicit(from, target)) return convert(e, target, loc);
        // A literal above LINT's range (16#FFFF_FFFF_FFFF_FFFF) is a ULINT constant; it fits an LWORD as it is.
        if (e.isConst && !e.var && from->kind == TK::ULInt && target->kind == TK::LWord) return convert(e, target, loc);
        const bool promotion = std::strcmp(what, "operand") == 0;  // operands brought to their common type
        if (promotion && bitStringMix(from, target)) return convert(e, target, loc);
        if (codesysImplicit(from, target)) {
            if (!lenient(diag::W0001, loc, fmt::format("implicit conversion from {} to {}: possible loss of data", typeName(from), typeName(target)),
                         fmt::format("; use {}_TO_{}", upper(from->name), upper(target->name))))
                return bad(loc);
            return convert(e, target, loc);
        }
    }
    const bool enumToInt = from->kind == TK::Enum && (isInteger(target->kind) || isBitString(target->kind));
    const bool intToEnum = target->kind == TK::Enum && (isInteger(from->kind) || isBitString(from->kind));
    if (enumToInt || intToEnum) {
        const Type* en = enumToInt ? from : target;
        // {attribute 'strict'} refuses an integer becoming the enumeration; reading
        // the enumeration as an integer stays allowed, as in TwinCAT/CODESYS (decision 0334).
        // A constant that is one of its values may still be assigned, as the attribute's
        // documentation words it ("a constant value which is not an enumeration value").
        bool isOneOfItsValues = false;
        if (intToEnum && e.isConst)
            for (const Enumerator& v : en->enumerators) isOneOfItsValues = isOneOfItsValues || v.value == e.constInt;
        if (en->strictEnum && intToEnum && !isOneOfItsValues) {
            error(diag::E0201, loc, fmt::format("{}: cannot convert {} to {} implicitly; '{}' has {{attribute 'strict'}}", what, typeName(from),
                                   typeName(target), en->name));
            return bad(loc);
        }
        // A constant that is one of its values (`ParameterNumber := 18`) is what
        // TwinCAT and CODESYS take without a message, strict or not; IEC has no
        // integer-to-enumeration conversion, so --strict still refuses it (decision 0429).
        const bool silent = isOneOfItsValues && !options_.strict;
        if (!silent && !lenient(diag::W0001, loc, fmt::format("implicit conversion from {} to {}", typeName(from), typeName(target))))
            return bad(loc);
        Checked c = convert(e, enumToInt ? target : en->base, loc);
        if (!c.ok) return c;
        c.type = target;
        if (c.node) c.node->type = target;
        return c;
    }
    std::string hint;
    if (isElementary(from->kind) && isElementary(target->kind) && !isStringType(from->kind))
        hint = fmt::format("; use {}_TO_{}", upper(from->name == "TIME_OF_DAY" ? "TOD" : from->name == "DATE_AND_TIME" ? "DT" : from->name),
                           upper(target->name == "TIME_OF_DAY" ? "TOD" : target->name == "DATE_AND_TIME" ? "DT" : target->name));
    Diagnostic& d = error(diag::E0201, loc, fmt::format("{}: cannot convert {} to {} implicitly{}", what, typeName(from), typeName(target), hint));
    // `s := "hello"`: in ST double quotes make a WSTRING literal (a C or Python habit).
    if (e.isConst && from->kind == TK::WString && target->kind == TK::String)
        d.withHelp("a STRING literal is written in single quotes ('hello'); double quotes make a WSTRING");
    return bad(loc);
}

const Type* Checker::commonType(Checked& a, Checked& b, const ast::Loc& loc, bool report) {
    auto fail = [&]() -> const Type* {
        if (report) error(diag::E0202, loc, fmt::format("operands of types {} and {} need an explicit conversion", typeName(a.type), typeName(b.type)));
        return nullptr;
    };
    if ((a.untypedInt || a.untypedReal) && (b.untypedInt || b.untypedReal)) {
        if (a.untypedReal || b.untypedReal) return types().elementary(TK::LReal);
        return types().elementary(TK::LInt);
    }
    if (a.untypedInt || a.untypedReal) {
        const Type* r = commonType(b, a, loc, report);
        return r;
    }
    // from here a is typed
    const Type* ta = a.type;
    TK ka = ta->kind;
    if (b.untypedInt && (ka == TK::Pointer || ka == TK::Interface)) return ta;
    if (b.untypedInt) {
        if (isInteger(ka) || isBitString(ka)) {
            if (fitsIn(b.constInt, false, ta)) return ta;
            Checked s = settle(b);
            return commonType(a, s, loc, report);
        }
        if (isReal(ka)) return ta;
        if (ka == TK::Enum) return fail();
        return fail();
    }
    if (b.untypedReal) {
        if (isReal(ka)) return ta;
        if (isInteger(ka) || isBitString(ka)) return types().elementary(TK::Real);
        return fail();
    }
    const Type* tb = b.type;
    TK kb = tb->kind;
    if (sameType(ta, tb)) return isStringType(ka) ? ta : ta;
    if (isStringType(ka) && ka == kb) return ta;
    if ((isInteger(ka) || isBitString(ka)) && (isInteger(kb) || isBitString(kb))) {
        IntInfo ia = intInfo(ka), ib = intInfo(kb);
        if (isBitString(ka) && isBitString(kb)) return types().elementary(bitKindOf(std::max(ia.bits, ib.bits)));
        if (ia.isSigned == ib.isSigned) return types().elementary(intKindOf(ia.isSigned, std::max(ia.bits, ib.bits)));
        IntInfo s = ia.isSigned ? ia : ib, u = ia.isSigned ? ib : ia;
        if (s.bits > u.bits) return types().elementary(intKindOf(true, s.bits));
        return types().elementary(intKindOf(true, std::min(64, u.bits * 2)));
    }
    if (isReal(ka) || isReal(kb)) {
        // A bit string meets a REAL as a number (CODESYS; `(high - low) * X` with X : BYTE):
        // the operand's conversion then warns, or is an error with --strict.
        auto number = [](TK k) { return isReal(k) || isInteger(k) || (isBitString(k) && k != TK::Bool); };
        bool otherOk = number(ka) && number(kb);
        if (!otherOk) return fail();
        if (ka == TK::LReal || kb == TK::LReal) return types().elementary(TK::LReal);
        return types().elementary(TK::Real);
    }
    if (ka == TK::Enum && kb == TK::Enum) return ta == tb ? ta : fail();
    if ((ka == TK::Pointer || ka == TK::Interface) && (kb == TK::Pointer || kb == TK::Interface)) return ta;
    // CODESYS: a pointer compares with an integer as the unsigned address (OSCAT's `pt < end`).
    if ((ka == TK::Pointer && (isInteger(kb) || isBitString(kb))) || (kb == TK::Pointer && (isInteger(ka) || isBitString(ka))))
        return types().elementary(TK::ULInt);
    if (ka == kb && isElementary(ka)) return ta;
    if (isTimeLike(ka) && isTimeLike(kb)) return types().elementary(TK::LTime);
    return fail();
}

Checked Checker::foldIfConst(Checked r, std::initializer_list<const Checked*> operands) {
    for (const Checked* o : operands)
        if (!o->isConst) return r;
    exec::Ctx dummy;
    if (isRealRep(r.type)) {
        double v = r.node->f(dummy);
        Checked c = constReal(v, r.type, r.loc);
        return c;
    }
    if (isIntRep(r.type)) {
        int64_t v = r.node->i(dummy);
        Checked c = constInt(v, r.type, r.loc);
        return c;
    }
    return r;
}

// For overload resolution (checker_overloads.cpp): the silent IEC conversions.
bool iecWidening(const Type* from, const Type* to) { return iecImplicit(from, to); }

}  // namespace strun::sema
