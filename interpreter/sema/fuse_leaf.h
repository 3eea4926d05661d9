// The operands a fused node can read itself: a variable of the instance or
// frame, or a constant (decision 0151). Shared by the fusion builders.
#pragma once

#include "interpreter/exec/value_nodes.h"

namespace strun::sema::fusion {

using exec::BaseKind;

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

}  // namespace strun::sema::fusion
