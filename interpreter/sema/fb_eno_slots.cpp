#include "interpreter/sema/fb_eno_slots.h"

#include <set>

#include "stdlib/number_scan.h"

namespace strun::sema {

namespace {

bool isEnOrEno(const ast::Arg& a) {
    return (!a.output && stdlib::equalsIgnoreCase(a.name, "EN")) || (a.output && stdlib::equalsIgnoreCase(a.name, "ENO"));
}

// Collects (upper case) the names X of `X(EN := ...)`, `X(ENO => ...)` and
// `X.ENO`, and the pairs (Q, X) of `Q.X(EN := ...)` and `Q.X.ENO`, where Q is
// a global list or a program (decision 0388).
struct EnoUses {
    std::set<std::string> names;
    std::set<std::pair<std::string, std::string>> qualified;

    void note(const ast::Expr* instance) {
        if (instance->kind == ast::ExprKind::Name) {
            names.insert(stdlib::upperAscii(instance->name));
        } else if (instance->kind == ast::ExprKind::Member && instance->kids.size() == 1 &&
                   instance->kids[0]->kind == ast::ExprKind::Name) {
            qualified.insert({stdlib::upperAscii(instance->kids[0]->name), stdlib::upperAscii(instance->name)});
        }
    }
    void expr(const ast::Expr* e) {
        if (!e) return;
        const ast::Expr* first = e->kids.empty() ? nullptr : e->kids[0].get();
        if (e->kind == ast::ExprKind::Member && first && stdlib::equalsIgnoreCase(e->name, "ENO")) note(first);
        if (e->kind == ast::ExprKind::Call && first)
            for (const ast::Arg& a : e->args)
                if (isEnOrEno(a)) note(first);
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

// A kept parse (the editors', a live reload) comes back with its slots: forget
// the instances that have one already.
void forgetSlotted(const std::vector<ast::VarBlock>& blocks, EnoUses& uses) {
    for (const ast::VarBlock& block : blocks)
        for (const ast::VarDecl& d : block.vars)
            for (const std::string& name : d.names)
                if (name.find('$') != std::string::npos) uses.names.erase(stdlib::upperAscii(name.substr(0, name.find('$'))));
}

// The slots of the instances `uses` names among `blocks` (those of the
// sections `holds` accepts), appended to `blocks` as a block of `section`.
void addSlotsTo(std::vector<ast::VarBlock>& blocks, const EnoUses& uses, bool (*holds)(ast::VarSection), ast::VarSection section) {
    std::vector<ast::VarDecl> slots;
    for (const ast::VarBlock& block : blocks) {
        if (!holds(block.section) || block.constant) continue;
        for (const ast::VarDecl& d : block.vars) {
            // Only a block instance: a variable of a named, non-array type.
            if (!d.type || d.type->kind != ast::TypeSpecKind::Named) continue;
            for (const std::string& name : d.names)
                if (uses.names.count(stdlib::upperAscii(name))) slots.push_back(slotFor(d, name));
        }
    }
    if (slots.empty()) return;
    ast::VarBlock block;
    block.loc = slots.front().loc;
    block.section = section;
    block.vars = std::move(slots);
    blocks.push_back(std::move(block));
}

void addSlots(ast::Pou& pou) {
    EnoUses uses;
    uses.stmts(pou.body);
    if (uses.names.empty()) return;
    forgetSlotted(pou.vars, uses);
    addSlotsTo(pou.vars, uses, holdsInstances, ast::VarSection::Var);
}

}  // namespace

std::string enoSlotName(const std::string& instance) { return instance + "$ENO"; }

namespace {
// The instances X of the uses `Q.X` whose Q is `name` (the last part of a
// dotted list name: `GVL` of `Lib.GVL`).
EnoUses qualifiedBy(const EnoUses& uses, const std::string& name) {
    EnoUses here;
    std::string key = stdlib::upperAscii(name);
    if (auto dot = key.rfind('.'); dot != std::string::npos) key = key.substr(dot + 1);
    for (const auto& [q, x] : uses.qualified)
        if (q == key) here.names.insert(x);
    return here;
}
bool anySection(ast::VarSection) { return true; }
}  // namespace

void addGlobalFbEnoSlots(std::vector<ast::CompilationUnit>& units) {
    EnoUses uses;
    for (const auto& u : units)
        for (const auto& p : u.pous) usesOf(*p, uses);
    if (uses.names.empty() && uses.qualified.empty()) return;
    for (const auto& u : units)
        for (const ast::GlobalList& list : u.globals) forgetSlotted(list.blocks, uses);
    for (auto& u : units)
        for (ast::GlobalList& list : u.globals) {
            if (list.blocks.empty()) continue;
            EnoUses here = qualifiedBy(uses, list.nameSpace);  // GVL.X.ENO
            forgetSlotted(list.blocks, here);
            here.names.insert(uses.names.begin(), uses.names.end());
            addSlotsTo(list.blocks, here, anySection, list.blocks.front().section);
        }
    // Prog.inst.ENO read in another POU: the program keeps the slot its own calls write.
    for (auto& u : units)
        for (auto& p : u.pous) {
            if (p->kind != ast::PouKind::Program || uses.qualified.empty()) continue;
            EnoUses here = qualifiedBy(uses, p->name);
            if (here.names.empty()) continue;
            forgetSlotted(p->vars, here);
            addSlotsTo(p->vars, here, holdsInstances, ast::VarSection::Var);
        }
}

void addFbEnoSlots(ast::Pou& pou) {
    // Only the instances of a PROGRAM or a block persist from call to call.
    if (pou.kind == ast::PouKind::Program || pou.kind == ast::PouKind::FunctionBlock) addSlots(pou);
}

}  // namespace strun::sema
