// Operators: operand types brought to a common type, the node specialised for
// it, and constant operands folded at check time (except a division by a
// constant zero, which keeps its runtime DIV_BY_ZERO rule).
#include <fmt/format.h>

#include "interpreter/sema/checker.h"
#include "interpreter/sema/fuse.h"
#include "interpreter/sema/node_factory.h"

namespace strun::sema {

using exec::CmpOp;

namespace {

template <template <class> class N>
exec::Expr* intOp(exec::NodePool& pool, Rep rep, exec::Expr* a, exec::Expr* b) {
    return makeIntByRep<N>(pool, rep, a, b);
}

constexpr exec::BinOp binOpOf(CmpOp op) {
    switch (op) {
        case CmpOp::Eq: return exec::BinOp::Eq;
        case CmpOp::Ne: return exec::BinOp::Ne;
        case CmpOp::Lt: return exec::BinOp::Lt;
        case CmpOp::Le: return exec::BinOp::Le;
        case CmpOp::Gt: return exec::BinOp::Gt;
        default: return exec::BinOp::Ge;
    }
}

template <CmpOp OP>
struct CmpIntBind {
    template <class T>
    using I = exec::CmpI<T, OP>;
    template <class T>
    using IK = exec::CmpIK<T, OP>;
};

template <CmpOp OP>
exec::Expr* cmpConstNode(exec::NodePool& pool, Rep rep, exec::Expr* a, int64_t k) {
    if (exec::Expr* n = fuseBinary(pool, binOpOf(OP), rep, a, nullptr, k)) return n;
    return makeIntByRep<CmpIntBind<OP>::template IK>(pool, rep, a, k);
}

template <CmpOp OP>
exec::Expr* cmpNode(exec::NodePool& pool, const Type* t, exec::Expr* a, exec::Expr* b) {
    Rep rep = repOf(t);
    if (!isStringType(t->kind))
        if (exec::Expr* n = fuseBinary(pool, binOpOf(OP), (rep == Rep::F32 || rep == Rep::F64) ? rep : arithmeticRep(rep), a, b)) return n;
    if (rep == Rep::F32) return pool.make<exec::CmpF<float, OP>>(a, b);
    if (rep == Rep::F64) return pool.make<exec::CmpF<double, OP>>(a, b);
    if (t->kind == TK::String) return pool.make<exec::CmpStr<char, OP>>(a, b);
    if (t->kind == TK::WString) return pool.make<exec::CmpStr<char16_t, OP>>(a, b);
    return makeIntByRep<CmpIntBind<OP>::template I>(pool, arithmeticRep(rep), a, b);
}

CmpOp cmpOpOf(ast::Op op) {
    switch (op) {
        case ast::Op::Eq: return CmpOp::Eq;
        case ast::Op::Ne: return CmpOp::Ne;
        case ast::Op::Lt: return CmpOp::Lt;
        case ast::Op::Le: return CmpOp::Le;
        case ast::Op::Gt: return CmpOp::Gt;
        default: return CmpOp::Ge;
    }
}

const char* opText(ast::Op op) {
    switch (op) {
        case ast::Op::Add: return "+";
        case ast::Op::Sub: return "-";
        case ast::Op::Mul: return "*";
        case ast::Op::Div: return "/";
        case ast::Op::Mod: return "MOD";
        case ast::Op::Pow: return "**";
        case ast::Op::Eq: return "=";
        case ast::Op::Ne: return "<>";
        case ast::Op::Lt: return "<";
        case ast::Op::Le: return "<=";
        case ast::Op::Gt: return ">";
        case ast::Op::Ge: return ">=";
        case ast::Op::And: return "AND";
        case ast::Op::Or: return "OR";
        case ast::Op::Xor: return "XOR";
        case ast::Op::AndThen: return "AND_THEN";
        case ast::Op::OrElse: return "OR_ELSE";
        case ast::Op::Neg: return "-";
        case ast::Op::Plus: return "+";
        case ast::Op::Not: return "NOT";
    }
    return "?";
}

// TIME * number: computed in the time's unit; a TwinCAT project's TIME/LTIME
// is unsigned (decisions 0367, 0389), so its bits are read and rounded so.
struct TimeMulReal final : exec::Expr {
    exec::Expr *t, *k;
    bool divide;
    int bits;
    bool isUnsigned;
    TimeMulReal(exec::Expr* a, exec::Expr* b, bool d, int n, bool u) : t(a), k(b), divide(d), bits(n), isUnsigned(u) {}
    int64_t i(exec::Ctx& c) override {
        const int64_t raw = t->i(c);
        double v = isUnsigned ? static_cast<double>(static_cast<uint64_t>(raw)) : static_cast<double>(raw);
        double f = k->f(c);
        double r = divide ? v / f : v * f;
        return exec::realToIntRounded(r, bits, !isUnsigned);
    }
};

}  // namespace

Checked Checker::checkUnary(const ast::Expr& e) {
    Checked a = checkExpr(*e.kids[0]);
    if (!a.ok) return a;
    Checked r;
    r.ok = true;
    r.loc = e.loc;
    r.hasCall = a.hasCall;
    if (e.op == ast::Op::Plus) {
        if (!(isNumeric(a.type->kind) || a.untypedInt || a.untypedReal || isTimeLike(a.type->kind))) {
            error(diag::E0202, e.loc, fmt::format("unary '+' needs a number, not {}", typeName(a.type)));
            return bad(e.loc);
        }
        a.isPlace = false;
        a.var = nullptr;
        return a;
    }
    if (e.op == ast::Op::Neg) {
        if (a.untypedInt) {
            // Wrapping negation: -(LINT min) must not be C++ signed overflow.
            Checked c = constInt(static_cast<int64_t>(uint64_t{0} - static_cast<uint64_t>(a.constInt)), a.type, e.loc);
            c.untypedInt = true;
            c.foldedExpr = a.foldedExpr;
            return c;
        }
        if (a.isConst && a.type->kind == TK::ULInt && static_cast<uint64_t>(a.constInt) == (uint64_t(1) << 63)) {
            // -9223372036854775808: the magnitude alone only fits ULINT.
            Checked c = constInt(a.constInt, types().elementary(TK::LInt), e.loc);
            c.untypedInt = true;
            return c;
        }
        if (a.untypedReal) { Checked c = constReal(-a.constReal, a.type, e.loc); c.untypedReal = true; return c; }
        TK k = a.type->kind;
        if (isBitString(k) && k != TK::Bool) {
            // CODESYS negates a bit string as a number (OSCAT's `INC(cnt, -step, mx)`
            // with step : BYTE gives -step): it becomes the signed integer of twice
            // its width (LINT for 32 and 64 bits), with the conversion warning.
            const int bits = bitWidth(k);
            const Type* to = types().elementary(bits <= 8 ? TK::Int : bits <= 16 ? TK::DInt : TK::LInt);
            a = coerce(a, to, e.loc, "operand");
            if (!a.ok) return a;
            k = a.type->kind;
        }
        if (!(isInteger(k) || isReal(k) || isTimeLike(k))) {
            error(diag::E0202, e.loc, fmt::format("unary '-' needs a number or a duration, not {}", typeName(a.type)));
            return bad(e.loc);
        }
        r.type = a.type;
        Rep rep = isReal(k) ? repOf(a.type) : arithmeticRep(repOf(a.type));
        r.node = isReal(k) ? makeRealByRep<exec::NegF>(pool(), rep, a.node) : makeIntByRep<exec::NegI>(pool(), rep, a.node);
        r.node->type = r.type;
        return foldIfConst(r, {&a});
    }
    // NOT
    if (a.untypedInt) a = settle(a);
    TK k = a.type->kind;
    r.type = a.type;
    if (k == TK::Bool) r.node = pool().make<exec::NotBool>(a.node);
    else if (isBitString(k) || isInteger(k)) r.node = makeIntByRep<exec::NotBits>(pool(), repOf(a.type), a.node);
    else {
        error(diag::E0202, e.loc, fmt::format("NOT needs a BOOL or a bit string, not {}", typeName(a.type)));
        return bad(e.loc);
    }
    r.node->type = r.type;
    return foldIfConst(r, {&a});
}

Checked Checker::checkBinary(const ast::Expr& e) {
    Checked a = checkExpr(*e.kids[0]);
    const bool compare = e.op == ast::Op::Eq || e.op == ast::Op::Ne || e.op == ast::Op::Lt || e.op == ast::Op::Le ||
                         e.op == ast::Op::Gt || e.op == ast::Op::Ge;
    Checked b = compare && a.ok ? checkExprExpecting(*e.kids[1], a.type) : checkExpr(*e.kids[1]);
    if (!a.ok || !b.ok) return bad(e.loc);
    switch (e.op) {
        case ast::Op::Eq: case ast::Op::Ne: case ast::Op::Lt: case ast::Op::Le: case ast::Op::Gt: case ast::Op::Ge:
            return makeCompare(e.op, std::move(a), std::move(b), e.loc);
        case ast::Op::And: case ast::Op::Or: case ast::Op::Xor: case ast::Op::AndThen: case ast::Op::OrElse:
            return makeLogic(e.op, std::move(a), std::move(b), e.loc);
        default:
            return makeArith(e.op, std::move(a), std::move(b), e.loc);
    }
}

Checked Checker::makeArith(ast::Op op, Checked a, Checked b, const ast::Loc& loc) {
    Checked r;
    r.ok = true;
    r.loc = loc;
    r.hasCall = a.hasCall || b.hasCall;
    // `(eModule - 1) * nOffset`: an enumeration without {attribute 'strict'} is
    // its integer in arithmetic (CODESYS/TwinCAT), with the implicit-conversion
    // warning; an error with --strict or on a strict enumeration (decision 0327).
    auto enumAsInteger = [&](Checked& v, const Checked& other) {
        const TK ko = other.type->kind;
        if (v.type->kind != TK::Enum || !v.type->base || !(other.untypedInt || isInteger(ko) || isBitString(ko) || ko == TK::Enum)) return;
        if (v.type->strictEnum) {  // reading it as an integer is allowed, computing with it is not (decision 0334)
            error(diag::E0201, v.loc.line ? v.loc : loc,
                  fmt::format("operand: no arithmetic on enumeration {}; '{}' has {{attribute 'strict'}}", typeName(v.type), v.type->name));
            v = bad(loc);
            return;
        }
        v = coerce(v, v.type->base, v.loc.line ? v.loc : loc, "operand");
    };
    enumAsInteger(a, b);
    if (!a.ok) return bad(loc);
    enumAsInteger(b, a);
    if (!b.ok) return bad(loc);
    TK ka = a.type->kind, kb = b.type->kind;
    if ((op == ast::Op::Div || op == ast::Op::Mod) && b.isConst && (b.untypedInt || isInteger(kb) || isBitString(kb)) &&
        b.constInt == 0)
        warning(diag::W0012, b.loc.line ? b.loc : loc, fmt::format("division by the constant 0: at run time {} records DIV_BY_ZERO and divides by 1",
                                                       op == ast::Op::Div ? "'/'" : "MOD"));
    bool aNum = a.untypedInt || a.untypedReal || isNumeric(ka);
    bool bNum = b.untypedInt || b.untypedReal || isNumeric(kb);
    // ---- durations and dates (IEC table of time operations)
    bool aTime = !a.untypedInt && !a.untypedReal && (isTimeLike(ka) || isDateLike(ka));
    bool bTime = !b.untypedInt && !b.untypedReal && (isTimeLike(kb) || isDateLike(kb));
    if (aTime || bTime) {
        if ((op == ast::Op::Mul || op == ast::Op::Div) && aTime && isTimeLike(ka) && bNum) {
            r.type = a.type;
            if (b.untypedReal || isReal(kb)) {
                Checked bb = b.untypedReal ? coerce(b, types().elementary(TK::LReal), loc, "operand") : b;
                r.node = pool().make<TimeMulReal>(a.node, bb.node, op == ast::Op::Div, bitWidth(ka), a.type->unsignedDuration);
            } else {
                // TIME * ANY_INT: the count multiplies the time's own unit.
                Checked bb = settle(b);
                if (!(isInteger(bb.type->kind) || isBitString(bb.type->kind))) {
                    error(diag::E0202, loc, fmt::format("a duration can be multiplied or divided only by a number, not {}", typeName(bb.type)));
                    return bad(loc);
                }
                if (op == ast::Op::Mul) r.node = intOp<exec::MulI>(pool(), repOf(a.type), a.node, bb.node);
                else r.node = makeIntByRep<exec::DivI>(pool(), repOf(a.type), a.node, bb.node, site(loc));
                r.node->type = r.type;
                if (op == ast::Op::Div && bb.isConst && bb.constInt == 0) return r;
                return foldIfConst(r, {&a, &bb});
            }
            r.node->type = r.type;
            return r;
        }
        if (op == ast::Op::Mul && bTime && isTimeLike(kb) && aNum) return makeArith(op, b, a, loc);
        if (op == ast::Op::Add || op == ast::Op::Sub) {
            const Type* result = nullptr;
            Checked x = a, y = b;
            if (isTimeLike(ka) && isTimeLike(kb)) {
                result = ka == TK::LTime || kb == TK::LTime ? types().elementary(TK::LTime) : a.type;
            } else if (isDateLike(ka) && ka != TK::Date && ka != TK::LDate && isTimeLike(kb)) {
                result = a.type;  // TOD/DT +- TIME
            } else if (!options_.strict && (ka == TK::Date || ka == TK::LDate) && isTimeLike(kb)) {
                result = a.type;  // DATE +- TIME: computed as DT +- TIME, as TwinCAT compiles it (decision 0368)
            } else if (op == ast::Op::Add && isTimeLike(ka) && isDateLike(kb) && kb != TK::Date && kb != TK::LDate) {
                return makeArith(op, b, a, loc);
            } else if (op == ast::Op::Sub && isDateLike(ka) && ka == kb) {
                result = (ka == TK::Date || ka == TK::Dt || ka == TK::Tod) ? types().elementary(TK::Time) : types().elementary(TK::LTime);
            }
            if (!result) {
                error(diag::E0202, loc, fmt::format("operator '{}' is not defined for {} and {}", opText(op), typeName(a.type), typeName(b.type)));
                return bad(loc);
            }
            if (isDateLike(ka) || isDateLike(kb)) {
                // One rule for `dt - T#345ms` and SUB_DT_TIME (decision 0093).
                if (const BuiltinFn* fn = builtinTable().find(op == ast::Op::Add ? kDateAddOperator : kDateSubOperator)) {
                    CallArgs call;
                    call.name = opText(op);
                    call.args = {a, b};
                    call.names = {"", ""};
                    call.loc = loc;
                    return (*fn)(*this, call);
                }
            }
            // Bring both operands to nanoseconds-or-unit of the result.
            int64_t sr = nanosPerUnit(result->kind);
            auto toUnit = [&](Checked v) -> exec::Expr* {
                int64_t sv = nanosPerUnit(v.type->kind);
                if (sv == sr) return v.node;
                return sv > sr ? pool().make<exec::ScaleUnits>(v.node, sv / sr, 1) : pool().make<exec::ScaleUnits>(v.node, 1, sr / sv);
            };
            exec::Expr* xa = toUnit(x);
            exec::Expr* yb = toUnit(y);
            Rep rep = repOf(result);
            r.type = result;
            if (result->kind == TK::Tod || result->kind == TK::LTod) {
                // TOD +- TIME stays within the day, as ADD_TOD_TIME (decision 0053).
                int64_t day = result->kind == TK::Tod ? 86400000LL : 86400000000000LL;
                exec::Expr* sum = op == ast::Op::Add ? intOp<exec::AddI>(pool(), Rep::I64, xa, yb) : intOp<exec::SubI>(pool(), Rep::I64, xa, yb);
                r.node = pool().make<exec::WrapModulo>(sum, day);
            } else {
                r.node = op == ast::Op::Add ? intOp<exec::AddI>(pool(), rep, xa, yb) : intOp<exec::SubI>(pool(), rep, xa, yb);
            }
            r.node->type = result;
            return foldIfConst(r, {&a, &b});
        }
        error(diag::E0202, loc, fmt::format("operator '{}' is not defined for {} and {}", opText(op), typeName(a.type), typeName(b.type)));
        return bad(loc);
    }
    if (ka == TK::Pointer && kb == TK::Pointer && op == ast::Op::Sub) {
        // `pLoc - pBuffer` (TwinCAT TcDynStringKit): the distance in bytes, a
        // signed LINT (__XINT on strun's 64-bit platform; decision 0439).
        r.type = types().elementary(TK::LInt);
        r.node = intOp<exec::SubI>(pool(), Rep::I64, a.node, b.node);
        r.node->type = r.type;
        return r;
    }
    if ((ka == TK::Pointer && (b.untypedInt || isInteger(kb) || (isBitString(kb) && kb != TK::Bool))) && (op == ast::Op::Add || op == ast::Op::Sub)) {
        // CODESYS pointer arithmetic: in bytes.
        Checked y = convert(b, types().elementary(TK::LInt), loc);
        r.type = a.type;
        r.node = op == ast::Op::Add ? intOp<exec::AddI>(pool(), Rep::U64, a.node, y.node) : intOp<exec::SubI>(pool(), Rep::U64, a.node, y.node);
        r.node->type = r.type;
        return r;
    }
    bool aInt = a.untypedInt || isInteger(ka) || isBitString(ka);
    bool bInt = b.untypedInt || isInteger(kb) || isBitString(kb);
    if (!(aNum || aInt) || !(bNum || bInt)) {
        error(diag::E0202, loc, fmt::format("operator '{}' needs numbers, not {} and {}", opText(op), typeName(a.type), typeName(b.type)));
        return bad(loc);
    }
    if (op == ast::Op::Pow) {
        // REAL ** 10.0 stays REAL: an untyped literal takes the other operand's type.
        const Type* rt = (ka == TK::LReal && !a.untypedReal) || (kb == TK::LReal && !b.untypedReal) ? types().elementary(TK::LReal)
                                                                                                     : types().elementary(TK::Real);
        if ((a.untypedInt || a.untypedReal) && (b.untypedInt || b.untypedReal)) rt = types().elementary(TK::LReal);
        if ((a.untypedInt || a.untypedReal) && (b.untypedInt || b.untypedReal)) rt = types().elementary(TK::LReal);
        Checked x = convert(a, rt, loc), y = convert(b, rt, loc);
        if (!x.ok || !y.ok) return bad(loc);
        r.type = rt;
        r.node = makeRealByRep<exec::PowF>(pool(), repOf(rt), x.node, y.node);
        r.node->type = rt;
        bool untyped = (a.untypedInt || a.untypedReal) && (b.untypedInt || b.untypedReal);
        Checked f = foldIfConst(r, {&x, &y});
        f.untypedReal = untyped;
        return f;
    }
    const bool bothUntyped = (a.untypedInt || a.untypedReal) && (b.untypedInt || b.untypedReal);
    if (bothUntyped && (op == ast::Op::Div || op == ast::Op::Mod) && b.untypedInt && b.constInt == 0) {
        // 10 / 0 is not folded (DIV_BY_ZERO at run time): give it the dividend's natural type.
        a = settle(a);
        b = settle(b);
    }
    const Type* t = commonType(a, b, loc);
    if (!t) return bad(loc);
    if (op == ast::Op::Mod && !(isInteger(t->kind) || isBitString(t->kind))) {
        error(diag::E0202, loc, fmt::format("MOD needs integers, not {}", typeName(t)));
        return bad(loc);
    }
    Checked x = coerce(a, t, loc, "operand");
    Checked y = coerce(b, t, loc, "operand");
    if (!x.ok || !y.ok) return bad(loc);
    r.type = t;
    bool real = isReal(t->kind);
    Rep rep = real ? repOf(t) : arithmeticRep(repOf(t));
    if (!real && y.isConst && !x.isConst) {
        int64_t k = y.constInt;
        bool safeDivisor = k != 0 && !(k == -1 && isSignedInt(integerView(t->kind)));
        // +-2^k divides by shifts (decision 0490); the magnitude as the
        // computation type sees the constant.
        const uint64_t magnitude = k < 0 && isSignedInt(integerView(t->kind)) ? 0 - static_cast<uint64_t>(k) : static_cast<uint64_t>(k);
        const bool powerOfTwo = exec::isPowerOfTwoDivisor(magnitude);
        exec::Expr* n = nullptr;
        switch (op) {
            case ast::Op::Add: n = fuseBinary(pool(), exec::BinOp::Add, rep, x.node, nullptr, k); break;
            case ast::Op::Sub: n = fuseBinary(pool(), exec::BinOp::Sub, rep, x.node, nullptr, k); break;
            case ast::Op::Mul: n = fuseBinary(pool(), exec::BinOp::Mul, rep, x.node, nullptr, k); break;
            case ast::Op::Div: if (safeDivisor) n = fuseBinary(pool(), exec::BinOp::Div, rep, x.node, nullptr, k); break;
            case ast::Op::Mod: if (safeDivisor) n = fuseBinary(pool(), exec::BinOp::Mod, rep, x.node, nullptr, k); break;
            default: break;
        }
        if (!n) switch (op) {
            case ast::Op::Add: n = makeIntByRep<exec::AddIK>(pool(), rep, x.node, k); break;
            case ast::Op::Sub: n = makeIntByRep<exec::SubIK>(pool(), rep, x.node, k); break;
            case ast::Op::Mul: n = makeIntByRep<exec::MulIK>(pool(), rep, x.node, k); break;
            case ast::Op::Div:
                if (safeDivisor) n = powerOfTwo ? makeIntByRep<exec::DivPow2K>(pool(), rep, x.node, k) : makeIntByRep<exec::DivIK>(pool(), rep, x.node, k);
                break;
            case ast::Op::Mod:
                if (safeDivisor) n = powerOfTwo ? makeIntByRep<exec::ModPow2K>(pool(), rep, x.node, k) : makeIntByRep<exec::ModIK>(pool(), rep, x.node, k);
                break;
            default: break;
        }
        if (n) {
            r.node = n;
            r.node->type = t;
            return r;
        }
    }
    if (real && (x.isConst != y.isConst) && op != ast::Op::Mod) {
        const bool left = x.isConst;
        exec::Expr* v = left ? y.node : x.node;
        double k = left ? x.constReal : y.constReal;
        auto make = [&](auto tag) -> exec::Expr* {
            using T = decltype(tag);
            switch (op) {
                case ast::Op::Add: return left ? static_cast<exec::Expr*>(pool().make<exec::RealK<T, exec::RealOp::Add, true>>(v, k)) : pool().make<exec::RealK<T, exec::RealOp::Add, false>>(v, k);
                case ast::Op::Sub: return left ? static_cast<exec::Expr*>(pool().make<exec::RealK<T, exec::RealOp::Sub, true>>(v, k)) : pool().make<exec::RealK<T, exec::RealOp::Sub, false>>(v, k);
                case ast::Op::Mul: return left ? static_cast<exec::Expr*>(pool().make<exec::RealK<T, exec::RealOp::Mul, true>>(v, k)) : pool().make<exec::RealK<T, exec::RealOp::Mul, false>>(v, k);
                default: return left ? static_cast<exec::Expr*>(pool().make<exec::RealK<T, exec::RealOp::Div, true>>(v, k)) : pool().make<exec::RealK<T, exec::RealOp::Div, false>>(v, k);
            }
        };
        static constexpr exec::BinOp kBin[] = {exec::BinOp::Add, exec::BinOp::Sub, exec::BinOp::Mul, exec::BinOp::Div};
        const int which = op == ast::Op::Add ? 0 : op == ast::Op::Sub ? 1 : op == ast::Op::Mul ? 2 : 3;
        r.node = left ? nullptr : fuseBinary(pool(), kBin[which], rep, v, nullptr, 0, k);
        if (!r.node) r.node = rep == Rep::F32 ? make(float{}) : make(double{});
        r.node->type = t;
        return r;
    }
    switch (op) {
        case ast::Op::Add: r.node = fuseBinary(pool(), exec::BinOp::Add, rep, x.node, y.node); break;
        case ast::Op::Sub: r.node = fuseBinary(pool(), exec::BinOp::Sub, rep, x.node, y.node); break;
        case ast::Op::Mul: r.node = fuseBinary(pool(), exec::BinOp::Mul, rep, x.node, y.node); break;
        case ast::Op::Div: if (real) r.node = fuseBinary(pool(), exec::BinOp::Div, rep, x.node, y.node); break;
        default: r.node = nullptr; break;
    }
    if (!r.node) switch (op) {
        case ast::Op::Add: r.node = real ? makeRealByRep<exec::AddF>(pool(), rep, x.node, y.node) : intOp<exec::AddI>(pool(), rep, x.node, y.node); break;
        case ast::Op::Sub: r.node = real ? makeRealByRep<exec::SubF>(pool(), rep, x.node, y.node) : intOp<exec::SubI>(pool(), rep, x.node, y.node); break;
        case ast::Op::Mul: r.node = real ? makeRealByRep<exec::MulF>(pool(), rep, x.node, y.node) : intOp<exec::MulI>(pool(), rep, x.node, y.node); break;
        case ast::Op::Div:
            r.node = real ? makeRealByRep<exec::DivF>(pool(), rep, x.node, y.node)
                          : makeIntByRep<exec::DivI>(pool(), rep, x.node, y.node, site(loc));
            break;
        case ast::Op::Mod: r.node = makeIntByRep<exec::ModI>(pool(), rep, x.node, y.node, site(loc)); break;
        default: error(diag::E0202, loc, "unsupported operator"); return bad(loc);
    }
    r.node->type = t;
    if ((op == ast::Op::Div || op == ast::Op::Mod) && !real && y.isConst && y.constInt == 0) {
        r.flexibleLiteral = bothUntyped;  // 10 / 0 assigned to an INT is an INT division
        return r;  // runtime DIV_BY_ZERO
    }
    Checked f = foldIfConst(r, {&x, &y});
    if (bothUntyped && f.isConst) {
        if (real) f.untypedReal = true;
        else f.untypedInt = true;
        if (f.untypedInt) { f.type = types().elementary(f.constInt >= INT32_MIN && f.constInt <= INT32_MAX ? TK::DInt : TK::LInt); f.node->type = f.type; }
        f.foldedExpr = true;
    }
    return f;
}

Checked Checker::makeCompare(ast::Op op, Checked a, Checked b, const ast::Loc& loc) {
    Checked r;
    r.ok = true;
    r.loc = loc;
    r.hasCall = a.hasCall || b.hasCall;
    r.type = types().elementary(TK::Bool);
    // c = 'y' with c : CHAR compares characters.
    warnConstantComparison(op, a, b, loc);
    if (isCharType(a.type->kind) && isStringType(b.type->kind) && b.isConst) b = coerce(b, a.type, b.loc, "operand");
    else if (isCharType(b.type->kind) && isStringType(a.type->kind) && a.isConst) a = coerce(a, b.type, a.loc, "operand");
    if (!a.ok || !b.ok) return bad(loc);
    // A BOOL compared with the literal 0 or 1: IEC's boolean literals, as matiec
    // (Beremiz, OpenPLC) reads `IF INIT = 0 THEN` (decision 0359).
    auto boolLiteral = [](const Checked& c) { return c.untypedInt && c.isConst && (c.constInt == 0 || c.constInt == 1); };
    if (a.type->kind == TK::Bool && boolLiteral(b)) b = coerce(b, a.type, b.loc, "operand");
    else if (b.type->kind == TK::Bool && boolLiteral(a)) a = coerce(a, b.type, a.loc, "operand");
    if (!a.ok || !b.ok) return bad(loc);
    // An integer compared with an enumeration value compares with the value's
    // integer (`UDINT_TO_INT(any.TypeClass) = IBaseLibrary.TypeClass.TYPE_INT`,
    // as TcUnit writes it; CODESYS/TwinCAT accept it): decision 0302. Not with --strict.
    // Also a bit string, for an enumeration on WORD (`eStatus > WORD#16#8000`, SIMATIC AX).
    if (!options_.strict) {
        auto isPlainInteger = [](const Type* t) { return (isInteger(t->kind) || isBitString(t->kind)) && !t->isSubrange; };
        if (a.type->kind == TK::Enum && a.type->base && isPlainInteger(b.type)) a = coerce(a, a.type->base, a.loc, "operand");
        else if (b.type->kind == TK::Enum && b.type->base && isPlainInteger(a.type)) b = coerce(b, b.type->base, b.loc, "operand");
        if (!a.ok || !b.ok) return bad(loc);
    }
    // Two interface values of different interfaces: `=` / `<>` compare the
    // instances they designate (simatic-ax/json: `elem = _lastElement`; decision 0392).
    if (a.type->kind == TK::Interface && b.type->kind == TK::Interface && a.type != b.type && (op == ast::Op::Eq || op == ast::Op::Ne))
        b.type = a.type;
    const Type* t = commonType(a, b, loc, false);
    if (!t || t->kind == TK::Struct || t->kind == TK::FunctionBlock || t->kind == TK::Array) {
        if (t && (op == ast::Op::Eq || op == ast::Op::Ne) && sameType(a.type, b.type)) {
            r.node = op == ast::Op::Eq ? static_cast<exec::Expr*>(pool().make<exec::CmpBytes<true>>(a.node, b.node, t->size))
                                       : pool().make<exec::CmpBytes<false>>(a.node, b.node, t->size);
            r.node->type = r.type;
            return r;
        }
        error(diag::E0202, loc, fmt::format("cannot compare {} with {}", typeName(a.type), typeName(b.type)));
        return bad(loc);
    }
    Checked x = isStringType(t->kind) ? a : coerce(a, t, loc, "operand");
    Checked y = isStringType(t->kind) ? b : coerce(b, t, loc, "operand");
    if (!x.ok || !y.ok) return bad(loc);
    if (isStringType(t->kind) && a.type->kind != b.type->kind) {
        error(diag::E0202, loc, fmt::format("cannot compare {} with {}", typeName(a.type), typeName(b.type)));
        return bad(loc);
    }
    if (isIntRep(t) && y.isConst && !x.isConst) {
        Rep rep = arithmeticRep(repOf(t));
        switch (cmpOpOf(op)) {
            case CmpOp::Eq: r.node = cmpConstNode<CmpOp::Eq>(pool(), rep, x.node, y.constInt); break;
            case CmpOp::Ne: r.node = cmpConstNode<CmpOp::Ne>(pool(), rep, x.node, y.constInt); break;
            case CmpOp::Lt: r.node = cmpConstNode<CmpOp::Lt>(pool(), rep, x.node, y.constInt); break;
            case CmpOp::Le: r.node = cmpConstNode<CmpOp::Le>(pool(), rep, x.node, y.constInt); break;
            case CmpOp::Gt: r.node = cmpConstNode<CmpOp::Gt>(pool(), rep, x.node, y.constInt); break;
            case CmpOp::Ge: r.node = cmpConstNode<CmpOp::Ge>(pool(), rep, x.node, y.constInt); break;
        }
        r.node->type = r.type;
        return r;
    }
    switch (cmpOpOf(op)) {
        case CmpOp::Eq: r.node = cmpNode<CmpOp::Eq>(pool(), t, x.node, y.node); break;
        case CmpOp::Ne: r.node = cmpNode<CmpOp::Ne>(pool(), t, x.node, y.node); break;
        case CmpOp::Lt: r.node = cmpNode<CmpOp::Lt>(pool(), t, x.node, y.node); break;
        case CmpOp::Le: r.node = cmpNode<CmpOp::Le>(pool(), t, x.node, y.node); break;
        case CmpOp::Gt: r.node = cmpNode<CmpOp::Gt>(pool(), t, x.node, y.node); break;
        case CmpOp::Ge: r.node = cmpNode<CmpOp::Ge>(pool(), t, x.node, y.node); break;
    }
    r.node->type = r.type;
    if (isStringType(t->kind)) return r;
    return foldIfConst(r, {&x, &y});
}

Checked Checker::makeLogic(ast::Op op, Checked a, Checked b, const ast::Loc& loc) {
    Checked r;
    r.ok = true;
    r.loc = loc;
    r.hasCall = a.hasCall || b.hasCall;
    if (op == ast::Op::AndThen || op == ast::Op::OrElse) {
        if (a.type->kind != TK::Bool || b.type->kind != TK::Bool) {
            error(diag::E0202, loc, fmt::format("{} needs BOOL operands", opText(op)));
            return bad(loc);
        }
        r.type = a.type;
        r.node = op == ast::Op::AndThen ? static_cast<exec::Expr*>(pool().make<exec::AndThen>(a.node, b.node)) : pool().make<exec::OrElse>(a.node, b.node);
        r.node->type = r.type;
        return foldIfConst(r, {&a, &b});
    }
    // An enumeration declared on a bit-string type is a set of flags in
    // SIMATIC AX: `(mode AND ConversionMode#FORCE_SIGN) = ConversionMode#FORCE_SIGN`
    // computes on the base type and stays the enumeration (decision 0394).
    if (a.type->kind == TK::Enum && a.type == b.type && a.type->base && isBitString(a.type->base->kind)) {
        const Type* flags = a.type;
        a.type = flags->base;
        b.type = flags->base;
        Checked r2 = makeLogic(op, a, b, loc);
        if (!r2.ok) return r2;
        r2.type = flags;
        if (r2.node) r2.node->type = flags;
        return r2;
    }
    const Type* t = nullptr;
    if (a.type->kind == TK::Bool && b.type->kind == TK::Bool && !a.untypedInt && !b.untypedInt) t = a.type;
    else if (a.type->kind == TK::Bool || b.type->kind == TK::Bool) {
        error(diag::E0202, loc, fmt::format("{} of {} and {}: both operands must be BOOL or both bit strings", opText(op), typeName(a.type), typeName(b.type)));
        return bad(loc);
    } else {
        TK ka = a.untypedInt ? TK::Byte : a.type->kind, kb = b.untypedInt ? TK::Byte : b.type->kind;
        if (!(isBitString(ka) || isInteger(ka)) || !(isBitString(kb) || isInteger(kb))) {
            error(diag::E0202, loc, fmt::format("{} needs BOOL or bit-string operands, not {} and {}", opText(op), typeName(a.type), typeName(b.type)));
            return bad(loc);
        }
        t = commonType(a, b, loc);
        if (!t) return bad(loc);
    }
    Checked x = coerce(a, t, loc, "operand");
    Checked y = coerce(b, t, loc, "operand");
    if (!x.ok || !y.ok) return bad(loc);
    Rep rep = repOf(t);
    r.type = t;
    switch (op) {
        case ast::Op::And: r.node = intOp<exec::AndI>(pool(), rep, x.node, y.node); break;
        case ast::Op::Or: r.node = intOp<exec::OrI>(pool(), rep, x.node, y.node); break;
        default: r.node = intOp<exec::XorI>(pool(), rep, x.node, y.node); break;
    }
    r.node->type = t;
    return foldIfConst(r, {&x, &y});
}

}  // namespace strun::sema

namespace strun::sema {

// `u < 0` and `u >= 0` on an unsigned integer: always FALSE / always TRUE.
void Checker::warnConstantComparison(ast::Op op, const Checked& a, const Checked& b, const ast::Loc& loc) {
    if (!a.ok || !b.ok || !a.type || !b.type) return;
    auto zero = [](const Checked& c) { return c.isConst && (c.untypedInt || isInteger(c.type->kind)) && c.constInt == 0; };
    bool alwaysTrue = false, alwaysFalse = false;
    if (isUnsignedInt(a.type->kind) && !a.isConst && zero(b)) {
        alwaysFalse = op == ast::Op::Lt;
        alwaysTrue = op == ast::Op::Ge;
    } else if (isUnsignedInt(b.type->kind) && !b.isConst && zero(a)) {
        alwaysFalse = op == ast::Op::Gt;
        alwaysTrue = op == ast::Op::Le;
    }
    if (!alwaysTrue && !alwaysFalse) return;
    const Type* unsignedType = isUnsignedInt(a.type->kind) ? a.type : b.type;
    warning(diag::W0013, loc, fmt::format("this comparison is always {}: a {} is never negative", alwaysTrue ? "TRUE" : "FALSE", typeName(unsignedType)));
}

}  // namespace strun::sema
