// AST expressions strun writes itself rather than parses: the checker builds
// statements from declarations (run-time initial values, a generic block's
// constants) and needs literals and names for them.
#pragma once

#include <cstdint>
#include <string>

#include "interpreter/ast/ast.h"

namespace strun::ast {

// An integer literal with `value`; a negative value is the literal of its
// magnitude under a unary minus, as the parser builds `-5`.
ExprPtr integerExpr(int64_t value, const Loc& loc);
// A plain name, as written in code.
ExprPtr nameExpr(const std::string& name, const Loc& loc);

}  // namespace strun::ast
