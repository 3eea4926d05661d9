// CASE statements (decisions 0268, 0352). The labels become a table of
// branch pointers when they span at most kMaxTable values, scanned ranges
// otherwise. A branch of exactly one statement is run by the CASE itself
// (its tick, then a tail call), without Body::run's register saves; a
// selector that is a DINT or INT/enumeration variable of the instance or
// frame is read inside the node instead of through a child node.
#pragma once

#include <algorithm>
#include <limits>

#include "interpreter/exec/stmt_nodes.h"
#include "interpreter/exec/value_nodes.h"

namespace strun::exec {

// The labels and branches of one CASE. Filled by the checker (entries,
// blocks, elseBlock), then finish() once it sits in its node: the branches
// point into `blocks` and at `elseBlock`, so the CaseArms must not move or
// change afterwards.
struct CaseArms {
    struct Entry { int64_t lo, hi; size_t block; };
    // How a branch runs: `only` set: that one statement (tick, then it);
    // else `body` (null: an empty branch, nothing runs and nothing ticks).
    struct Branch {
        Stmt* only = nullptr;
        const Body* body = nullptr;
    };
    bool isUnsigned64 = false;
    std::vector<Entry> entries;  // in source order: the first match wins
    std::vector<Body> blocks;
    Body elseBlock;
    std::vector<Branch> branches;  // one per block, then the ELSE branch (last)
    // Dense labels: the branch of every selector value in
    // [tableLo, tableLo + tableSize); a gap is the ELSE branch. tableSize 0: scan.
    static constexpr int64_t kMaxTable = 1024;
    int64_t tableLo = 0;
    uint64_t tableSize = 0;
    const Branch* const* table = nullptr;
    const Branch* elseBranch = nullptr;
    std::vector<const Branch*> tableStore;

    static Branch branchOf(const Body& b) {
        Branch r;
        if (!b.block && b.s0 && !b.s1) r.only = b.s0;
        else if (b.block || b.s0) r.body = &b;
        return r;
    }

    // Whether the labels fit a table: its lowest value and span (highest - lowest).
    bool tableSpan(int64_t& lo, int64_t& span) const {
        if (isUnsigned64 || entries.empty()) return false;
        int64_t l = std::numeric_limits<int64_t>::max(), h = std::numeric_limits<int64_t>::min();
        for (const Entry& e : entries) {
            if (e.lo > e.hi) continue;
            l = std::min(l, e.lo);
            h = std::max(h, e.hi);
        }
        if (l > h || __builtin_sub_overflow(h, l, &span) || span >= kMaxTable) return false;
        lo = l;
        return true;
    }
    bool fitsTable() const {
        int64_t lo = 0, span = 0;
        return tableSpan(lo, span);
    }

    void finish() {
        branches.clear();
        for (const Body& b : blocks) branches.push_back(branchOf(b));
        branches.push_back(branchOf(elseBlock));
        elseBranch = &branches.back();
        tableStore.clear();
        table = nullptr;
        tableSize = 0;
        int64_t lo = 0, span = 0;
        if (!tableSpan(lo, span)) return;
        tableStore.assign(static_cast<size_t>(span + 1), nullptr);
        for (const Entry& e : entries)
            for (int64_t v = e.lo; v <= e.hi && e.lo <= e.hi; ++v) {
                const Branch*& slot = tableStore[static_cast<size_t>(v - lo)];
                if (!slot) slot = &branches[e.block];  // the first match wins
            }
        for (const Branch*& slot : tableStore)
            if (!slot) slot = elseBranch;
        tableLo = lo;
        tableSize = tableStore.size();  // span + 1: never 0
        table = tableStore.data();
    }

    const Branch* scan(int64_t v) const {
        for (const Entry& e : entries) {
            bool in = isUnsigned64 ? (static_cast<uint64_t>(v) >= static_cast<uint64_t>(e.lo) && static_cast<uint64_t>(v) <= static_cast<uint64_t>(e.hi))
                                   : (v >= e.lo && v <= e.hi);
            if (in) return &branches[e.block];
        }
        return elseBranch;
    }

    // A branch of several statements: out of line, so that dispatch() saves
    // no registers for it and ends in tail calls.
    [[gnu::noinline]] static Flow runBody(const Body* b, Ctx& c) { return b->run(c); }

    // Runs the branch of selector value v, ticking exactly as Body::run.
    // TABLE: the arms have a table (fitsTable()), so it is not tested.
    template <bool TABLE = false>
    [[gnu::always_inline]] inline Flow dispatch(Ctx& c, int64_t v) const {
        const Branch* b;
        if (TABLE || __builtin_expect(tableSize != 0, 1)) {
            uint64_t k = static_cast<uint64_t>(v) - static_cast<uint64_t>(tableLo);
            b = k < tableSize ? table[k] : elseBranch;
        } else {
            b = scan(v);
        }
        if (Stmt* s = b->only) {
            c.stmt = s;
            if (tickAborts(c)) return Flow::Abort;
            return s->exec(c);
        }
        return b->body ? runBody(b->body, c) : Flow::Next;
    }
};

// CASE on any selector expression.
struct CaseStmt final : Stmt {
    Expr* selector = nullptr;
    CaseArms arms;
    Flow exec(Ctx& c) override { return arms.dispatch(c, selector->i(c)); }
};

// CASE on a variable of signed storage type T (INT and enumerations: int16_t;
// DINT: int32_t) of the current instance (Self) or frame (Frame): read as
// VarNode<T, B>::i reads it. Only for labels that fit a table.
template <class T, BaseKind B>
struct CaseOnVar final : Stmt {
    static_assert(std::is_signed_v<T> && std::is_integral_v<T>);
    uint32_t off = 0;
    CaseArms arms;
    explicit CaseOnVar(uint32_t o) : off(o) {}
    Flow exec(Ctx& c) override { return arms.dispatch<true>(c, static_cast<int64_t>(loadAs<T>(baseOf<B>(c, nullptr) + off))); }
};

}  // namespace strun::exec
