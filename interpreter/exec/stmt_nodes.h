// Statements of the resolved tree. Every statement boundary and every loop
// back-edge ticks the machine (virtual time, preemption, watchdog); a tick
// that asks for an abort unwinds with Flow::Abort to the task body.
#pragma once

#include <algorithm>
#include <limits>

#include "interpreter/exec/operator_nodes.h"

namespace strun::exec {

// The tick's slow path (the countdown ran out, decision 0265). While an
// activation is being aborted every tick stops it, without costing time:
// aborting expires the countdown (Machine::expireCountdown), so a statement
// that returned normally from an aborted call is followed by no other
// (decision 0267); Block does not test Ctx::aborting per statement.
[[gnu::noinline, gnu::cold]] inline bool tickExpired(Ctx& c) {
    if (c.aborting) {
        ++c.m->left;  // not a tick: the countdown stays expired
        return true;
    }
    if (c.m->countdownExpired()) {
        c.aborting = true;
        c.m->expireCountdown();
        return true;
    }
    return false;
}

inline bool tickAborts(Ctx& c) {
    if (__builtin_expect(--c.m->left < 0, 0)) return tickExpired(c);
    return false;
}

struct Block final : Stmt {
    std::vector<Stmt*> stmts;
    std::vector<std::pair<int, size_t>> labels;  // label id -> statement index
    // The walk keeps the list's bounds and the current statement in locals
    // (decision 0484): read through `stmts` after each statement's virtual
    // call, the compiler reloaded the vector's data and rebuilt the address
    // from an index, about 4 instructions more per statement.
    Flow exec(Ctx& c) override {
        Stmt* const* const first = stmts.data();
        Stmt* const* const end = first + stmts.size();
        for (Stmt* const* p = first; p != end;) {
            Stmt* s = *p++;
            c.stmt = s;
            if (tickAborts(c)) return Flow::Abort;
            Flow f = s->exec(c);
            if (__builtin_expect(f != Flow::Next, 0)) {
                if (f == Flow::Jump) {
                    auto it = std::find_if(labels.begin(), labels.end(), [&](auto& l) { return l.first == c.jumpLabel; });
                    if (it != labels.end()) { p = first + it->second; continue; }
                }
                return f;
            }
        }
        return Flow::Next;
    }
};

// One statement of a list, as Block::exec runs it: the tick before it, then
// the statement. Always inlined, as Body::run and runWhile (decision 0410).
[[gnu::always_inline]] inline Flow runOne(Ctx& c, Stmt* s) {
    c.stmt = s;
    if (tickAborts(c)) return Flow::Abort;
    return s->exec(c);
}

// The body of a loop, an IF branch or a CASE branch, held by its statement
// (decision 0266): up to two statements inline, run without the Block's call
// and vector walk; longer lists, and lists with labels (JMP targets), run
// as their Block. Built from a finished Block (the Block must not change
// afterwards). Every statement still ticks exactly as in Block::exec.
// The loops run their body through withShape (one loop per shape, decision
// 0498) and an inlined call (call_nodes.h) with runPinned, both always
// inlined into them (decision 0410):
// left to GCC's budget, the inlining of run() into a loop node
// (WhileCompare in sort) came and went with unrelated edits to the same
// unit (+-9 % instructions). The IF and CASE nodes keep run() (GCC's
// choice) or, IfCompare, runOutOfLine.
struct Body {
    Stmt* s0 = nullptr;
    Stmt* s1 = nullptr;
    Block* block = nullptr;  // set: run the Block itself
    Body() = default;
    Body(Block* b) {  // NOLINT: implicit, so that nodes built from a Block* keep their constructors
        if (!b) return;
        if (!b->labels.empty() || b->stmts.size() > 2) block = b;
        else {
            if (b->stmts.size() > 0) s0 = b->stmts[0];
            if (b->stmts.size() > 1) s1 = b->stmts[1];
        }
    }
    [[gnu::always_inline]] inline Flow runPinned(Ctx& c) const {
        if (block) return block->exec(c);
        return runInline(c);
    }
    // Calls loop(run), `run(c)` running this body with its shape resolved
    // once: a loop per shape, the statements in locals. Read through the
    // Body after each statement's call, the shape was tested and the
    // statements reloaded at every iteration (decisions 0497, 0498).
    template <class Loop>
    [[gnu::always_inline]] inline Flow withShape(Loop&& loop) const {
        if (block || !s0) return loop([b = *this](Ctx& k) { return b.runPinned(k); });
        Stmt* const a = s0;
        if (Stmt* const b = s1) return loop([a, b](Ctx& k) {
            Flow f = runOne(k, a);
            if (f != Flow::Next) return f;
            return runOne(k, b);
        });
        return loop([a](Ctx& k) { return runOne(k, a); });
    }
    // The statements held inline (none, one or two), as runPinned runs them:
    // an inlined call's body (call_nodes.h) and, through withShape, a loop's
    // empty body. run() tests the shape in another order, so that its last
    // call is a tail call; written that way here (measured while the loops
    // still ran their statements through it), GCC laid out the loops and
    // inlined call bodies worse (collatz +2.0 %, fb_io +1.3 %, bubble_sort
    // +1.3 % instructions).
    [[gnu::always_inline]] inline Flow runInline(Ctx& c) const {
        if (!s0) return Flow::Next;
        Flow f = runOne(c, s0);
        if (f != Flow::Next || !s1) return f;
        return runOne(c, s1);
    }
    // The IF and CASE bodies of more than two statements jump to the Block's
    // walk out of line: inlined (GCC did once the walk got shorter, decision
    // 0484), it made every IfCompare THEN save six registers (collatz +5.7 %).
    [[gnu::noinline]] static Flow runBlock(Block* b, Ctx& c) { return b->exec(c); }
    // A branch ends in a tail call of its last statement: a branch of one
    // saves no registers and pays no test after it (IfCompare's THEN
    // through runOutOfLine: 29 instructions -> 12, decision 0496).
    inline Flow run(Ctx& c) const {
        if (block) return runBlock(block, c);
        if (!s1) return s0 ? runOne(c, s0) : Flow::Next;
        Flow f = runOne(c, s0);
        if (f != Flow::Next) return f;
        return runOne(c, s1);
    }
    // Never inlined: IfCompare's THEN, tail-called, so that the IF node
    // saves no registers (decision 0410; inlined there once loops stopped
    // using GCC's budget: func_calls +2.8 %, state_machine +1.6 %).
    [[gnu::noinline]] Flow runOutOfLine(Ctx& c) const { return run(c); }
};

// place := value, for scalar storage T.
template <class T>
struct Assign final : Stmt {
    Expr* place;
    Expr* value;
    Assign(Expr* p, Expr* v) : place(p), value(v) {}
    Flow exec(Ctx& c) override {
        if constexpr (std::is_floating_point_v<T>) {
            T v = static_cast<T>(value->f(c));
            storeAs<T>(place->addr(c), v);
        } else if constexpr (std::is_same_v<T, bool>) {
            uint8_t v = value->i(c) != 0;
            storeAs<uint8_t>(place->addr(c), v);
        } else {
            T v = static_cast<T>(value->i(c));
            storeAs<T>(place->addr(c), v);
        }
        return Flow::Next;
    }
};

// Fast path: target in the current instance or frame.
template <class T, bool FRAME>
struct AssignLocal final : Stmt {
    uint32_t off;
    Expr* value;
    AssignLocal(uint32_t o, Expr* v) : off(o), value(v) {}
    Flow exec(Ctx& c) override {
        uint8_t* p = (FRAME ? c.frame : c.self) + off;
        if constexpr (std::is_floating_point_v<T>) storeAs<T>(p, static_cast<T>(value->f(c)));
        else if constexpr (std::is_same_v<T, bool>) storeAs<uint8_t>(p, value->i(c) != 0);
        else storeAs<T>(p, static_cast<T>(value->i(c)));
        return Flow::Next;
    }
};

// dst := src between two variables of the instance or frame of one storage
// type T (a block call's `out => v`, decision 0409): one virtual call, where
// AssignLocal paid a second for its value node. What it stores is what
// AssignLocal<T> stores from a variable of T: the same bytes; for a BOOL
// (T = bool, held in a byte) 0/1.
template <class T, bool DST_FRAME, bool SRC_FRAME>
struct CopyLocal final : Stmt {
    uint32_t dst, src;
    CopyLocal(uint32_t d, uint32_t s) : dst(d), src(s) {}
    Flow exec(Ctx& c) override {
        const uint8_t* s = (SRC_FRAME ? c.frame : c.self) + src;
        uint8_t* d = (DST_FRAME ? c.frame : c.self) + dst;
        if constexpr (std::is_same_v<T, bool>) storeAs<uint8_t>(d, loadAs<uint8_t>(s) != 0);
        else storeAs<T>(d, loadAs<T>(s));
        return Flow::Next;
    }
};

// One bit of a T-sized place.
template <class T>
struct AssignBit final : Stmt {
    Expr* base;
    int bit;
    Expr* value;
    AssignBit(Expr* b, int n, Expr* v) : base(b), bit(n), value(v) {}
    Flow exec(Ctx& c) override {
        bool v = value->i(c) != 0;
        uint8_t* p = base->addr(c);
        T w = loadAs<T>(p);
        T mask = static_cast<T>(T(1) << bit);
        w = v ? static_cast<T>(w | mask) : static_cast<T>(w & static_cast<T>(~mask));
        storeAs<T>(p, w);
        return Flow::Next;
    }
};

// Length of the NUL-terminated text at `s`, at most `max` code units.
template <class Ch>
inline size_t boundedLength(const Ch* s, size_t max) {
    if constexpr (sizeof(Ch) == 1) return strnlen(reinterpret_cast<const char*>(s), max);
    else {
        size_t k = 0;
        while (k < max && s[k] != 0) ++k;
        return k;
    }
}

// STRING / WSTRING assignment: copies up to the target's length, truncating.
template <class Ch>
struct AssignString final : Stmt {
    Expr* place;
    Expr* value;
    uint32_t maxLen;
    AssignString(Expr* p, Expr* v, uint32_t n) : place(p), value(v), maxLen(n) {}
    Flow exec(Ctx& c) override {
        const Ch* src = reinterpret_cast<const Ch*>(value->addr(c));
        Ch* dst = reinterpret_cast<Ch*>(place->addr(c));
        size_t k = boundedLength<Ch>(src, maxLen);
        // memmove semantics: source and target may overlap (s := s).
        if (src != dst) std::memmove(dst, src, k * sizeof(Ch));
        dst[k] = 0;
        return Flow::Next;
    }
};

// Structures, arrays, FB instances: bytewise copy.
struct AssignBytes final : Stmt {
    Expr* place;
    Expr* value;
    uint32_t size;
    AssignBytes(Expr* p, Expr* v, uint32_t n) : place(p), value(v), size(n) {}
    Flow exec(Ctx& c) override {
        const uint8_t* src = value->addr(c);
        uint8_t* dst = place->addr(c);
        if (src != dst) std::memmove(dst, src, size);
        return Flow::Next;
    }
};

// An expression evaluated for its effect (a call statement).
// Runs `body` with `self` as the current instance: initialisers that take an
// address (`r : REF_TO INT := REF(counter)`), run once before the first cycle.
struct WithSelf final : Stmt {
    uint8_t* self;
    Stmt* body;
    WithSelf(uint8_t* s, Stmt* b) : self(s), body(b) {}
    Flow exec(Ctx& c) override {
        uint8_t* saved = c.self;
        c.self = self;
        Flow f = body->exec(c);
        c.self = saved;
        return f;
    }
};

struct EvalStmt final : Stmt {
    Expr* e;
    enum class Rep : uint8_t { Int, Real, Addr, None } rep;
    EvalStmt(Expr* x, Rep r) : e(x), rep(r) {}
    Flow exec(Ctx& c) override {
        switch (rep) {
            case Rep::Int: (void)e->i(c); break;
            case Rep::Real: (void)e->f(c); break;
            default: (void)e->addr(c); break;
        }
        return c.aborting ? Flow::Abort : Flow::Next;
    }
};

// S= / R= : assigns only when the condition is TRUE.
struct CondStmt final : Stmt {
    Expr* cond;
    Stmt* then;
    CondStmt(Expr* k, Stmt* t) : cond(k), then(t) {}
    Flow exec(Ctx& c) override { return cond->i(c) ? then->exec(c) : Flow::Next; }
};

// CASE: interpreter/exec/case_nodes.h.

// FOR v := from TO to BY step: bounds and step evaluated once; the control
// variable is read back each iteration (CODESYS lets the body change it) and
// ends one step past the bound, like CODESYS.
template <class T>
struct ForStmt final : Stmt {
    Expr* var;
    Expr *from, *to, *by;  // by may be null (step 1)
    bool descending = false;  // a negative constant step on an unsigned variable (decision 0326)
    Body body;
    template <class Run>
    [[gnu::always_inline]] static Flow stepOne(Ctx& c, uint8_t* p, T end, Run&& run) {
        while (loadAs<T>(p) <= end) {
            Flow f = run(c);
            if (f != Flow::Next) {
                if (f == Flow::Exit) break;
                if (f != Flow::Continue) return f;
            }
            if (tickAborts(c)) return Flow::Abort;
            storeAs<T>(p, static_cast<T>(static_cast<U<T>>(loadAs<T>(p)) + U<T>(1)));
        }
        return Flow::Next;
    }
    Flow exec(Ctx& c) override {
        T end = static_cast<T>(to->i(c));
        if (!by) {
            // Step 1 (decision 0266): no test of the step's sign per iteration.
            uint8_t* p = var->addr(c);
            storeAs<T>(p, static_cast<T>(from->i(c)));
            return body.withShape([&](auto&& run) { return stepOne(c, p, end, run); });
        }
        T step = static_cast<T>(by->i(c));
        const bool up = !descending && step >= T(0);
        uint8_t* p = var->addr(c);
        storeAs<T>(p, static_cast<T>(from->i(c)));
        return body.withShape([&](auto&& run) {
            for (;;) {
                T v = loadAs<T>(p);
                if (up ? !(v <= end) : !(v >= end)) break;
                Flow f = run(c);
                if (f != Flow::Next) {
                    if (f == Flow::Exit) break;
                    if (f != Flow::Continue) return f;
                }
                if (tickAborts(c)) return Flow::Abort;
                // The control variable is a plain variable: its address does not move.
                storeAs<T>(p, static_cast<T>(static_cast<U<T>>(loadAs<T>(p)) + static_cast<U<T>>(step)));
            }
            return Flow::Next;
        });
    }
};

// The WHILE loop of WhileStmt and WhileCompare (fused_nodes.h): `holds(c)`
// evaluates the condition.
template <class Cond>
[[gnu::always_inline]] inline Flow runWhile(Ctx& c, const Body& body, Cond&& holds) {
    return body.withShape([&](auto&& run) {
        while (holds(c)) {
            Flow f = run(c);
            if (f != Flow::Next) {
                if (f == Flow::Exit) break;
                if (f != Flow::Continue) return f;
            }
            if (tickAborts(c)) return Flow::Abort;
        }
        return c.aborting ? Flow::Abort : Flow::Next;
    });
}

struct WhileStmt final : Stmt {
    Expr* cond;
    Body body;
    Flow exec(Ctx& c) override {
        return runWhile(c, body, [this](Ctx& k) { return cond->i(k) != 0; });
    }
};

struct RepeatStmt final : Stmt {
    Expr* cond;
    Body body;
    Flow exec(Ctx& c) override {
        return body.withShape([&](auto&& run) {
            for (;;) {
                Flow f = run(c);
                if (f != Flow::Next) {
                    if (f == Flow::Exit) break;
                    if (f != Flow::Continue) return f;
                }
                if (cond->i(c)) break;
                if (tickAborts(c)) return Flow::Abort;
            }
            return c.aborting ? Flow::Abort : Flow::Next;
        });
    }
};

struct FlowStmt final : Stmt {
    Flow flow;
    explicit FlowStmt(Flow f) : flow(f) {}
    Flow exec(Ctx&) override { return flow; }
};

struct JumpStmt final : Stmt {
    int label;
    explicit JumpStmt(int l) : label(l) {}
    Flow exec(Ctx& c) override { c.jumpLabel = label; return Flow::Jump; }
};

struct NopStmt final : Stmt {
    Flow exec(Ctx&) override { return Flow::Next; }
};

}  // namespace strun::exec
