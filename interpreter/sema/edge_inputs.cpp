#include "interpreter/sema/edge_inputs.h"

#include <map>

#include "interpreter/ast/synthesized_expr.h"
#include "stdlib/number_scan.h"

namespace strun::sema {

namespace {

using Triggers = std::map<std::string, std::string>;  // input name (upper case) -> its trigger's name

// Makes every read of an edge input in the body read its trigger's Q.
struct EdgeReads {
    const Triggers& triggers;

    void expr(ast::ExprPtr& e) {
        if (!e) return;
        if (e->kind == ast::ExprKind::Name) {
            const auto it = triggers.find(stdlib::upperAscii(e->name));
            if (it == triggers.end()) return;
            auto q = std::make_unique<ast::Expr>();
            q->kind = ast::ExprKind::Member;
            q->loc = e->loc;
            q->nameLoc = e->loc;
            q->name = "Q";
            q->kids.push_back(ast::nameExpr(it->second, e->loc));
            e = std::move(q);
            return;
        }
        // A call's callee and a member's name are not reads of a variable.
        for (size_t i = 0; i < e->kids.size(); ++i)
            if (!(i == 0 && e->kind == ast::ExprKind::Call && e->kids[0] && e->kids[0]->kind == ast::ExprKind::Name)) expr(e->kids[i]);
        for (ast::Arg& a : e->args) expr(a.value);
    }
    void stmts(ast::StmtList& list) {
        for (auto& s : list) stmt(*s);
    }
    void stmt(ast::Stmt& s) {
        // `x := ...` writes the input as passed; `a[x] := ...` reads it.
        if (s.target && s.target->kind != ast::ExprKind::Name) expr(s.target);
        expr(s.expr);
        expr(s.from);
        expr(s.to);
        expr(s.by);
        for (auto& c : s.conds) expr(c);
        for (auto& b : s.blocks) stmts(b);
        for (auto& c : s.cases) stmts(c.body);
        stmts(s.body);
        if (s.elseBlock) stmts(*s.elseBlock);
    }
};

}  // namespace

std::string edgeTriggerName(const std::string& input) { return input + "$EDGE"; }

void lowerEdgeInputs(ast::Pou& pou) {
    if (pou.kind != ast::PouKind::FunctionBlock && pou.kind != ast::PouKind::Program) return;
    // Lowered once: a parse kept from an earlier check (the editors', a live reload) comes back lowered.
    for (const ast::VarBlock& block : pou.vars)
        for (const ast::VarDecl& d : block.vars)
            for (const std::string& name : d.names)
                if (name.size() > 5 && name.compare(name.size() - 5, 5, "$EDGE") == 0) return;
    Triggers triggers;
    std::vector<ast::VarDecl> instances;
    ast::StmtList calls;
    for (const ast::VarBlock& block : pou.vars) {
        for (const ast::VarDecl& d : block.vars) {
            if (d.edge == ast::VarDecl::Edge::None) continue;
            for (const std::string& name : d.names) {
                // Anything but a BOOL input is the checker's error.
                if (block.section != ast::VarSection::Input || !d.type || d.type->kind != ast::TypeSpecKind::Named ||
                    stdlib::upperAscii(d.type->name) != "BOOL")
                    continue;
                const std::string trigger = edgeTriggerName(name);
                triggers[stdlib::upperAscii(name)] = trigger;
                ast::VarDecl inst;
                inst.loc = d.loc;
                inst.names.push_back(trigger);
                inst.nameLocs.push_back(d.loc);
                inst.type = std::make_unique<ast::TypeSpec>();
                inst.type->loc = d.loc;
                inst.type->name = d.edge == ast::VarDecl::Edge::Rising ? "R_TRIG" : "F_TRIG";
                inst.pragmas.push_back({d.loc, "attribute 'strun_hidden'"});  // out of --dump and --vcd
                instances.push_back(std::move(inst));
                // trigger(CLK := input);
                auto call = std::make_unique<ast::Expr>();
                call->kind = ast::ExprKind::Call;
                call->loc = d.loc;
                call->kids.push_back(ast::nameExpr(trigger, d.loc));
                ast::Arg clk;
                clk.loc = d.loc;
                clk.name = "CLK";
                clk.value = ast::nameExpr(name, d.loc);
                call->args.push_back(std::move(clk));
                auto stmt = std::make_unique<ast::Stmt>();
                stmt->kind = ast::StmtKind::Call;
                stmt->loc = d.loc;
                stmt->expr = std::move(call);
                calls.push_back(std::move(stmt));
            }
        }
    }
    if (triggers.empty()) return;
    EdgeReads{triggers}.stmts(pou.body);
    for (auto& s : pou.body) calls.push_back(std::move(s));
    pou.body = std::move(calls);
    ast::VarBlock block;
    block.loc = instances.front().loc;
    block.section = ast::VarSection::Var;
    block.vars = std::move(instances);
    pou.vars.push_back(std::move(block));
}

}  // namespace strun::sema
