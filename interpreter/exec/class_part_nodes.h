// A derived class instance assigned to (or passed for) a variable of its
// base class (SIMATIC AX, IEC 61131-3 Ed.3; decision 0392): the base part of
// the instance is copied, the target keeps its own class. Every instance
// starts with the pointer to its class (checker_declare.cpp), which the
// copy leaves alone: the target's methods stay its own class's.
#pragma once

#include <cstring>

#include "interpreter/exec/stmt_nodes.h"

namespace strun::exec {

// The source instance, seen as its base class: only marks the value for the
// store (Checker::storeTo); reads its address like the instance itself.
struct ClassPartOf final : Expr {
    Expr* instance;
    explicit ClassPartOf(Expr* i) : instance(i) {}
    uint8_t* addr(Ctx& c) override { return instance->addr(c); }
};

// place := the base part of value: the bytes of the base class after the
// class pointer.
struct AssignClassPart final : Stmt {
    Expr* place;
    Expr* value;
    uint32_t from, size;
    AssignClassPart(Expr* p, Expr* v, uint32_t f, uint32_t n) : place(p), value(v), from(f), size(n) {}
    Flow exec(Ctx& c) override {
        const uint8_t* src = value->addr(c);
        uint8_t* dst = place->addr(c);
        if (src != dst && size > from) std::memmove(dst + from, src + from, size - from);
        return Flow::Next;
    }
};

}  // namespace strun::exec
