// The scanner (interpreter/ast/st_scanner.h) against the lexer ANTLR
// generates from grammar/STLexer.g4, the definition of the tokens
// (decision 0157): used by the unit test on the repository's sources and by
// the fuzz target on every input it tries.
#pragma once

#include <optional>
#include <string>

namespace strun::fuzz {

// The first difference between the two token lists (type, channel, text,
// line, column) of `text`, which must be valid UTF-8; nullopt when equal.
std::optional<std::string> scannerDifference(const std::string& text);

}  // namespace strun::fuzz
