// Builds FusedBin nodes (decision 0151). The templates instantiate every
// operator for every operand shape, with the IF, WHILE and assignment forms
// each of them can become, so the work is split by computation type over
// fuse_binary_integer.cpp and fuse_binary_real.cpp (one compiler process
// each, about half the memory of one).
#pragma once

#include <optional>

#include "interpreter/exec/fused_nodes.h"
#include "interpreter/sema/fuse_leaf.h"

namespace strun::sema::fusion {

using exec::BinOp;

// DINT (wide = false) or LINT computations; kInt: the right constant when b is null.
exec::Expr* fuseBinaryInteger(exec::NodePool& pool, BinOp op, bool wide, exec::Expr* a, exec::Expr* b, int64_t kInt);
// REAL (wide = false) or LREAL computations.
exec::Expr* fuseBinaryReal(exec::NodePool& pool, BinOp op, bool wide, exec::Expr* a, exec::Expr* b, double kReal);

template <class T, BinOp OP, class L, class R>
exec::Expr* make(exec::NodePool& pool, L l, R r) {
    return pool.make<exec::FusedBin<T, OP, L, R>>(l, r);
}

// The right operand of every shape, for a left operand that is a leaf.
template <class T, BinOp OP, class L>
exec::Expr* withRight(exec::NodePool& pool, L l, const Leaf<T>& rb, exec::Expr* b) {
    switch (rb.kind) {
        case LeafKind::Self: return make<T, OP>(pool, l, exec::OpVar<T, BaseKind::Self>{rb.off});
        case LeafKind::Frame: return make<T, OP>(pool, l, exec::OpVar<T, BaseKind::Frame>{rb.off});
        case LeafKind::Const: return make<T, OP>(pool, l, exec::OpConst<T>{rb.k});
        default: return make<T, OP>(pool, l, exec::OpNode<T>{b});
    }
}

template <class T, BinOp OP>
exec::Expr* fuseTyped(exec::NodePool& pool, exec::Expr* a, exec::Expr* b, T k) {
    Leaf<T> la = leafOf<T>(a);
    Leaf<T> rb = b ? leafOf<T>(b) : Leaf<T>{LeafKind::Const, 0, k};
    constexpr bool divides = OP == BinOp::Div || OP == BinOp::Mod;
    if (divides && !std::is_floating_point_v<T> && rb.kind != LeafKind::Const) return nullptr;
    switch (la.kind) {
        case LeafKind::Self: return withRight<T, OP>(pool, exec::OpVar<T, BaseKind::Self>{la.off}, rb, b);
        case LeafKind::Frame: return withRight<T, OP>(pool, exec::OpVar<T, BaseKind::Frame>{la.off}, rb, b);
        default: break;
    }
    // k OP x with a commutative OP (3 * x, 0 = x): x OP k, the constant inline.
    constexpr bool commutes = OP == BinOp::Add || OP == BinOp::Mul || OP == BinOp::And || OP == BinOp::Or || OP == BinOp::Xor ||
                              OP == BinOp::Eq || OP == BinOp::Ne;
    if constexpr (commutes) {
        if (rb.kind == LeafKind::Self || rb.kind == LeafKind::Frame) {
            exec::Ctx none;  // constants read nothing from the context
            std::optional<T> ka;
            if (auto* ci = dynamic_cast<exec::ConstInt*>(a)) ka = std::is_floating_point_v<T> ? static_cast<T>(ci->f(none)) : static_cast<T>(ci->i(none));
            else if (auto* cr = dynamic_cast<exec::ConstReal*>(a); cr && std::is_floating_point_v<T>) ka = static_cast<T>(cr->f(none));
            if (ka) {
                exec::OpConst<T> kk{*ka};
                if (rb.kind == LeafKind::Self) return make<T, OP>(pool, exec::OpVar<T, BaseKind::Self>{rb.off}, kk);
                return make<T, OP>(pool, exec::OpVar<T, BaseKind::Frame>{rb.off}, kk);
            }
        }
    }
    // A general left operand: worth fusing only when the right one is a variable
    // (node op constant already has its own nodes).
    exec::OpNode<T> l{a};
    switch (rb.kind) {
        case LeafKind::Self: return make<T, OP>(pool, l, exec::OpVar<T, BaseKind::Self>{rb.off});
        case LeafKind::Frame: return make<T, OP>(pool, l, exec::OpVar<T, BaseKind::Frame>{rb.off});
        default: return nullptr;
    }
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
