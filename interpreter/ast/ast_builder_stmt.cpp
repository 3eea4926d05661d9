// AstBuilder: statements.
#include "interpreter/ast/ast_builder.h"
#include "interpreter/ast/syntax_errors.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "grammar/STLexer.h"
#include "stdlib/number_scan.h"

namespace strun::ast {

using L = strun_grammar::STLexer;

namespace {

StmtPtr makeStmt(StmtKind kind, const Loc& at) {
    auto s = std::make_unique<Stmt>();
    s->kind = kind;
    s->loc = at;
    return s;
}

}  // namespace

void AstBuilder::stmtList(P::StmtListContext* c, StmtList& out) {
    if (c != nullptr) statements(c->statements, out);
}

void AstBuilder::statements(const std::vector<P::StatementContext*>& list, StmtList& out) {
    for (auto* s : list) {
        StmtPtr built = stmt(s);
        flushChained(out);
        if (built) out.push_back(std::move(built));
    }
}

StmtPtr AstBuilder::stmt(P::StatementContext* c) {
    const Loc at = loc(c);
    if (auto* e = exactly<P::ExprStmtContext>(c)) return exprStmt(e);

    if (auto* i = exactly<P::IfStmtContext>(c)) {
        auto s = makeStmt(StmtKind::If, at);
        const auto& conds = i->conds;
        const auto& blocks = i->blocks;
        for (size_t k = 0; k < conds.size(); ++k) {
            s->conds.push_back(expr(conds[k]));
            s->blocks.emplace_back();
            if (k < blocks.size()) stmtList(blocks[k], s->blocks.back());
        }
        if (i->elseBlock != nullptr) {
            s->elseBlock.emplace();
            stmtList(i->elseBlock, *s->elseBlock);
        }
        return s;
    }
    if (auto* cs = exactly<P::CaseStmtContext>(c)) {
        auto s = makeStmt(StmtKind::Case, at);
        s->expr = cs->selector ? expr(cs->selector) : placeholder(at);
        if (cs->body) caseBranches(cs->body->statements, *s);
        if (cs->elseBlock != nullptr) {
            s->elseBlock.emplace();
            stmtList(cs->elseBlock, *s->elseBlock);
        }
        return s;
    }
    if (auto* f = exactly<P::ForStmtContext>(c)) {
        auto s = makeStmt(StmtKind::For, at);
        s->name = text(f->control);
        s->nameLoc = loc(f->control);
        // `FOR Offset[1] := ...` (TwinCAT): the control variable is a place, not a name.
        if (f->control != nullptr && bareName(f->control) == nullptr) s->target = unary(f->control);
        s->from = f->from ? expr(f->from) : placeholder(at);
        s->to = f->to ? expr(f->to) : placeholder(at);
        if (f->by) s->by = f->step ? expr(f->step) : placeholder(at);
        stmtList(f->body, s->body);
        return s;
    }
    if (auto* w = exactly<P::WhileStmtContext>(c)) {
        auto s = makeStmt(StmtKind::While, at);
        s->expr = w->cond ? expr(w->cond) : placeholder(at);
        stmtList(w->body, s->body);
        return s;
    }
    if (auto* r = exactly<P::RepeatStmtContext>(c)) {
        auto s = makeStmt(StmtKind::Repeat, at);
        stmtList(r->body, s->body);
        s->expr = r->cond ? expr(r->cond) : placeholder(at);
        return s;
    }
    if (exactly<P::ExitStmtContext>(c)) return makeStmt(StmtKind::Exit, at);
    if (exactly<P::ContinueStmtContext>(c)) return makeStmt(StmtKind::Continue, at);
    if (auto* r = exactly<P::ReturnStmtContext>(c)) {
        auto s = makeStmt(StmtKind::Return, at);
        if (r->cond != nullptr) s->expr = expr(r->cond);  // `RETURN (xDone);` leaves when TRUE (CODESYS; decision 0433)
        return s;
    }
    if (auto* j = exactly<P::JmpStmtContext>(c)) {
        auto s = makeStmt(StmtKind::Jmp, at);
        s->name = text(j->target);
        s->nameLoc = loc(j->target);
        return s;
    }
    if (exactly<P::EmptyStmtContext>(c)) {
        // `END_IF;`: the ';' belongs to the statement before, not a statement of its own.
        const antlr4::Token* before = previousOnChannel(c->getStart());
        if (before != nullptr) switch (before->getType()) {
                case L::END_IF: case L::END_CASE: case L::END_FOR: case L::END_WHILE: case L::END_REPEAT: return nullptr;
                default: break;
            }
        return makeStmt(StmtKind::Empty, at);
    }
    return nullptr;  // a statement the parser could not make sense of (already reported)
}

// `lo` or `lo..hi` (with `dots` the '..'); a placeholder at `at` for what a
// syntax error left out.
CaseLabel AstBuilder::caseLabel(P::ExpressionContext* lo, const antlr4::Token* dots, P::ExpressionContext* hi, const Loc& at) {
    CaseLabel out;
    out.lo = lo ? expr(lo) : placeholder(at);
    if (dots) out.hi = hi ? expr(hi) : placeholder(at);
    return out;
}

// The statements of a CASE: a label statement (`1, 5..9:`) starts the
// next branch, the others belong to the branch before them.
void AstBuilder::caseBranches(const std::vector<P::StatementContext*>& items, Stmt& out) {
    for (auto* item : items) {
        auto* labels = exactly<P::ExprStmtContext>(item);
        if (labels != nullptr && labels->colon != nullptr) {
            CaseBranch branch;
            branch.loc = loc(labels);
            branch.labels.push_back(caseLabel(labels->parts.empty() ? nullptr : labels->parts[0], labels->dots,
                                              labels->hi, branch.loc));
            for (auto* label : labels->moreLabels)
                branch.labels.push_back(caseLabel(label->lo, label->dots, label->hi, loc(label)));
            out.cases.push_back(std::move(branch));
            continue;
        }
        if (out.cases.empty()) {
            error(diag::E0503, loc(item), "expected a CASE label ('value:') before the first statement of a CASE");
            continue;
        }
        StmtPtr built = stmt(item);
        flushChained(out.cases.back().body);
        if (built) out.cases.back().body.push_back(std::move(built));
    }
}

void AstBuilder::flushChained(StmtList& out) {
    for (auto& s : chained_) out.push_back(std::move(s));
    chained_.clear();
}

StmtPtr AstBuilder::exprStmt(P::ExprStmtContext* c) {
    const Loc at = loc(c);
    const auto& operands = c->parts;
    if (operands.empty()) return nullptr;
    if (c->colon != nullptr && (c->dots != nullptr || !c->moreLabels.empty())) {
        error(diag::E0503, at, fmt::format("'{}' are CASE labels outside a CASE: a jump label is a name followed by ':'", sourceText(c)));
        return nullptr;
    }
    if (c->colon != nullptr) {  // a jump label
        const antlr4::Token* name = bareName(operands[0]);
        if (name == nullptr) {
            error(diag::E0504, at, fmt::format("'{}' cannot be a label: a jump label is a name followed by ':'", sourceText(operands[0])));
            return nullptr;
        }
        auto s = makeStmt(StmtKind::Label, at);
        s->name = name->getText();
        return s;
    }
    if (operands.size() == 1) {
        ExprPtr e = expr(operands[0]);
        if (c->assign != nullptr || c->eq != nullptr) return nullptr;  // right side missing: reported
        if (e->kind != ExprKind::Call) {
            // `END_WHIL;`: a mistyped keyword, not an expression.
            if (const antlr4::Token* name = bareName(operands[0]); name != nullptr) {
                const std::string keyword = mistypedEndKeyword(name->getText());
                if (!keyword.empty()) {
                    error(diag::E0001, at, fmt::format("'{}' is not a keyword: did you mean '{}'?", name->getText(), keyword));
                    return nullptr;
                }
            }
            const bool comparison = e->kind == ExprKind::Binary && e->op == Op::Eq;
            Diagnostic& d = error(comparison ? diag::E0004 : diag::E0001, at, fmt::format("'{}' is not a statement: expected ':=' or a call with '(...)'{}",
                                                  sourceText(operands[0]),
                                                  comparison ? " (for an assignment write ':=', not '=')" : ""));
            if (comparison) d.withHelp("'=' compares; assignment is ':=': x := 5;");
            return nullptr;
        }
        auto s = makeStmt(StmtKind::Call, at);
        s->expr = std::move(e);
        return s;
    }

    StmtKind kind = StmtKind::Assign;
    if (c->assign != nullptr && c->assign->getType() == L::TRY_ASSIGN) {
        kind = StmtKind::TryAssign;
    } else if (c->setOperator != nullptr) {
        // `x S= y` lexes as x, S, =, y: the word before '=' names the operator.
        const std::string op = stdlib::upperAscii(text(c->setOperator));
        if (op == "S") kind = StmtKind::SetAssign;
        else if (op == "R") kind = StmtKind::ResetAssign;
        else if (op == "REF") kind = StmtKind::RefAssign;
        else {
            error(diag::E0001, loc(c->setOperator), "unknown assignment operator '" + text(c->setOperator) +
                                            "=', expected ':=', 'S=', 'R=', 'REF=' or '?='");
            return nullptr;
        }
    }
    // `a := b := 3;` (CODESYS): `b := 3;` first, then `a := b;` — the value
    // of an assignment is the value assigned (decision 0203).
    if (operands.size() > 2 && kind != StmtKind::Assign) {
        error(diag::E0001, loc(operands[2]), "only ':=' assignments can be chained (a := b := 3)");
        return nullptr;
    }
    for (size_t k = operands.size() - 1; k >= 2 && kind == StmtKind::Assign; --k) {
        auto inner = makeStmt(StmtKind::Assign, loc(operands[k - 1]));
        inner->target = expr(operands[k - 1]);
        inner->expr = expr(operands[k]);
        chained_.push_back(std::move(inner));
    }
    auto s = makeStmt(kind, at);
    s->target = expr(operands[0]);
    s->expr = expr(operands[1]);
    return s;
}

}  // namespace strun::ast
