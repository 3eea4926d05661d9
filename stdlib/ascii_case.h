// ASCII case folding, the way IEC 61131-3 compares names (identifiers and
// keywords are case-insensitive; only ASCII letters have a case there).
// Header-only: the build-time tool that embeds the library uses it too
// (stdlib/library_mentions.h).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace strun::stdlib {

inline char upperAscii(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - ('a' - 'A')) : c; }
inline char lowerAscii(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c + ('a' - 'A')) : c; }

// The text with a-z folded to A-Z (names and keywords are ASCII; other bytes unchanged).
inline std::string upperAscii(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = upperAscii(c);
    return out;
}
// The text with A-Z folded to a-z.
inline std::string lowerAscii(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = lowerAscii(c);
    return out;
}

inline bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (upperAscii(a[i]) != upperAscii(b[i])) return false;
    return true;
}

}  // namespace strun::stdlib
