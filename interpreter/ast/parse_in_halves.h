// A large file parsed as two halves on two threads, each half a run of whole
// top-level declarations (decision 0159).
//
// Only the fast path: each half is parsed with SLL prediction and no error
// recovery, and its AST built with a log of its own. If either half has a
// syntax error or the builder reports anything, the result is empty and the
// caller parses the whole file as usual, so that messages never depend on
// where a file was split.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "interpreter/ast/ast.h"
#include "interpreter/ast/st_scanner.h"

namespace strun::ast {

// Files with fewer tokens are parsed in one piece: below this (about 8 000
// lines), a second thread costs more than the half of the parse it saves.
inline constexpr std::size_t kTokensToParseInHalves = 40000;

// `tokens`: the file's tokens as parse.cpp hands them to the parser (ACTION
// resolved), ending with EOF; `text`: the file's (valid UTF-8) text.
// Empty when the file has no split point between top-level declarations
// near its middle, or when a half does not parse cleanly. (parseFile calls
// it for files of at least kTokensToParseInHalves tokens.)
std::optional<CompilationUnit> parseInHalves(std::string_view text, const std::vector<ScannedToken>& tokens, int fileIndex);

}  // namespace strun::ast
