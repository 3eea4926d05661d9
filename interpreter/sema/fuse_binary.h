// Builds FusedBin nodes (decisions 0151, 0262). The templates instantiate every
// operator for every operand shape, with the IF, WHILE, assignment and
// conversion forms each of them can become; the work is split by computation
// type over four files.
#pragma once

#include <optional>

#include "interpreter/exec/fused_nodes.h"
#include "interpreter/sema/fuse_leaf.h"

namespace strun::sema::fusion {

using exec::BinOp;

// One file per computation type (fuse_binary_dint.cpp, _lint, _real,
// _lreal), so that the two cores of a build share the work; k: the right
// constant when b is null.
exec::Expr* fuseBinaryDint(exec::NodePool& pool, BinOp op, exec::Expr* a, exec::Expr* b, int64_t k);
exec::Expr* fuseBinaryLint(exec::NodePool& pool, BinOp op, exec::Expr* a, exec::Expr* b, int64_t k);
exec::Expr* fuseBinaryReal(exec::NodePool& pool, BinOp op, exec::Expr* a, exec::Expr* b, double k);
exec::Expr* fuseBinaryLreal(exec::NodePool& pool, BinOp op, exec::Expr* a, exec::Expr* b, double k);

template <class T, BinOp OP, class L, class R>
exec::Expr* make(exec::NodePool& pool, L l, R r) {
    return pool.make<exec::FusedBin<T, OP, L, R>>(l, r);
}

// A computed operand worth reading through one virtual call inside a fused
// node with a constant (3 * x + 1, x MOD 2 = 0, a[i] > 0): a fused operator
// or an array element. Plain variables of other widths keep the general
// nodes (AddIK, CmpIK), which the statement builders recognise. An integer
// computation also takes the general integer operators (`(a + b) MOD k`,
// decision 0486): the fused node is then the one the store or the IF can
// absorb.
template <class T>
bool computedOperand(exec::Expr* e) {
    if constexpr (!std::is_floating_point_v<T>)
        if (exec::nodeCast<exec::IntOperator>(e)) return true;
    return exec::nodeCast<exec::FusedArith>(e) || exec::nodeCast<exec::Index1Target>(e);
}

// The constant value of `e` as T, when it is a constant node.
template <class T>
std::optional<T> constOf(exec::Expr* e) {
    exec::Ctx none;  // constants read nothing from the context
    if (auto* ci = exec::nodeCast<exec::ConstInt>(e)) return std::is_floating_point_v<T> ? static_cast<T>(ci->f(none)) : static_cast<T>(ci->i(none));
    if (auto* cr = exec::nodeCast<exec::ConstReal>(e); cr && std::is_floating_point_v<T>) return static_cast<T>(cr->f(none));
    return std::nullopt;
}

// A fused node with a constant right operand; a divisor +-2^k divides by
// shifts (decision 0490).
template <class T, BinOp OP, class L>
exec::Expr* makeWithConst(exec::NodePool& pool, L l, T k) {
    if constexpr ((OP == BinOp::Div || OP == BinOp::Mod) && !std::is_floating_point_v<T>)
        if (exec::PowerOfTwoDivisor<T>::fits(k)) return make<T, OP>(pool, l, exec::OpPow2Divisor<T>{exec::PowerOfTwoDivisor<T>(k)});
    return make<T, OP>(pool, l, exec::OpConst<T>{k});
}

// The operand shapes (decision 0262): a variable with a variable, a
// constant or any node; any node with a variable; a computed node with a
// constant; for comparisons, two array elements (a[j] > a[j + 1]).
template <class T, BinOp OP>
exec::Expr* fuseTyped(exec::NodePool& pool, exec::Expr* a, exec::Expr* b, T k) {
    Leaf<T> la = leafOf<T>(a);
    Leaf<T> rb = b ? leafOf<T>(b) : Leaf<T>{LeafKind::Const, 0, k};
    constexpr bool divides = OP == BinOp::Div || OP == BinOp::Mod;
    if (divides && !std::is_floating_point_v<T> && rb.kind != LeafKind::Const) return nullptr;
    if (la.isVar())
        return withVar(la, [&](auto lv) -> exec::Expr* {
            if (rb.isVar()) return withVar(rb, [&](auto rv) { return make<T, OP>(pool, lv, rv); });
            if (rb.kind == LeafKind::Const) return makeWithConst<T, OP>(pool, lv, rb.k);
            return make<T, OP>(pool, lv, exec::OpNode<T>{b});
        });
    // k OP x with a commutative OP (3 * x, 0 = x): x OP k, the constant inline.
    constexpr bool commutes = OP == BinOp::Add || OP == BinOp::Mul || OP == BinOp::And || OP == BinOp::Or || OP == BinOp::Xor ||
                              OP == BinOp::Eq || OP == BinOp::Ne;
    if constexpr (commutes) {
        if (b && (rb.isVar() || computedOperand<T>(b)))
            if (std::optional<T> ka = constOf<T>(a)) {
                if (rb.isVar()) return withVar(rb, [&](auto rv) { return make<T, OP>(pool, rv, exec::OpConst<T>{*ka}); });
                return make<T, OP>(pool, exec::OpNode<T>{b}, exec::OpConst<T>{*ka});
            }
    }
    // k < x with an ordered comparison (an inlined body's `IF lo > value`
    // once `lo` reads as its constant argument, decision 0403): x > k, the
    // same test (NaN included) with the constant inline.
    constexpr bool ordered = OP == BinOp::Lt || OP == BinOp::Gt || OP == BinOp::Le || OP == BinOp::Ge;
    if constexpr (ordered) {
        constexpr BinOp mirrored = OP == BinOp::Lt ? BinOp::Gt : OP == BinOp::Gt ? BinOp::Lt : OP == BinOp::Le ? BinOp::Ge : BinOp::Le;
        if (b && (rb.isVar() || computedOperand<T>(b)))
            if (std::optional<T> ka = constOf<T>(a)) {
                if (rb.isVar()) return withVar(rb, [&](auto rv) { return make<T, mirrored>(pool, rv, exec::OpConst<T>{*ka}); });
                return make<T, mirrored>(pool, exec::OpNode<T>{b}, exec::OpConst<T>{*ka});
            }
    }
    if constexpr (isCompare(OP)) {
        exec::OpElem<T> ea, eb;
        if (b && elemOf<T>(a, ea) && elemOf<T>(b, eb)) return make<T, OP>(pool, ea, eb);
    }
    exec::OpNode<T> l{a};
    if (rb.isVar()) return withVar(rb, [&](auto rv) { return make<T, OP>(pool, l, rv); });
    if (rb.kind == LeafKind::Const && computedOperand<T>(a)) return makeWithConst<T, OP>(pool, l, rb.k);
    return nullptr;
}

template <class T>
exec::Expr* fuseOp(exec::NodePool& pool, BinOp op, exec::Expr* a, exec::Expr* b, T k) {
    switch (op) {
        case BinOp::Add: return fuseTyped<T, BinOp::Add>(pool, a, b, k);
        case BinOp::Sub: return fuseTyped<T, BinOp::Sub>(pool, a, b, k);
        case BinOp::Mul: return fuseTyped<T, BinOp::Mul>(pool, a, b, k);
        case BinOp::Div: return fuseTyped<T, BinOp::Div>(pool, a, b, k);
        case BinOp::Eq: return fuseTyped<T, BinOp::Eq>(pool, a, b, k);
        case BinOp::Ne: return fuseTyped<T, BinOp::Ne>(pool, a, b, k);
        case BinOp::Lt: return fuseTyped<T, BinOp::Lt>(pool, a, b, k);
        case BinOp::Le: return fuseTyped<T, BinOp::Le>(pool, a, b, k);
        case BinOp::Gt: return fuseTyped<T, BinOp::Gt>(pool, a, b, k);
        case BinOp::Ge: return fuseTyped<T, BinOp::Ge>(pool, a, b, k);
        default: break;
    }
    if constexpr (!std::is_floating_point_v<T>) {
        switch (op) {
            case BinOp::Mod: return fuseTyped<T, BinOp::Mod>(pool, a, b, k);
            case BinOp::And: return fuseTyped<T, BinOp::And>(pool, a, b, k);
            case BinOp::Or: return fuseTyped<T, BinOp::Or>(pool, a, b, k);
            case BinOp::Xor: return fuseTyped<T, BinOp::Xor>(pool, a, b, k);
            default: break;
        }
    }
    return nullptr;
}

}  // namespace strun::sema::fusion
