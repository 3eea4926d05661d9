#include "interpreter/ast/synthesized_expr.h"

namespace strun::ast {

ExprPtr integerExpr(int64_t value, const Loc& loc) {
    auto lit = std::make_unique<Expr>();
    lit->kind = ExprKind::Literal;
    lit->lit = LitKind::Integer;
    lit->loc = loc;
    // The magnitude in unsigned arithmetic: -LINT#-9223372036854775808 has no signed value.
    const uint64_t magnitude = value < 0 ? 0 - static_cast<uint64_t>(value) : static_cast<uint64_t>(value);
    lit->text = std::to_string(magnitude);
    if (value >= 0) return lit;
    auto neg = std::make_unique<Expr>();
    neg->kind = ExprKind::Unary;
    neg->op = Op::Neg;
    neg->loc = loc;
    neg->kids.push_back(std::move(lit));
    return neg;
}

ExprPtr nameExpr(const std::string& name, const Loc& loc) {
    auto e = std::make_unique<Expr>();
    e->kind = ExprKind::Name;
    e->loc = loc;
    e->name = name;
    return e;
}

}  // namespace strun::ast
