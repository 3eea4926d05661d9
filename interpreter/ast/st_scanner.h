// The lexer strun runs: UTF-8 source text -> tokens, by hand.
//
// grammar/STLexer.g4 stays the definition of the tokens (their types, the
// parser's vocabulary) and the reference this scanner is tested against
// (tests/unit/ast/scanner_equivalence_test.cpp compares both on every source
// of the repository and on generated input). The generated ANTLR lexer cost a
// third of `strun check` and, through the deserialisation of its state
// machine at every process start, a seventh of a one-line run; this scanner
// reads each byte once (decision 0157).
//
// Same rules as the grammar: longest match, the earlier rule on a tie;
// whitespace and comments produce no token; pragmas go to the PRAGMAS channel
// and malformed input (stray characters, unterminated comments, strings and
// pragmas) to the ERRORS channel. Lines count from 1 and columns from 0 in
// code points, as ANTLR counts them; start and stop are byte offsets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace strun::ast {

struct ScannedToken {
    std::size_t type;       // STLexer token type (antlr4::Token::EOF for the last)
    std::uint32_t channel;  // DEFAULT, or STLexer::PRAGMAS / STLexer::ERRORS
    std::uint32_t start;    // byte offset of the first byte
    std::uint32_t stop;     // byte offset of the last byte (start - 1 when empty)
    std::uint32_t line;     // 1-based
    std::uint32_t column;   // 0-based, in code points
};

struct ScanResult {
    std::vector<ScannedToken> tokens;  // always ends with an EOF token
    bool overLimit = false;            // more than maxTokens tokens: scanning stopped there
    // Empty declarations (`x : INT;;` in a VAR block or STRUCT): the index of
    // each extra `;`, hidden from the parser and reported as one warning (decision 0276).
    std::vector<std::size_t> emptyDeclarations;
};

// `text` must be valid UTF-8 (ast/utf8_input.h makes it so) and shorter
// than 4 GiB. Tokens of every channel count towards maxTokens.
ScanResult scanSource(std::string_view text, std::size_t maxTokens);

// The token type of an identifier-shaped word: its keyword, else IDENTIFIER.
std::size_t keywordOrIdentifier(std::string_view word);

}  // namespace strun::ast
