// t := a[i + k1]; a[i + k1] := a[i + k2]; a[i + k2] := t as one node
// (decision 0379): the swap of two array elements through a temporary, the
// inner step of every exchange sort. The three statements stay three
// statements to the machine: the node is the first of them (its line and
// column), ticks before the second and the third with `c.stmt` set to
// them, exactly as the Block would, and runs the original statements
// when a subscript is out of range, so that every fault is reported where
// and when the unfused statements report it. With both subscripts in range
// each element's address is computed once instead of twice.
#pragma once

#include "interpreter/exec/fused_nodes.h"

namespace strun::exec {

template <class T>
struct SwapElems final : Stmt {
    OpElem<T> x;           // a[i + k1]: read into t, then overwritten
    OpElem<T> y;           // a[i + k2]: copied into a[i + k1], then written from t
    CtxBase tmpBase;       // t: a variable of the instance or frame
    uint32_t tmpOff;
    Stmt* first;           // the three statements, for the slow path
    Stmt* second;
    Stmt* third;
    SwapElems(const OpElem<T>& a, const OpElem<T>& b, CtxBase tb, uint32_t to, Stmt* s1, Stmt* s2, Stmt* s3)
        : x(a), y(b), tmpBase(tb), tmpOff(to), first(s1), second(s2), third(s3) {}

    Flow exec(Ctx& c) override {
        const uint64_t kx = elemSlot(c, x);
        const uint64_t ky = elemSlot(c, y);
        if (__builtin_expect(kx >= static_cast<uint64_t>(x.count) || ky >= static_cast<uint64_t>(y.count), 0)) return asStatements(c);
        uint8_t* px = c.*x.base + x.off + kx * sizeof(T);  // the stride is sizeof(T) (checked when built)
        uint8_t* py = c.*y.base + y.off + ky * sizeof(T);
        const T v = loadAs<T>(px);
        storeAs<T>(c.*tmpBase + tmpOff, v);
        c.stmt = second;
        if (tickAborts(c)) return Flow::Abort;
        storeAs<T>(px, loadAs<T>(py));
        c.stmt = third;
        if (tickAborts(c)) return Flow::Abort;
        storeAs<T>(py, v);  // t is no element and no subscript (checked when built): still v
        return Flow::Next;
    }

private:
    // The element's position from the first (0-based, as OpElem::get
    // computes it); count or more when the subscript is out of range.
    [[gnu::always_inline]] static uint64_t elemSlot(Ctx& c, const OpElem<T>& e) {
        return static_cast<uint64_t>(e.subscript(c)) - static_cast<uint64_t>(e.lo);
    }
    // A subscript out of range: the three statements as the Block runs them
    // (the first is already ticked), each reporting its own fault.
    [[gnu::noinline]] Flow asStatements(Ctx& c) {
        Flow f = first->exec(c);
        if (f != Flow::Next) return f;
        f = runOne(c, second);
        if (f != Flow::Next) return f;
        return runOne(c, third);
    }
};

}  // namespace strun::exec
