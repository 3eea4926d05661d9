// What an editor service (strun lsp) learns from the checker: every checked
// expression with its type and, for a plain variable or member, the variable.
// The checker calls it only when one is set (Checker::setExprObserver), so
// `check` and `run` pay nothing for it.
#pragma once

#include "interpreter/ast/ast.h"
#include "interpreter/sema/symbols.h"

namespace strun::sema {

class ExprObserver {
public:
    virtual ~ExprObserver() = default;
    // After `e` was checked in the body of `pou` (null: a declaration's
    // initial value or a configuration) with the result `c`.
    virtual void checked(const ast::Expr& e, const Checked& c, const PouInfo* pou) = 0;
};

}  // namespace strun::sema
