// Deep copies of AST expressions, for the few places that rebuild a call
// from declaration text (CODESYS FB_init arguments written on a declaration).
#pragma once

#include "interpreter/ast/ast.h"

namespace strun::ast {

ExprPtr cloneExpr(const Expr& e);
Arg cloneArg(const Arg& a);

}  // namespace strun::ast
