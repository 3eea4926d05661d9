// Parsing of IEC 61131-3 numeric and character-string literals exactly as
// written in source text (after the lexer has cut them out, and after the
// caller has removed a type prefix such as INT# or STRING#).
// Time, date and duration literals live in stdlib/time_literals.h.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "stdlib/result.h"

namespace strun::stdlib {

// Unsigned integer literal: decimal `123`, `1_000`, or based `2#1010_1010`,
// `8#17`, `16#FF`, `16#ff_ff`. Underscores only between digits (no leading,
// trailing or doubled one). Errors: no digits, a digit invalid for the base,
// a misplaced underscore, an unknown base, a value above 2^64-1. Stops at the
// first overflowing digit, so a literal of thousands of digits fails fast.
Result<uint64_t> parseIntegerLiteral(std::string_view text);

// Decimal integer with an optional leading '+' or '-' (as in INT#-5):
// -9223372036854775808 .. 9223372036854775807. Based literals are accepted
// without a sign only and must fit int64.
Result<int64_t> parseSignedIntegerLiteral(std::string_view text);

// Real literal: `1.5E-3`, `1.0`, `3e5`, `1_000.5`, `-2.5` (optional sign,
// underscores between digits, optional fraction, optional exponent; a plain
// integer is accepted as well). A value too large for double is an error;
// one too small rounds to 0.
Result<double> parseRealLiteral(std::string_view text);

// The ST literal of a text: `it's` -> `'it$'s'` (`"..."` when wide): `$`,
// the quote, newline, CR and tab escaped, other control bytes as $hh
// ($00hh when wide); everything else (UTF-8 text) as it is. What
// parseStringLiteral / parseWideStringLiteral read back.
std::string quoteStringLiteral(std::string_view text, bool wide = false);

// Single-byte string literal including its quotes: `'a$Nb'` -> "a\nb".
// Escapes (letters case-insensitive): $$ $' $" $L (LF) $N (newline = LF)
// $P (form feed) $R (CR) $T (tab) and $hh (two hex digits, one byte).
// Other bytes are kept as they are (UTF-8 text stays UTF-8 bytes).
// Errors: missing quotes, an unescaped `'` inside, a bad or cut-off escape.
Result<std::string> parseStringLiteral(std::string_view text);

// Double-byte string literal including its quotes: `"wide"`. Same escapes,
// but $hhhh takes four hex digits (one UTF-16 code unit). The source text is
// UTF-8 and becomes UTF-16 (characters above U+FFFF as surrogate pairs).
// A single-quoted literal is accepted too (for a STRING literal assigned to a
// WSTRING); its numeric escapes are then $hh.
// Errors as above, plus invalid UTF-8.
Result<std::u16string> parseWideStringLiteral(std::string_view text);

}  // namespace strun::stdlib
