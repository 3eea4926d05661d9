// The operands a fused node can read itself: a variable of the instance or
// frame, a constant (decision 0151), an element a[i + k] of an array
// variable (decision 0262). Shared by the fusion builders.
#pragma once

#include "interpreter/exec/fused_nodes.h"

namespace strun::sema::fusion {

using exec::BaseKind;

enum class LeafKind : uint8_t { None, Self, Frame, Const };

template <class T>
struct Leaf {
    LeafKind kind = LeafKind::None;
    uint32_t off = 0;
    T k{};
    bool isVar() const { return kind == LeafKind::Self || kind == LeafKind::Frame; }
};

// f(OpVar<T, Self or Frame>) for a variable leaf.
template <class T, class F>
auto withVar(const Leaf<T>& v, F&& f) {
    if (v.kind == LeafKind::Self) return f(exec::OpVar<T, BaseKind::Self>{v.off});
    return f(exec::OpVar<T, BaseKind::Frame>{v.off});
}

// A variable node of storage type exactly T in the instance or frame: the
// fused node loads it as the variable node would.
template <class T>
Leaf<T> leafOf(exec::Expr* e) {
    if (!e) return {};
    if (auto* v = exec::nodeCast<exec::VarNode<T, BaseKind::Self>>(e)) return {LeafKind::Self, v->off, T{}};
    if (auto* v = exec::nodeCast<exec::VarNode<T, BaseKind::Frame>>(e)) return {LeafKind::Frame, v->off, T{}};
    return {};
}

namespace detail {
template <class T, BaseKind B, exec::IndexFrom IX>
bool elemAs(exec::Expr* e, exec::OpElem<T>& out) {
    auto* n = exec::nodeCast<exec::Index1Var<T, B, IX>>(e);
    if (!n) return false;
    out.base = exec::ctxBase<B>();
    out.off = n->off;
    out.indexBase = IX == exec::IndexFrom::Self32 ? &exec::Ctx::self : &exec::Ctx::frame;
    out.indexOff = n->indexOff;
    out.indexAdd = n->indexAdd;
    out.lo = n->lo;
    out.count = n->count;
    out.stride = n->stride;
    out.site = &n->site;  // the node stays in the pool
    return true;
}
}  // namespace detail

// An element node of storage type exactly T of an array variable of the
// instance or frame whose subscript is a DINT variable of the instance or
// frame plus a constant (fuseIndex1's Index1Var): the operand that reads it.
template <class T>
bool elemOf(exec::Expr* e, exec::OpElem<T>& out) {
    using exec::IndexFrom;
    return e && (detail::elemAs<T, BaseKind::Self, IndexFrom::Self32>(e, out) || detail::elemAs<T, BaseKind::Self, IndexFrom::Frame32>(e, out) ||
                 detail::elemAs<T, BaseKind::Frame, IndexFrom::Self32>(e, out) || detail::elemAs<T, BaseKind::Frame, IndexFrom::Frame32>(e, out));
}

}  // namespace strun::sema::fusion
