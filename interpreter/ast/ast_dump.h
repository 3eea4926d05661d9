// Compact one-line text forms of AST expressions, statements and types, for
// tests and debugging: `a + b * c` -> "(+ a (* b c))".
#pragma once

#include <string>

#include "interpreter/ast/ast.h"

namespace strun::ast {

// Literal: its text (typed: "INT#-5"); Name: the name; Member "(. x a)";
// Index "([] a i j)"; Deref "(^ p)"; Call "(call f 1 a:=2 q=>v NOT q=>w)";
// Unary "(neg x)" "(plus x)" "(not x)"; Binary "(op a b)" with op as written
// in ST (+ - * / MOD ** = <> < <= > >= AND OR XOR AND_THEN OR_ELSE);
// THIS, SUPER.
std::string dump(const Expr& e);

// Assign "(:= x 1)", "(S= x c)", "(R= ..)", "(?= ..)", "(REF= ..)";
// Call "(call-stmt (call f))"; If "(if c1 {..} c2 {..} else {..})";
// Case "(case x [1,2..3: {..}] else {..})"; For "(for i a b by {..})";
// While "(while c {..})"; Repeat "(repeat {..} c)"; Exit/Continue/Return;
// Jmp "(jmp l)"; Label "(label l)"; Empty ";". A block is "{s1 s2}".
std::string dump(const Stmt& s);
std::string dump(const StmtList& list);

// Named "INT"; String "STRING[n]"/"WSTRING"; Array "ARRAY[1..3,*] OF INT";
// Pointer "POINTER TO T"; Reference "REFERENCE TO T"; Subrange "INT(0..100)";
// Enum "(a,b:=5) INT"; Struct "STRUCT(a:INT;b:REAL)".
std::string dump(const TypeSpec& t);

// Expr: its expression; Array "[3(0),1]"; Struct "(a:=1,b:=[1,2])".
std::string dump(const Init& i);

}  // namespace strun::ast
