#include "interpreter/sema/case_lowering.h"

namespace strun::sema {

namespace {

template <class T, exec::BaseKind B>
exec::Stmt* onVar(exec::NodePool& pool, exec::Expr* selector, exec::CaseArms& arms) {
    auto* v = exec::nodeCast<exec::VarNode<T, B>>(selector);
    if (!v) return nullptr;
    auto* n = pool.make<exec::CaseOnVar<T, B>>(v->off);
    n->arms = std::move(arms);
    n->arms.finish();
    return n;
}

}  // namespace

exec::Stmt* makeCaseNode(exec::NodePool& pool, exec::Expr* selector, exec::CaseArms&& arms) {
    using exec::BaseKind;
    if (arms.fitsTable()) {  // CaseOnVar does not test for the table
        if (exec::Stmt* n = onVar<int32_t, BaseKind::Self>(pool, selector, arms)) return n;
        if (exec::Stmt* n = onVar<int16_t, BaseKind::Self>(pool, selector, arms)) return n;
        if (exec::Stmt* n = onVar<int32_t, BaseKind::Frame>(pool, selector, arms)) return n;
        if (exec::Stmt* n = onVar<int16_t, BaseKind::Frame>(pool, selector, arms)) return n;
    }
    auto* n = pool.make<exec::CaseStmt>();
    n->selector = selector;
    n->arms = std::move(arms);
    n->arms.finish();
    return n;
}

}  // namespace strun::sema
