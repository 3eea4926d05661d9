#include "interpreter/ast/ast_clone.h"

namespace strun::ast {

ExprPtr cloneExpr(const Expr& e) {
    auto out = std::make_unique<Expr>();
    out->kind = e.kind;
    out->loc = e.loc;
    out->lit = e.lit;
    out->text = e.text;
    out->typePrefix = e.typePrefix;
    out->valueText = e.valueText;
    out->name = e.name;
    out->nameLoc = e.nameLoc;
    out->pointerTo = e.pointerTo;
    out->op = e.op;
    for (const auto& k : e.kids) out->kids.push_back(k ? cloneExpr(*k) : nullptr);
    for (const auto& a : e.args) out->args.push_back(cloneArg(a));
    return out;
}

Arg cloneArg(const Arg& a) {
    Arg out;
    out.loc = a.loc;
    out.name = a.name;
    out.output = a.output;
    out.negated = a.negated;
    out.value = a.value ? cloneExpr(*a.value) : nullptr;
    return out;
}

namespace {

template <typename T, typename F>
auto cloneOrNull(const std::unique_ptr<T>& p, F&& clone) -> decltype(clone(*p)) {
    return p ? clone(*p) : nullptr;
}

ExprPtr cloneExprOrNull(const ExprPtr& e) { return e ? cloneExpr(*e) : nullptr; }

StmtList cloneStmts(const StmtList& list) {
    StmtList out;
    out.reserve(list.size());
    for (const auto& s : list) out.push_back(s ? cloneStmt(*s) : nullptr);
    return out;
}

Property cloneProperty(const Property& p) {
    Property out;
    out.loc = p.loc;
    out.name = p.name;
    out.access = p.access;
    out.abstract = p.abstract;
    out.final = p.final;
    out.type = cloneOrNull(p.type, cloneTypeSpec);
    out.getter = cloneOrNull(p.getter, clonePou);
    out.setter = cloneOrNull(p.setter, clonePou);
    out.pragmas = p.pragmas;
    return out;
}

}  // namespace

TypeSpecPtr cloneTypeSpec(const TypeSpec& t) {
    auto out = std::make_unique<TypeSpec>();
    out->kind = t.kind;
    out->loc = t.loc;
    out->name = t.name;
    out->wide = t.wide;
    out->length = cloneExprOrNull(t.length);
    for (const Range& r : t.dims) out->dims.push_back(Range{cloneExprOrNull(r.lo), cloneExprOrNull(r.hi), r.star});
    out->elem = cloneOrNull(t.elem, cloneTypeSpec);
    out->lo = cloneExprOrNull(t.lo);
    out->hi = cloneExprOrNull(t.hi);
    for (const EnumValue& v : t.enumValues) out->enumValues.push_back(EnumValue{v.loc, v.name, cloneExprOrNull(v.value)});
    for (const VarDecl& f : t.fields) out->fields.push_back(cloneVarDecl(f));
    for (const Arg& a : t.initArgs) out->initArgs.push_back(cloneArg(a));
    for (const auto& element : t.elementInitArgs) {
        out->elementInitArgs.emplace_back();
        for (const Arg& a : element) out->elementInitArgs.back().push_back(cloneArg(a));
    }
    for (const ExprPtr& g : t.genericArgs) out->genericArgs.push_back(cloneExprOrNull(g));
    out->isUnion = t.isUnion;
    out->refTo = t.refTo;
    return out;
}

InitPtr cloneInit(const Init& i) {
    auto out = std::make_unique<Init>();
    out->kind = i.kind;
    out->loc = i.loc;
    out->expr = cloneExprOrNull(i.expr);
    for (const ArrayInitItem& item : i.items)
        out->items.push_back(ArrayInitItem{cloneExprOrNull(item.repeat), cloneOrNull(item.value, cloneInit), cloneOrNull(item.callForm, cloneInit)});
    for (const StructInitItem& f : i.fields) out->fields.push_back(StructInitItem{f.loc, f.name, cloneOrNull(f.value, cloneInit)});
    return out;
}

VarDecl cloneVarDecl(const VarDecl& d) {
    VarDecl out;
    out.loc = d.loc;
    out.names = d.names;
    out.nameLocs = d.nameLocs;
    out.address = d.address;
    out.type = cloneOrNull(d.type, cloneTypeSpec);
    out.init = cloneOrNull(d.init, cloneInit);
    out.pragmas = d.pragmas;
    out.accessPath = d.accessPath;
    out.readOnly = d.readOnly;
    out.edge = d.edge;
    return out;
}

VarBlock cloneVarBlock(const VarBlock& b) {
    VarBlock out;
    out.loc = b.loc;
    out.section = b.section;
    out.access = b.access;
    out.constant = b.constant;
    out.generic = b.generic;
    out.retain = b.retain;
    out.nonRetain = b.nonRetain;
    out.persistent = b.persistent;
    for (const VarDecl& d : b.vars) out.vars.push_back(cloneVarDecl(d));
    return out;
}

StmtPtr cloneStmt(const Stmt& s) {
    auto out = std::make_unique<Stmt>();
    out->kind = s.kind;
    out->loc = s.loc;
    out->target = cloneExprOrNull(s.target);
    out->expr = cloneExprOrNull(s.expr);
    out->name = s.name;
    out->nameLoc = s.nameLoc;
    out->from = cloneExprOrNull(s.from);
    out->to = cloneExprOrNull(s.to);
    out->by = cloneExprOrNull(s.by);
    for (const ExprPtr& c : s.conds) out->conds.push_back(cloneExprOrNull(c));
    for (const StmtList& b : s.blocks) out->blocks.push_back(cloneStmts(b));
    for (const CaseBranch& c : s.cases) {
        CaseBranch branch;
        branch.loc = c.loc;
        for (const CaseLabel& l : c.labels) branch.labels.push_back(CaseLabel{cloneExprOrNull(l.lo), cloneExprOrNull(l.hi)});
        branch.body = cloneStmts(c.body);
        out->cases.push_back(std::move(branch));
    }
    out->body = cloneStmts(s.body);
    if (s.elseBlock) out->elseBlock = cloneStmts(*s.elseBlock);
    return out;
}

std::unique_ptr<Pou> clonePou(const Pou& p) {
    auto out = std::make_unique<Pou>();
    out->kind = p.kind;
    out->loc = p.loc;
    out->endLoc = p.endLoc;
    out->name = p.name;
    out->nameLoc = p.nameLoc;
    out->nameSpace = p.nameSpace;
    out->returnType = cloneOrNull(p.returnType, cloneTypeSpec);
    out->access = p.access;
    out->abstract = p.abstract;
    out->final = p.final;
    out->override = p.override;
    out->extends = p.extends;
    for (const ExprPtr& g : p.extendsGenericArgs) out->extendsGenericArgs.push_back(cloneExprOrNull(g));
    out->extendsList = p.extendsList;
    out->implements = p.implements;
    for (const VarBlock& b : p.vars) out->vars.push_back(cloneVarBlock(b));
    out->body = cloneStmts(p.body);
    out->hasBody = p.hasBody;
    out->isAction = p.isAction;
    for (const auto& m : p.methods) out->methods.push_back(cloneOrNull(m, clonePou));
    for (const Property& prop : p.properties) out->properties.push_back(cloneProperty(prop));
    out->pragmas = p.pragmas;
    return out;
}

}  // namespace strun::ast
