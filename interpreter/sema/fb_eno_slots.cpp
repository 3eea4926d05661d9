#include "interpreter/sema/fb_eno_slots.h"

#include <set>

#include "stdlib/number_scan.h"

namespace strun::sema {

namespace {

std::string upperOf(const std::string& s) {
    std::string out = s;
    for (char& c : out)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    return out;
}

bool isEnOrEno(const ast::Arg& a) {
    return (!a.output && stdlib::equalsIgnoreCase(a.name, "EN")) || (a.output && stdlib::equalsIgnoreCase(a.name, "ENO"));
}

// Collects (upper case) the names X of `X(EN := ...)`, `X(ENO => ...)` and `X.ENO`.
struct EnoUses {
    std::set<std::string> names;

    void expr(const ast::Expr* e) {
        if (!e) return;
        const ast::Expr* first = e->kids.empty() ? nullptr : e->kids[0].get();
        if (e->kind == ast::ExprKind::Member && first && first->kind == ast::ExprKind::Name && stdlib::equalsIgnoreCase(e->name, "ENO"))
            names.insert(upperOf(first->name));
        if (e->kind == ast::ExprKind::Call && first && first->kind == ast::ExprKind::Name)
            for (const ast::Arg& a : e->args)
                if (isEnOrEno(a)) names.insert(upperOf(first->name));
        for (const auto& k : e->kids) expr(k.get());
        for (const ast::Arg& a : e->args) expr(a.value.get());
    }
    void stmts(const ast::StmtList& list) {
        for (const auto& s : list) stmt(*s);
    }
    void stmt(const ast::Stmt& s) {
        expr(s.target.get());
        expr(s.expr.get());
        expr(s.from.get());
        expr(s.to.get());
        expr(s.by.get());
        for (const auto& c : s.conds) expr(c.get());
        for (const auto& b : s.blocks) stmts(b);
        for (const auto& c : s.cases) stmts(c.body);
        stmts(s.body);
        if (s.elseBlock) stmts(*s.elseBlock);
    }
};

bool holdsInstances(ast::VarSection s) {
    return s == ast::VarSection::Var || s == ast::VarSection::Stat || s == ast::VarSection::Inst;
}

// A hidden BOOL `X$ENO` declared where the instance X is (`d` its declaration).
ast::VarDecl slotFor(const ast::VarDecl& d, const std::string& name) {
    ast::VarDecl slot;
    slot.loc = d.loc;
    slot.names.push_back(enoSlotName(name));
    slot.nameLocs.push_back(d.loc);
    slot.type = std::make_unique<ast::TypeSpec>();
    slot.type->loc = d.loc;
    slot.type->name = "BOOL";
    slot.pragmas.push_back({d.loc, "attribute 'strun_hidden'"});  // out of --dump and --vcd (decision 0290)
    return slot;
}

void usesOf(const ast::Pou& pou, EnoUses& uses) {
    uses.stmts(pou.body);
    for (const auto& m : pou.methods) usesOf(*m, uses);
}

void addSlots(ast::Pou& pou) {
    EnoUses uses;
    uses.stmts(pou.body);
    if (uses.names.empty()) return;
    // Added once: a parse kept from an earlier check (the editors', a live reload) comes back with them.
    for (const ast::VarBlock& block : pou.vars)
        for (const ast::VarDecl& d : block.vars)
            for (const std::string& name : d.names)
                if (name.find('$') != std::string::npos) uses.names.erase(upperOf(name.substr(0, name.find('$'))));
    std::vector<ast::VarDecl> slots;
    for (const ast::VarBlock& block : pou.vars) {
        if (!holdsInstances(block.section) || block.constant) continue;
        for (const ast::VarDecl& d : block.vars) {
            // Only a block instance: a variable of a named, non-array type.
            if (!d.type || d.type->kind != ast::TypeSpecKind::Named) continue;
            for (const std::string& name : d.names)
                if (uses.names.count(upperOf(name))) slots.push_back(slotFor(d, name));
        }
    }
    if (slots.empty()) return;
    ast::VarBlock block;
    block.loc = slots.front().loc;
    block.section = ast::VarSection::Var;
    block.vars = std::move(slots);
    pou.vars.push_back(std::move(block));
}

}  // namespace

std::string enoSlotName(const std::string& instance) { return instance + "$ENO"; }

void addGlobalFbEnoSlots(std::vector<ast::CompilationUnit>& units) {
    EnoUses uses;
    for (const auto& u : units)
        for (const auto& p : u.pous) usesOf(*p, uses);
    if (uses.names.empty()) return;
    // Added once: a parse kept from an earlier check comes back with them.
    for (const auto& u : units)
        for (const ast::GlobalList& list : u.globals)
            for (const ast::VarBlock& block : list.blocks)
                for (const ast::VarDecl& d : block.vars)
                    for (const std::string& name : d.names)
                        if (name.find('$') != std::string::npos) uses.names.erase(upperOf(name.substr(0, name.find('$'))));
    for (auto& u : units)
        for (ast::GlobalList& list : u.globals) {
            std::vector<ast::VarDecl> slots;
            for (const ast::VarBlock& block : list.blocks) {
                if (block.constant) continue;
                for (const ast::VarDecl& d : block.vars) {
                    if (!d.type || d.type->kind != ast::TypeSpecKind::Named) continue;
                    for (const std::string& name : d.names)
                        if (uses.names.count(upperOf(name))) slots.push_back(slotFor(d, name));
                }
            }
            if (slots.empty()) continue;
            ast::VarBlock block;
            block.loc = slots.front().loc;
            block.section = list.blocks.front().section;
            block.vars = std::move(slots);
            list.blocks.push_back(std::move(block));
        }
}

void addFbEnoSlots(ast::Pou& pou) {
    // Only the instances of a PROGRAM or a block persist from call to call.
    if (pou.kind == ast::PouKind::Program || pou.kind == ast::PouKind::FunctionBlock) addSlots(pou);
}

}  // namespace strun::sema
