// Recognises the operands a fused node can read itself (decision 0151).
#include "interpreter/sema/fuse.h"

namespace strun::sema {

using exec::BaseKind;
using exec::BinOp;

namespace {

enum class LeafKind : uint8_t { None, Self, Frame, Const };

template <class T>
struct Leaf {
    LeafKind kind = LeafKind::None;
    uint32_t off = 0;
    T k{};
};

// A variable node of storage type exactly T in the instance or frame: the
// fused node loads it as the variable node would.
template <class T>
Leaf<T> leafOf(exec::Expr* e) {
    if (!e) return {};
    if (auto* v = dynamic_cast<exec::VarNode<T, BaseKind::Self>*>(e)) return {LeafKind::Self, v->off, T{}};
    if (auto* v = dynamic_cast<exec::VarNode<T, BaseKind::Frame>*>(e)) return {LeafKind::Frame, v->off, T{}};
    return {};
}

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

template <class T, BaseKind B>
exec::Stmt* addConst(exec::NodePool& pool, uint32_t off, exec::Expr* value) {
    // The value as the checker builds it: x + k (AddIK / SubIK over the
    // variable node, in the computation type of T) or, for DINT/LINT
    // variables, the fused form of the same.
    using C = std::conditional_t<(sizeof(T) < 4), int32_t, T>;  // arithmeticRep
    using V = exec::VarNode<T, B>;
    auto same = [&](exec::Expr* e) {
        auto* v = dynamic_cast<V*>(e);
        return v && v->off == off;
    };
    if (auto* n = dynamic_cast<exec::AddIK<C>*>(value); n && same(n->l)) return pool.make<exec::AddConstLocal<T, B>>(off, static_cast<int64_t>(n->b));
    if (auto* n = dynamic_cast<exec::SubIK<C>*>(value); n && same(n->l))
        return pool.make<exec::AddConstLocal<T, B>>(off, static_cast<int64_t>(0 - static_cast<uint64_t>(static_cast<int64_t>(n->b))));
    if constexpr (std::is_same_v<C, T>) {
        using OV = exec::OpVar<T, B>;
        using K = exec::OpConst<T>;
        if (auto* n = dynamic_cast<exec::FusedBin<T, BinOp::Add, OV, K>*>(value); n && n->l.off == off)
            return pool.make<exec::AddConstLocal<T, B>>(off, static_cast<int64_t>(n->r.k));
        if (auto* n = dynamic_cast<exec::FusedBin<T, BinOp::Sub, OV, K>*>(value); n && n->l.off == off)
            return pool.make<exec::AddConstLocal<T, B>>(off, static_cast<int64_t>(0 - static_cast<uint64_t>(static_cast<int64_t>(n->r.k))));
    }
    return nullptr;
}

template <BaseKind B>
exec::Stmt* addConstByRep(exec::NodePool& pool, Rep rep, uint32_t off, exec::Expr* value) {
    switch (rep) {
        case Rep::I8: return addConst<int8_t, B>(pool, off, value);
        case Rep::I16: return addConst<int16_t, B>(pool, off, value);
        case Rep::I32: return addConst<int32_t, B>(pool, off, value);
        case Rep::I64: return addConst<int64_t, B>(pool, off, value);
        default: return nullptr;  // unsigned: rare as counters, left to the general nodes
    }
}

template <class T>
exec::Expr* realToInt(exec::NodePool& pool, exec::Expr* value, int bits, bool isSigned, bool truncate) {
    if (truncate) return pool.make<exec::ConvRealIntT<T, true>>(value, bits, isSigned);
    return pool.make<exec::ConvRealIntT<T, false>>(value, bits, isSigned);
}

}  // namespace

exec::Expr* fuseBinary(exec::NodePool& pool, BinOp op, Rep rep, exec::Expr* a, exec::Expr* b, int64_t kInt, double kReal) {
    switch (rep) {
        case Rep::I32: return fuseOp<int32_t>(pool, op, a, b, static_cast<int32_t>(kInt));
        case Rep::I64: return fuseOp<int64_t>(pool, op, a, b, kInt);
        case Rep::F32: return fuseOp<float>(pool, op, a, b, static_cast<float>(kReal));
        case Rep::F64: return fuseOp<double>(pool, op, a, b, kReal);
        default: return nullptr;
    }
}

exec::Stmt* fuseAddConstLocal(exec::NodePool& pool, Rep rep, bool frame, uint32_t off, exec::Expr* value) {
    return frame ? addConstByRep<BaseKind::Frame>(pool, rep, off, value) : addConstByRep<BaseKind::Self>(pool, rep, off, value);
}

exec::Expr* fuseRealToInt(exec::NodePool& pool, exec::Expr* value, int bits, bool isSigned, bool truncate) {
    switch (bits) {
        case 8: return isSigned ? realToInt<int8_t>(pool, value, bits, isSigned, truncate) : realToInt<uint8_t>(pool, value, bits, isSigned, truncate);
        case 16: return isSigned ? realToInt<int16_t>(pool, value, bits, isSigned, truncate) : realToInt<uint16_t>(pool, value, bits, isSigned, truncate);
        case 32: return isSigned ? realToInt<int32_t>(pool, value, bits, isSigned, truncate) : realToInt<uint32_t>(pool, value, bits, isSigned, truncate);
        case 64: return isSigned ? realToInt<int64_t>(pool, value, bits, isSigned, truncate) : realToInt<uint64_t>(pool, value, bits, isSigned, truncate);
        default: return nullptr;
    }
}

}  // namespace strun::sema
