// Source text -> AST for one file: the scanner (st_scanner.h) makes the
// tokens, the parser generated from grammar/STParser.g4 the parse tree, and
// ast_builder the AST. Syntax errors go to
// the CompileLog with file:line:col and what was expected; parsing recovers
// and reports further errors. Never throws.
#pragma once

#include <cstddef>
#include <vector>

#include "interpreter/ast/ast.h"
#include "interpreter/ast/parse_in_halves.h"
#include "interpreter/source/source_set.h"

namespace strun::ast {

// Tokens of one file (comments and pragmas included); past it the file is
// rejected with an error (docs/limits.md).
inline constexpr std::size_t kMaxTokensPerFile = 2000000;

// A file of at least `halvesFrom` tokens that parses cleanly is parsed in
// two halves on two threads (parse_in_halves.h); the result is the same.
CompilationUnit parseFile(const SourceSet& sources, int fileIndex, CompileLog& log,
                          std::size_t halvesFrom = kTokensToParseInHalves);

// parseFile of each of `files`, two at a time on two threads; the units and
// the messages come in the order of `files`, as from one parseFile after
// the other.
std::vector<CompilationUnit> parseFiles(const SourceSet& sources, const std::vector<int>& files, CompileLog& log);

}  // namespace strun::ast
