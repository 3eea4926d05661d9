// An ACTION called with arguments (TwinCAT, CODESYS): `fb.A_Add(putValue := s,
// bOk => ok)`. An action has no parameters of its own; the arguments name the
// block's inputs, set before the action runs, and its outputs, read after it,
// as Beckhoff documents for the buffer blocks (FB_MemRingBuffer.A_AddTail);
// a VAR_IN_OUT is bound to its argument before the action runs.
// The call becomes the statements it stands for, checked as if written so.
#include <fmt/format.h>

#include "interpreter/ast/ast_clone.h"
#include "interpreter/sema/checker.h"

namespace strun::sema {

namespace {

// The block's parameter of that name (its own or inherited), or null.
VarSym* blockParameter(PouInfo* block, const std::string& upperName) {
    for (PouInfo* p = block; p; p = p->parent)
        for (VarSym* v : p->params)
            if (upper(v->name) == upperName) return v;
    return nullptr;
}

ast::ExprPtr memberExpr(const ast::Expr& instance, const ast::Arg& arg) {
    auto member = std::make_unique<ast::Expr>();
    member->kind = ast::ExprKind::Member;
    member->loc = arg.loc;
    member->nameLoc = arg.loc;
    member->name = arg.name;
    member->kids.push_back(ast::cloneExpr(instance));
    return member;
}

}  // namespace

exec::Stmt* Checker::callActionWithArguments(const ast::Expr& call, PouInfo* block) {
    const ast::Expr& callee = *call.kids[0];
    const ast::Expr& instance = *callee.kids[0];
    auto* seq = pool().make<exec::Block>();
    std::vector<std::unique_ptr<ast::Stmt>> after;  // the outputs, read once the action has run
    bool ok = true;
    for (const ast::Arg& a : call.args) {
        if (a.name.empty() || !a.value) {
            error(diag::E0301, a.loc, fmt::format("the action '{}' has no parameters of its own: name the input of '{}' it sets (name := value)",
                                                  callee.name, block->name));
            ok = false;
            continue;
        }
        VarSym* p = blockParameter(block, upper(a.name));
        const bool isInput = p && p->section == ast::VarSection::Input;
        const bool isOutput = p && p->section == ast::VarSection::Output;
        const bool isInOut = p && p->section == ast::VarSection::InOut;
        if (a.output ? !isOutput : !(isInput || isInOut)) {
            error(diag::E0302, a.loc, fmt::format("'{}' is not {} of '{}' (the arguments of an action call set the block's inputs and "
                                                  "VAR_IN_OUTs with ':=' and read its outputs with '=>')",
                                                  a.name, a.output ? "an output" : "an input", block->name));
            ok = false;
            continue;
        }
        if (isInOut) {
            // `fbTable.A_Add(hTable := hTable, ...)` (Beckhoff's FB_HashTableCtrl):
            // the VAR_IN_OUT is bound to the variable, as a call of the block binds it (decision 0463).
            Checked inst = checkExpr(instance);
            Checked v = checkExpr(*a.value);
            if (!inst.ok || !v.ok) { ok = false; continue; }
            const Field* f = inst.type->findField(upper(p->name));
            exec::Expr* slot = pool().make<exec::OffsetPlace>(inst.node, f ? f->offset : 0);
            if (exec::Stmt* bind = bindInOut(p, v, slot, a.value->loc)) seq->stmts.push_back(bind);
            else ok = false;
            continue;
        }
        auto stmt = std::make_unique<ast::Stmt>();
        stmt->kind = ast::StmtKind::Assign;
        stmt->loc = a.loc;
        stmt->target = a.output ? ast::cloneExpr(*a.value) : memberExpr(instance, a);
        stmt->expr = a.output ? memberExpr(instance, a) : ast::cloneExpr(*a.value);
        if (a.output) {
            after.push_back(std::move(stmt));
            continue;
        }
        if (exec::Stmt* set = checkAssign(*stmt)) seq->stmts.push_back(set);
        else ok = false;
        assignmentValues_.push_back(std::move(stmt));
    }
    auto run = std::make_unique<ast::Stmt>();
    run->kind = ast::StmtKind::Call;
    run->loc = call.loc;
    run->expr = std::make_unique<ast::Expr>();
    run->expr->kind = ast::ExprKind::Call;
    run->expr->loc = call.loc;
    run->expr->kids.push_back(ast::cloneExpr(callee));
    if (exec::Stmt* action = checkStmt(*run)) seq->stmts.push_back(action);
    else ok = false;
    assignmentValues_.push_back(std::move(run));
    for (auto& stmt : after) {
        if (exec::Stmt* get = checkAssign(*stmt)) seq->stmts.push_back(get);
        else ok = false;
        assignmentValues_.push_back(std::move(stmt));
    }
    return ok ? seq : nullptr;
}

}  // namespace strun::sema
