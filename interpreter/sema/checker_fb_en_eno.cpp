// EN/ENO on a function-block call (decision 0358), as Beremiz and OpenPLC
// write the blocks of an LD rung: `TON3(EN := x, IN := y, PT := T#5s);
// TOF3(EN := TON3.ENO, ...)`. IEC 61131-3 gives every block the input EN and
// the output ENO: a block not enabled is not called and keeps its outputs;
// ENO is TRUE after a call that ran. A block that declares EN or ENO itself
// keeps them as its own variables (decision 0333). Calls of other instances
// are compiled as before and cost nothing more.
#include "interpreter/ast/ast_clone.h"
#include "interpreter/exec/call_nodes.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/fb_eno_slots.h"
#include "stdlib/number_scan.h"

namespace strun::sema {

namespace {
// A block that declares EN or ENO itself: they are its own variables.
bool ownsEnEno(const Type* instance) { return instance->findField("EN") || instance->findField("ENO"); }
}  // namespace

VarSym* Checker::fbEnoSlot(const ast::Expr& instance) {
    if (instance.kind != ast::ExprKind::Name) return nullptr;
    VarSym* slot = lookupVar(upper(enoSlotName(instance.name)));
    if (!slot) return nullptr;
    if (slot->owner == pou_) return slot;
    // A global instance's slot (decision 0370), unless a local of that name hides the global.
    const VarSym* inst = lookupVar(upper(instance.name));
    return !slot->owner && inst && !inst->owner ? slot : nullptr;
}

// The slot of `instance` as an expression: `X$ENO` for `X` (its own or a
// global instance), `GVL.X$ENO` for `GVL.X` (a global list's instance) and
// `Prog.X$ENO` for `Prog.X` (a program's instance), decision 0388. False
// when the instance has no slot.
bool Checker::fbEnoSlotPath(const ast::Expr& instance, ast::Expr& slot) {
    slot.kind = instance.kind;
    slot.loc = instance.loc;
    slot.nameLoc = instance.nameLoc;
    slot.name = enoSlotName(instance.name);
    if (instance.kind == ast::ExprKind::Name) return fbEnoSlot(instance) != nullptr;
    if (instance.kind != ast::ExprKind::Member || instance.kids.size() != 1 || instance.kids[0]->kind != ast::ExprKind::Name)
        return false;
    const ast::Expr& q = *instance.kids[0];
    const std::string key = upper(slot.name);
    const VarSym* inst = nullptr;  // the instance X, when its slot exists
    if (auto p = pous_.find(upper(q.name)); p != pous_.end() && p->second->kind == ast::PouKind::Program) {
        if (p->second->vars.count(key))
            if (auto v = p->second->vars.find(upper(instance.name)); v != p->second->vars.end()) inst = v->second;
    } else if (isNamespace(q) && !lookupVar(upper(q.name))) {
        const VarSym* s = lookupVar(key);
        if (s && !s->owner) inst = lookupVar(upper(instance.name));
    }
    // Only a block's ENO: a structure member named like one is not.
    if (!inst || !inst->type || inst->type->kind != TK::FunctionBlock || ownsEnEno(inst->type)) return false;
    slot.kids.push_back(ast::cloneExpr(q));
    return true;
}

bool Checker::usesFbEnEno(const Checked& inst, const ast::Expr& call) {
    if (ownsEnEno(inst.type)) return false;
    ast::Expr slot;
    return hasEnEno(call) || (!call.kids.empty() && fbEnoSlotPath(*call.kids[0], slot));
}

bool Checker::checkFbEnoRead(const ast::Expr& member, Checked& out) {
    ast::Expr slot;
    if (!stdlib::equalsIgnoreCase(member.name, "ENO") || member.kids.empty() || !fbEnoSlotPath(*member.kids[0], slot)) return false;
    const ast::Expr& instance = *member.kids[0];
    if (instance.kind == ast::ExprKind::Name) {
        const VarSym* v = lookupVar(upper(instance.name));
        if (!v || !v->type || v->type->kind != TK::FunctionBlock || ownsEnEno(v->type)) return false;
    }
    slot.loc = member.loc;
    out = checkExpr(slot);
    if (instance.kind != ast::ExprKind::Name && (!out.ok || out.type->kind != TK::Bool)) return false;
    out.readOnly = true;  // an output of the block, as `inst.Q`
    return true;
}

exec::Stmt* Checker::callFunctionBlockEnEno(Checked inst, const ast::Expr& e) {
    EnEnoParts parts;
    if (!splitEnEno(e, parts)) return nullptr;
    const ast::Expr& call = *parts.call;
    const ast::Arg* eno = parts.eno;
    exec::Expr* temp = parts.temp;
    exec::Stmt* storeEn = parts.storeEn;
    const Type* boolType = types().elementary(TK::Bool);

    exec::Stmt* body = callFunctionBlock(inst, call);
    if (!body) return nullptr;
    Checked flag;
    flag.ok = true;
    flag.type = boolType;
    flag.node = temp;  // the temporary EN was written to
    std::vector<exec::Stmt*> storeEno;
    if (eno && eno->value) {
        flag.loc = eno->value->loc;
        Checked target = checkExpr(*eno->value);
        exec::Stmt* st = target.ok ? assignChecked(target, flag, eno->value->loc) : nullptr;
        if (!st) return nullptr;
        storeEno.push_back(st);
    }
    if (ast::Expr slot; !e.kids.empty() && fbEnoSlotPath(*e.kids[0], slot)) {
        slot.loc = e.loc;
        flag.loc = e.loc;
        Checked place = checkExpr(slot);
        place.readOnly = false;
        if (exec::Stmt* st = place.ok ? assignChecked(place, flag, e.loc) : nullptr) storeEno.push_back(st);
    }
    return pool().make<exec::FbEnEnoStmt>(storeEn, temp, body, std::move(storeEno));
}

}  // namespace strun::sema
