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

// The FB_init methods an instance of `fb` runs, its EXTENDS chain's from the
// base down: TwinCAT and CODESYS run the base's first, then the derived one's
// (decision 0461).
std::vector<PouInfo*> fbInitChain(PouInfo* fb);

// A base block's FB_init called for a derived one's `derivedCall` (from
// fbInitCall): the arguments of the inputs the base declares. The derived
// FB_init repeats them and may add further ones, which the base does not get.
ast::Expr baseFbInitCall(const PouInfo& base, const ast::Expr& derivedCall);

}  // namespace strun::sema
