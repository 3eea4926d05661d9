// CODESYS/TwinCAT dynamic memory: __NEW(T), __NEW(T, n), __DELETE(p)
// (docs/decisions/0300). The blocks live in rt::Heap, whose live blocks are
// regions of the memory map: every dereference of a pointer into them is
// checked like any other, and a wrong __DELETE is a NULL_POINTER fault.
// Nothing here runs unless a program calls __NEW or __DELETE.
#pragma once

#include "interpreter/exec/value_nodes.h"
#include "runtime/machine.h"

namespace strun::exec {

// __NEW(T [, n]): a zeroed block of n values of T (n = 1 without a count),
// each set to T's initial value; then, for T a function block, the start-up
// code of the new instance (run-time initialisers, FB_init), which reaches
// the instance through HeapCurrent. 0 when n < 1 or the heap is exhausted.
struct HeapNew final : Expr {
    const Type* elem;
    uint32_t elemSize;
    Expr* count = nullptr;  // null: one value
    Stmt* init = nullptr;   // start-up code of one new instance, or null
    uint8_t* current = nullptr;  // the instance `init` works on (nested __NEWs save and restore it)
    HeapNew(const Type* t, uint32_t size) : elem(t), elemSize(size) {}
    int64_t i(Ctx& c) override;
};

// The instance a HeapNew is initialising.
struct HeapCurrent final : Expr {
    HeapNew* owner;
    explicit HeapCurrent(HeapNew* o) : owner(o) {}
    uint8_t* addr(Ctx&) override { return owner->current; }
};

// __DELETE(p): releases the block p points to (after the instance's FB_exit,
// if any) and sets p to 0 when p is a variable. p = 0 does nothing. A pointer that is not the start
// of a live block (released already, inside a block, not from __NEW) is a
// NULL_POINTER fault and nothing is released.
struct HeapDelete final : Expr {
    Expr* pointer;  // place of the pointer variable, or (clears false) its value: `__DELETE(THIS)`
    bool clears;
    Stmt* exit = nullptr;  // FB_exit of the instance, or null
    Site site;
    uint8_t* current = nullptr;  // the instance `exit` works on
    HeapDelete(Expr* p, bool c, Site s) : pointer(p), clears(c), site(s) {}
    int64_t i(Ctx& c) override;
};

struct HeapDeleteCurrent final : Expr {
    HeapDelete* owner;
    explicit HeapDeleteCurrent(HeapDelete* o) : owner(o) {}
    uint8_t* addr(Ctx&) override { return owner->current; }
};

// Runs `body` with the instance `place` evaluates to as THIS (a run-time
// initialiser of a block created by __NEW; WithSelf takes a fixed address).
struct WithSelfAt final : Stmt {
    Expr* place;
    Stmt* body;
    WithSelfAt(Expr* p, Stmt* b) : place(p), body(b) {}
    Flow exec(Ctx& c) override {
        uint8_t* saved = c.self;
        c.self = place->addr(c);
        Flow f = body->exec(c);
        c.self = saved;
        return f;
    }
};

// For a fault message: what the memory at p is, if it belongs to the heap
// ("" if not): "memory released by __DELETE", "memory past the end of a __NEW block of N bytes".
std::string heapDescription(const rt::Heap& heap, const void* p);

}  // namespace strun::exec
