// UTF-8 <-> UTF-16 transcoding for WSTRING values (source text and JSON are
// UTF-8, WSTRING holds UTF-16 code units).
#pragma once

#include <string>
#include <string_view>

#include "stdlib/result.h"

namespace strun::stdlib {

// Error on malformed UTF-8 (bad lead/continuation byte, overlong form,
// encoded surrogate, code point above U+10FFFF, truncated sequence).
Result<std::u16string> utf8ToUtf16(std::string_view utf8);

// Never fails: an unpaired surrogate becomes U+FFFD.
std::string utf16ToUtf8(std::u16string_view utf16);

// A STRING's bytes as UTF-8 text (for JSON and for STRING_TO_WSTRING): bytes
// that already form valid UTF-8 are kept; otherwise every byte is read as
// Latin-1 (ISO 8859-1), the CODESYS single-byte character set.
std::string bytesToUtf8(std::string_view bytes);

// STRING_TO_WSTRING: bytesToUtf8, then UTF-16.
std::u16string stringToWString(std::string_view bytes);
// WSTRING_TO_STRING: UTF-8 bytes (ASCII stays one byte per character; an
// unpaired surrogate becomes U+FFFD). Round-trips with stringToWString.
std::string wstringToString(std::u16string_view utf16);

// Appends the UTF-8 encoding of one code point (<= U+10FFFF, not a surrogate).
void appendUtf8(std::string& out, char32_t codePoint);

}  // namespace strun::stdlib
