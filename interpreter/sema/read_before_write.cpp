// W0017, the read-before-write warning (rule in read_before_write.h, decision 0162).
#include "interpreter/sema/read_before_write.h"

#include <map>
#include <set>

#include <fmt/format.h>

#include "interpreter/sema/types.h"

namespace strun::sema {

namespace {

// The candidates not yet written on the path followed, by upper-case name.
using Unwritten = std::map<std::string, const VarSym*>;

class Walker {
public:
    Walker(CompileLog& log) : log_(log) {}

    void statements(const ast::StmtList& list, Unwritten& open) {
        for (const auto& s : list) statement(*s, open);
    }

private:
    CompileLog& log_;
    std::set<const VarSym*> warned_;

    static const ast::Expr* root(const ast::Expr* e) {
        while (e && (e->kind == ast::ExprKind::Member || e->kind == ast::ExprKind::Index) && !e->kids.empty())
            e = e->kids[0].get();
        return e;
    }
    static std::string rootName(const ast::Expr* e) {
        e = root(e);
        return e && e->kind == ast::ExprKind::Name ? upper(e->name) : std::string();
    }

    void read(const ast::Expr* e, Unwritten& open) {
        if (!e) return;
        switch (e->kind) {
            case ast::ExprKind::Name: {
                auto it = open.find(upper(e->name));
                if (it == open.end()) return;
                const VarSym* v = it->second;
                open.erase(it);  // one warning per variable: its first read
                if (!warned_.insert(v).second) return;
                log_.warning(diag::W0017, e->loc, fmt::format("variable '{}' is read before it is ever written", v->name))
                    .note(v->loc, fmt::format("'{}' is declared here without an initial value: it holds 0 on every call",
                                              v->name))
                    .withHelp(fmt::format("assign '{}' before this line, or give it an initial value ('{} : ... := ...;')",
                                          v->name, v->name));
                return;
            }
            case ast::ExprKind::Call:
                // The callee (kids[0]) is not a read of a variable, but an instance's or
                // a method's path is evaluated: `a[i].M()` reads i.
                if (!e->kids.empty()) subscripts(e->kids[0].get(), open);
                for (const auto& a : e->args) argument(a, open);
                return;
            case ast::ExprKind::Assign:  // `(x := v)`: v is read, then x written
                if (e->kids.size() == 2) {
                    read(e->kids[1].get(), open);
                    write(e->kids[0].get(), open);
                }
                return;
            default:
                for (const auto& k : e->kids) read(k.get(), open);
        }
    }

    // The subscripts along a path (`a[i].b[j]` reads i and j), not its root.
    void subscripts(const ast::Expr* e, Unwritten& open) {
        while (e && (e->kind == ast::ExprKind::Member || e->kind == ast::ExprKind::Index) && !e->kids.empty()) {
            if (e->kind == ast::ExprKind::Index)
                for (size_t i = 1; i < e->kids.size(); ++i) read(e->kids[i].get(), open);
            e = e->kids[0].get();
        }
    }

    // A bare variable as an argument may be a VAR_IN_OUT, or its address be taken
    // (ADR, REF): the callee may write it.
    void argument(const ast::Arg& a, Unwritten& open) {
        const ast::Expr* v = a.value.get();
        if (!v) return;
        if (a.output || v->kind == ast::ExprKind::Name || v->kind == ast::ExprKind::Member ||
            v->kind == ast::ExprKind::Index) {
            subscripts(v, open);
            write(v, open);
            return;
        }
        read(v, open);
    }

    void write(const ast::Expr* target, Unwritten& open) {
        std::string name = rootName(target);
        if (!name.empty()) open.erase(name);
    }

    // Everything a statement list may write, at any depth.
    void writtenIn(const ast::StmtList& list, std::set<std::string>& out) {
        for (const auto& s : list) writtenIn(*s, out);
    }
    void writtenInExpr(const ast::Expr* e, std::set<std::string>& out) {
        if (!e) return;
        if (e->kind == ast::ExprKind::Call)
            for (const auto& a : e->args) {
                const ast::Expr* v = a.value.get();
                if (v && (a.output || v->kind == ast::ExprKind::Name || v->kind == ast::ExprKind::Member ||
                          v->kind == ast::ExprKind::Index))
                    out.insert(rootName(v));
                else
                    writtenInExpr(v, out);
            }
        if (e->kind == ast::ExprKind::Assign && !e->kids.empty()) out.insert(rootName(e->kids[0].get()));
        for (const auto& k : e->kids) writtenInExpr(k.get(), out);
    }
    void writtenIn(const ast::Stmt& s, std::set<std::string>& out) {
        if (s.target) out.insert(rootName(s.target.get()));
        if (s.kind == ast::StmtKind::For) out.insert(upper(s.name));
        writtenInExpr(s.expr.get(), out);
        for (const auto& c : s.conds) writtenInExpr(c.get(), out);
        writtenInExpr(s.from.get(), out);
        writtenInExpr(s.to.get(), out);
        writtenInExpr(s.by.get(), out);
        for (const auto& b : s.blocks) writtenIn(b, out);
        for (const auto& c : s.cases) writtenIn(c.body, out);
        writtenIn(s.body, out);
        if (s.elseBlock) writtenIn(*s.elseBlock, out);
    }

    // After branches that each started from `open`: what any branch may have written is written.
    static void keepCommon(Unwritten& open, const Unwritten& branch) {
        std::erase_if(open, [&](const auto& kv) { return !branch.count(kv.first); });
    }

    void loopBody(const ast::Stmt& s, Unwritten& open) {
        std::set<std::string> written;
        writtenIn(s.body, written);
        if (s.kind == ast::StmtKind::Repeat) writtenInExpr(s.expr.get(), written);
        Unwritten inside = open;
        for (const auto& n : written) inside.erase(n);
        statements(s.body, inside);
        if (s.kind == ast::StmtKind::Repeat) read(s.expr.get(), inside);
        keepCommon(open, inside);
    }

    void statement(const ast::Stmt& s, Unwritten& open) {
        switch (s.kind) {
            case ast::StmtKind::Assign:
            case ast::StmtKind::SetAssign:
            case ast::StmtKind::ResetAssign:
            case ast::StmtKind::TryAssign:
            case ast::StmtKind::RefAssign:
                read(s.expr.get(), open);
                subscripts(s.target.get(), open);
                write(s.target.get(), open);
                return;
            case ast::StmtKind::Call:
            case ast::StmtKind::Return: read(s.expr.get(), open); return;  // RETURN (cond);'s condition (decision 0433)
            case ast::StmtKind::If: {
                Unwritten after = open;
                for (size_t i = 0; i < s.conds.size(); ++i) {
                    read(s.conds[i].get(), open);  // conditions run in order until one holds
                    Unwritten branch = open;
                    if (i < s.blocks.size()) statements(s.blocks[i], branch);
                    keepCommon(after, branch);
                }
                Unwritten branch = open;
                if (s.elseBlock) statements(*s.elseBlock, branch);
                keepCommon(after, branch);
                open = std::move(after);
                return;
            }
            case ast::StmtKind::Case: {
                read(s.expr.get(), open);
                Unwritten after = open;
                for (const auto& c : s.cases) {
                    Unwritten branch = open;
                    statements(c.body, branch);
                    keepCommon(after, branch);
                }
                Unwritten branch = open;
                if (s.elseBlock) statements(*s.elseBlock, branch);
                keepCommon(after, branch);
                open = std::move(after);
                return;
            }
            case ast::StmtKind::For:
                read(s.from.get(), open);
                read(s.to.get(), open);
                read(s.by.get(), open);
                open.erase(upper(s.name));
                loopBody(s, open);
                return;
            case ast::StmtKind::While: {
                Unwritten first = open;  // the first test sees only what came before
                read(s.expr.get(), first);
                keepCommon(open, first);
                loopBody(s, open);
                return;
            }
            case ast::StmtKind::Repeat: loopBody(s, open); return;
            default: return;
        }
    }
};

bool hasLabel(const ast::StmtList& list) {
    for (const auto& s : list) {
        if (s->kind == ast::StmtKind::Label || s->kind == ast::StmtKind::Jmp) return true;
        for (const auto& b : s->blocks)
            if (hasLabel(b)) return true;
        for (const auto& c : s->cases)
            if (hasLabel(c.body)) return true;
        if (hasLabel(s->body) || (s->elseBlock && hasLabel(*s->elseBlock))) return true;
    }
    return false;
}

}  // namespace

void warnReadBeforeWrite(const PouInfo& pou, CompileLog& log) {
    if (pou.kind != ast::PouKind::Function && pou.kind != ast::PouKind::Method) return;
    if (!pou.ast || hasLabel(pou.ast->body)) return;
    Unwritten open;
    for (const auto& v : pou.ownedVars) {
        if (v->section != ast::VarSection::Var && v->section != ast::VarSection::Temp) continue;
        if (v->constant || v->inferred || v.get() == pou.result || !v->type || !isElementary(v->type->kind)) continue;
        if (!v->decl || v->decl->init || !v->decl->address.empty()) continue;
        open.emplace(upper(v->name), v.get());
    }
    if (open.empty()) return;
    Walker(log).statements(pou.ast->body, open);
}

}  // namespace strun::sema
