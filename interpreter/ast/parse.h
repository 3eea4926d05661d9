// Source text -> AST for one file: the scanner (st_scanner.h) makes the
// tokens, the parser generated from grammar/STParser.g4 the parse tree, and
// ast_builder the AST. Syntax errors go to
// the CompileLog with file:line:col and what was expected; parsing recovers
// and reports further errors. Never throws.
#pragma once

#include <cstddef>

#include "interpreter/ast/ast.h"
#include "interpreter/source/source_set.h"

namespace strun::ast {

// Tokens of one file (comments and pragmas included); past it the file is
// rejected with an error (docs/limits.md).
inline constexpr std::size_t kMaxTokensPerFile = 2000000;

CompilationUnit parseFile(const SourceSet& sources, int fileIndex, CompileLog& log);

}  // namespace strun::ast
