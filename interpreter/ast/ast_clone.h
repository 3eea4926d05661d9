// Deep copies of AST parts: expressions, for the few places that rebuild a
// call from declaration text (CODESYS FB_init arguments written on a
// declaration), and whole POUs, for the specialisations of a block with
// VAR_GENERIC CONSTANTs (one copy per set of values, decision 0312).
#pragma once

#include "interpreter/ast/ast.h"

namespace strun::ast {

ExprPtr cloneExpr(const Expr& e);
Arg cloneArg(const Arg& a);
TypeSpecPtr cloneTypeSpec(const TypeSpec& t);
InitPtr cloneInit(const Init& i);
VarDecl cloneVarDecl(const VarDecl& d);
VarBlock cloneVarBlock(const VarBlock& b);
StmtPtr cloneStmt(const Stmt& s);
std::unique_ptr<Pou> clonePou(const Pou& p);

}  // namespace strun::ast
