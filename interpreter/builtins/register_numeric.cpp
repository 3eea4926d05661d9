// Numeric functions (ABS SQRT LN LOG EXP SIN COS TAN ASIN ACOS ATAN ATAN2
// EXPT), arithmetic as functions (ADD MUL SUB DIV MOD MOVE), bit shifts
// (SHL SHR ROL ROR) and the logic functions (AND OR XOR NOT).
#include <fmt/format.h>

#include "interpreter/builtins/bind_support.h"
#include "interpreter/builtins/math_nodes.h"
#include "interpreter/builtins/register_groups.h"
#include "interpreter/builtins/time_arith.h"

namespace strun::stdlib::bind {

namespace {

template <MathFn F>
struct MathBind {
    template <class T>
    using N = MathNode<T, F>;
};

exec::Expr* makeMath(exec::NodePool& pool, Rep rep, MathFn fn, exec::Expr* a) {
    switch (fn) {
        case MathFn::Sqrt: return sema::makeRealByRep<MathBind<MathFn::Sqrt>::N>(pool, rep, a);
        case MathFn::Ln: return sema::makeRealByRep<MathBind<MathFn::Ln>::N>(pool, rep, a);
        case MathFn::Log: return sema::makeRealByRep<MathBind<MathFn::Log>::N>(pool, rep, a);
        case MathFn::Exp: return sema::makeRealByRep<MathBind<MathFn::Exp>::N>(pool, rep, a);
        case MathFn::Sin: return sema::makeRealByRep<MathBind<MathFn::Sin>::N>(pool, rep, a);
        case MathFn::Cos: return sema::makeRealByRep<MathBind<MathFn::Cos>::N>(pool, rep, a);
        case MathFn::Tan: return sema::makeRealByRep<MathBind<MathFn::Tan>::N>(pool, rep, a);
        case MathFn::Asin: return sema::makeRealByRep<MathBind<MathFn::Asin>::N>(pool, rep, a);
        case MathFn::Acos: return sema::makeRealByRep<MathBind<MathFn::Acos>::N>(pool, rep, a);
        case MathFn::Atan: return sema::makeRealByRep<MathBind<MathFn::Atan>::N>(pool, rep, a);
    }
    return nullptr;
}

template <ShiftFn F>
struct ShiftBind {
    template <class T>
    using N = ShiftNode<T, F>;
};

exec::Expr* makeShift(exec::NodePool& pool, Rep rep, ShiftFn fn, exec::Expr* in, exec::Expr* n) {
    switch (fn) {
        case ShiftFn::Shl: return sema::makeIntByRep<ShiftBind<ShiftFn::Shl>::N>(pool, rep, in, n);
        case ShiftFn::Shr: return sema::makeIntByRep<ShiftBind<ShiftFn::Shr>::N>(pool, rep, in, n);
        case ShiftFn::Rol: return sema::makeIntByRep<ShiftBind<ShiftFn::Rol>::N>(pool, rep, in, n);
        case ShiftFn::Ror: return sema::makeIntByRep<ShiftBind<ShiftFn::Ror>::N>(pool, rep, in, n);
    }
    return nullptr;
}

void addMath(Checker& ck, const char* name, MathFn fn) {
    struct MathData { MathFn fn; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [fn] = self.data<MathData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
        if (!isNumArg(a[0])) return argError(ck, a[0], call.name, "the input must be a number (ANY_NUM)");
        const Type* t = realTypeFor(ck, a[0]);
        Checked x = ck.convert(a[0], t, a[0].loc);
        if (!x.ok) return x;
        return makeResult(ck, makeMath(ck.pool(), sema::repOf(t), fn, x.node), t, call, a);
    }, MathData{fn}));
}

Checked checkAbs(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
    if (!isNumArg(a[0])) return argError(ck, a[0], call.name, "the input must be a number (ANY_NUM)");
    const Type* t = commonTypeOf(ck, a, call.loc, call.name);
    std::vector<Checked> x = a;
    if (!t || !coerceAll(ck, x, t, call.name)) return ck.bad(call.loc);
    Rep rep = sema::repOf(t);
    exec::Expr* n = sema::isReal(t->kind) ? sema::makeRealByRep<AbsF>(ck.pool(), rep, x[0].node)
                                          : sema::makeIntByRep<AbsI>(ck.pool(), rep, x[0].node);
    return makeResult(ck, n, t, call, a);
}

Checked checkAtan2(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"Y|IN1"}, {"X|IN2"}}, a)) return ck.bad(call.loc);
    for (const auto& v : a)
        if (!isNumArg(v)) return argError(ck, v, call.name, "the inputs must be numbers (ANY_NUM)");
    const Type* ty = realTypeFor(ck, a[0]);
    const Type* tx = realTypeFor(ck, a[1]);
    const Type* t = (ty->kind == TK::LReal || tx->kind == TK::LReal) ? ck.types().elementary(TK::LReal) : ty;
    Checked y = ck.convert(a[0], t, a[0].loc), x = ck.convert(a[1], t, a[1].loc);
    if (!y.ok || !x.ok) return ck.bad(call.loc);
    return makeResult(ck, sema::makeRealByRep<Atan2Node>(ck.pool(), sema::repOf(t), y.node, x.node), t, call, a);
}

Checked checkExpt(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN1"}, {"IN2"}}, a)) return ck.bad(call.loc);
    for (const auto& v : a)
        if (!isNumArg(v)) return argError(ck, v, call.name, "the inputs must be numbers (ANY_NUM)");
    const Type* t = realTypeFor(ck, a[0]);
    Checked base = ck.convert(a[0], t, a[0].loc);
    if (!base.ok) return base;
    bool intExponent = isIntegerArg(a[1]);
    Checked e = intExponent ? ck.settle(a[1]) : ck.convert(a[1], t, a[1].loc);
    if (!e.ok) return e;
    exec::Expr* n = sema::repOf(t) == Rep::F32 ? static_cast<exec::Expr*>(ck.pool().make<ExptNode<float>>(base.node, e.node, intExponent))
                                                : ck.pool().make<ExptNode<double>>(base.node, e.node, intExponent);
    return makeResult(ck, n, t, call, a);
}

enum class Arith { Add, Sub, Mul, Div, Mod };

bool hasTimeOrDate(const std::vector<Checked>& a) {
    for (const auto& v : a)
        if (!v.untypedInt && !v.untypedReal && (sema::isTimeLike(v.type->kind) || sema::isDateLike(v.type->kind))) return true;
    return false;
}

Checked checkArith(Checker& ck, CallArgs& call, Arith op) {
    std::vector<Checked> a;
    bool extensible = op == Arith::Add || op == Arith::Mul;
    bool bound = extensible ? bindExtensible(ck, call, {}, "IN", 1, 2, a) : bindFixed(ck, call, {{"IN1"}, {"IN2"}}, a);
    if (!bound) return ck.bad(call.loc);
    if (hasTimeOrDate(a)) {
        if (a.size() != 2) {
            ck.error(diag::E0301, call.loc, fmt::format("{} of durations or dates takes exactly two inputs", call.name));
            return ck.bad(call.loc);
        }
        TimeOp top = op == Arith::Add ? TimeOp::Add : op == Arith::Sub ? TimeOp::Sub : op == Arith::Mul ? TimeOp::Mul : TimeOp::Div;
        if (op == Arith::Mod) {
            ck.error(diag::E0202, call.loc, "MOD is not defined for durations or dates");
            return ck.bad(call.loc);
        }
        return timeArithmetic(ck, call, top, a[0], a[1]);
    }
    for (const auto& v : a)
        if (!isNumArg(v) && !isBitArg(v))
            return argError(ck, v, call.name, "the inputs must be numbers (ANY_NUM), durations or dates");
    const Type* t = commonTypeOf(ck, a, call.loc, call.name);
    std::vector<Checked> x = a;
    if (!t || !coerceAll(ck, x, t, call.name)) return ck.bad(call.loc);
    bool real = sema::isReal(t->kind);
    if (op == Arith::Mod && real) {
        ck.error(diag::E0202, call.loc, fmt::format("MOD needs integers, not {}", sema::typeName(t)));
        return ck.bad(call.loc);
    }
    Rep rep = sema::repOf(t);
    auto& pool = ck.pool();
    exec::Expr* n = x[0].node;
    for (size_t k = 1; k < x.size(); ++k) {
        exec::Expr* r = x[k].node;
        switch (op) {
            case Arith::Add: n = real ? sema::makeRealByRep<exec::AddF>(pool, rep, n, r) : sema::makeIntByRep<exec::AddI>(pool, rep, n, r); break;
            case Arith::Mul: n = real ? sema::makeRealByRep<exec::MulF>(pool, rep, n, r) : sema::makeIntByRep<exec::MulI>(pool, rep, n, r); break;
            case Arith::Sub: n = real ? sema::makeRealByRep<exec::SubF>(pool, rep, n, r) : sema::makeIntByRep<exec::SubI>(pool, rep, n, r); break;
            case Arith::Div:
                n = real ? sema::makeRealByRep<exec::DivF>(pool, rep, n, r) : sema::makeIntByRep<exec::DivI>(pool, rep, n, r, ck.site(call.loc));
                break;
            case Arith::Mod: n = sema::makeIntByRep<exec::ModI>(pool, rep, n, r, ck.site(call.loc)); break;
        }
        n->type = t;
    }
    // An integer division by a constant zero keeps its runtime DIV_BY_ZERO.
    bool fold = !((op == Arith::Div || op == Arith::Mod) && !real && x[1].isConst && x[1].constInt == 0);
    return makeResult(ck, n, t, call, a, fold);
}

Checked checkMove(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
    Checked r = a[0];
    r.isPlace = false;
    r.readOnly = false;
    r.var = nullptr;
    r.direct = Checked::Direct::None;
    r.loc = call.loc;
    return r;
}

// The type a shifted value keeps. A literal takes the smallest bit string
// holding it (CODESYS: "if the input is a constant the smallest possible data type is used").
const Type* shiftType(Checker& ck, const Checked& in) {
    if (!in.untypedInt) return in.type;
    int64_t v = in.constInt;
    if (v < 0) return ck.types().elementary(v >= INT8_MIN ? TK::SInt : v >= INT16_MIN ? TK::Int : v >= INT32_MIN ? TK::DInt : TK::LInt);
    return ck.types().elementary(v <= 0xFF ? TK::Byte : v <= 0xFFFF ? TK::Word : v <= 0xFFFFFFFFll ? TK::DWord : TK::LWord);
}

void addShift(Checker& ck, const char* name, ShiftFn fn) {
    struct ShiftData { ShiftFn fn; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [fn] = self.data<ShiftData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN"}, {"N"}}, a)) return ck.bad(call.loc);
        if (!(isBitArg(a[0]) || isIntegerArg(a[0])))
            return argError(ck, a[0], call.name, "IN must be a bit string or an integer");
        if (!(isIntegerArg(a[1]) || isBitArg(a[1]))) return argError(ck, a[1], call.name, "N must be an integer");
        const Type* t = shiftType(ck, a[0]);
        Checked in = ck.coerce(a[0], t, a[0].loc, "IN");
        Checked n = ck.settle(a[1]);
        if (!in.ok) return in;
        std::vector<Checked> args = {in, n};
        return makeResult(ck, makeShift(ck.pool(), sema::repOf(t), fn, in.node, n.node), t, call, args);
    }, ShiftData{fn}));
}

enum class Logic { And, Or, Xor };

Checked checkLogic(Checker& ck, CallArgs& call, Logic op) {
    std::vector<Checked> a;
    if (!bindExtensible(ck, call, {}, "IN", 1, 2, a)) return ck.bad(call.loc);
    bool anyBool = false, allBool = true;
    for (const auto& v : a) {
        bool b = !v.untypedInt && v.type->kind == TK::Bool;
        anyBool = anyBool || b;
        allBool = allBool && b;
        if (!b && !isBitArg(v) && !isIntegerArg(v)) return argError(ck, v, call.name, "the inputs must be BOOL or bit strings");
    }
    if (anyBool && !allBool) {
        ck.error(diag::E0202, call.loc, fmt::format("{}: the inputs must be all BOOL or all bit strings", call.name));
        return ck.bad(call.loc);
    }
    const Type* t = commonTypeOf(ck, a, call.loc, call.name);
    std::vector<Checked> x = a;
    if (!t || !coerceAll(ck, x, t, call.name)) return ck.bad(call.loc);
    Rep rep = sema::repOf(t);
    exec::Expr* n = x[0].node;
    for (size_t k = 1; k < x.size(); ++k) {
        switch (op) {
            case Logic::And: n = sema::makeIntByRep<exec::AndI>(ck.pool(), rep, n, x[k].node); break;
            case Logic::Or: n = sema::makeIntByRep<exec::OrI>(ck.pool(), rep, n, x[k].node); break;
            case Logic::Xor: n = sema::makeIntByRep<exec::XorI>(ck.pool(), rep, n, x[k].node); break;
        }
        n->type = t;
    }
    return makeResult(ck, n, t, call, a);
}

Checked checkNot(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
    if (!a[0].untypedInt && a[0].type->kind == TK::Bool)
        return makeResult(ck, ck.pool().make<exec::NotBool>(a[0].node), a[0].type, call, a);
    if (!isBitArg(a[0]) && !isIntegerArg(a[0])) return argError(ck, a[0], call.name, "the input must be BOOL or a bit string");
    const Type* t = shiftType(ck, a[0]);
    Checked in = ck.coerce(a[0], t, a[0].loc, "IN");
    if (!in.ok) return in;
    std::vector<Checked> args = {in};
    return makeResult(ck, sema::makeIntByRep<exec::NotBits>(ck.pool(), sema::repOf(t), in.node), t, call, args);
}

}  // namespace

void registerNumeric(Checker& ck) {
    ck.addBuiltin("ABS", checkAbs);
    addMath(ck, "SQRT", MathFn::Sqrt);
    addMath(ck, "LN", MathFn::Ln);
    addMath(ck, "LOG", MathFn::Log);
    addMath(ck, "EXP", MathFn::Exp);
    addMath(ck, "SIN", MathFn::Sin);
    addMath(ck, "COS", MathFn::Cos);
    addMath(ck, "TAN", MathFn::Tan);
    addMath(ck, "ASIN", MathFn::Asin);
    addMath(ck, "ACOS", MathFn::Acos);
    addMath(ck, "ATAN", MathFn::Atan);
    ck.addBuiltin("ATAN2", checkAtan2);
    ck.addBuiltin("EXPT", checkExpt);
    ck.addBuiltin("ADD", [](Checker& ck, CallArgs& c) { return checkArith(ck, c, Arith::Add); });
    ck.addBuiltin("SUB", [](Checker& ck, CallArgs& c) { return checkArith(ck, c, Arith::Sub); });
    ck.addBuiltin("MUL", [](Checker& ck, CallArgs& c) { return checkArith(ck, c, Arith::Mul); });
    ck.addBuiltin("DIV", [](Checker& ck, CallArgs& c) { return checkArith(ck, c, Arith::Div); });
    ck.addBuiltin("MOD", [](Checker& ck, CallArgs& c) { return checkArith(ck, c, Arith::Mod); });
    ck.addBuiltin("MOVE", checkMove);
    addShift(ck, "SHL", ShiftFn::Shl);
    addShift(ck, "SHR", ShiftFn::Shr);
    addShift(ck, "ROL", ShiftFn::Rol);
    addShift(ck, "ROR", ShiftFn::Ror);
    ck.addBuiltin("AND", [](Checker& ck, CallArgs& c) { return checkLogic(ck, c, Logic::And); });
    ck.addBuiltin("OR", [](Checker& ck, CallArgs& c) { return checkLogic(ck, c, Logic::Or); });
    ck.addBuiltin("XOR", [](Checker& ck, CallArgs& c) { return checkLogic(ck, c, Logic::Xor); });
    ck.addBuiltin("NOT", checkNot);
}

}  // namespace strun::stdlib::bind
