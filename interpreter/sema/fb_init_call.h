// The calls strun writes for a block on its behalf: `FB_init(...)` with the
// arguments of a declaration `fb : FB_X(a := 1)` or of `__NEW(FB_X(1))`, and
// `FB_exit(...)`, as expressions for Checker::callUserFunction.
#pragma once

#include "interpreter/ast/ast.h"
#include "interpreter/sema/symbols.h"

namespace strun::sema {

// `name()` at `loc`, without arguments.
ast::Expr implicitMethodCall(const char* name, const ast::Loc& loc);

// `FB_init(...)` of `init` with the arguments written on `declSpec` (none when
// null); positional ones skip the two implicit inputs bInitRetains and
// bInCopyCode, as in CODESYS.
ast::Expr fbInitCall(const PouInfo& init, const ast::TypeSpec* declSpec, const ast::Loc& loc);

}  // namespace strun::sema
