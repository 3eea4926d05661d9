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

}  // namespace strun::ast
