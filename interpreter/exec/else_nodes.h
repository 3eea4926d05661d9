// The ELSE of an IF link when it has one or two statements (decision 0378).
#pragma once

#include "interpreter/exec/stmt_nodes.h"

namespace strun::exec {

// Run without the Block's call into its vector walk: each statement ticked
// and recorded in Ctx::stmt as Block::exec does it. Still reached through
// the link's `otherwise` pointer and its virtual call, so that the IF nodes
// do not change. Run inline by the IF node itself, the ELSE needed a test
// on the IF's other paths (an ELSIF link: state_machine +0.35 %
// instructions), and, inline in every IF node, made GCC save registers on
// entry to every IF (+1.9 %) and, in session 14, call runOne and Body::run
// out of line from the loops of the same unit (sort +5 %).
struct ElseStmts final : Stmt {
    Stmt* s0;
    Stmt* s1;  // may be null
    ElseStmts(Stmt* a, Stmt* b) : s0(a), s1(b) {}
    // The last statement tail-called, as Body::run runs a branch (decision 0496).
    Flow exec(Ctx& c) override {
        if (!s1) return runOne(c, s0);
        Flow f = runOne(c, s0);
        if (f != Flow::Next) return f;
        return runOne(c, s1);
    }
    // The `otherwise` of an IF link for the ELSE Block `b`: null for an empty
    // ELSE, an ElseStmts for one or two statements without labels, else the Block.
    static Stmt* of(NodePool& pool, Block* b) {
        if (!b || !b->labels.empty() || b->stmts.size() > 2) return b;
        if (b->stmts.empty()) return nullptr;
        return pool.make<ElseStmts>(b->stmts[0], b->stmts.size() > 1 ? b->stmts[1] : nullptr);
    }
};

}  // namespace strun::exec
