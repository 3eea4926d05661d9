// Source bytes -> valid UTF-8 for the scanner (and for the ANTLR runtime,
// whose UTF-8 conversion throws on malformed input, where tests run the
// generated lexer): a source file may hold anything, so it is made valid first.
#pragma once

#include <string>

namespace strun::ast {

// Returns `bytes` with a leading UTF-8 byte-order mark removed and every byte
// that is not part of a well-formed UTF-8 sequence (RFC 3629: no overlongs,
// no surrogates, at most U+10FFFF) replaced by U+FFFD. Such a character is
// then reported by the scanner as an unexpected character where it occurs.
// `firstInvalid` (optional) receives the offset in the result of the first
// replacement character inserted, `invalidCount` how many were inserted.
std::string sanitizeUtf8(const std::string& bytes, size_t* firstInvalid = nullptr, size_t* invalidCount = nullptr);

}  // namespace strun::ast
