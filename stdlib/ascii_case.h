// ASCII case folding, the way IEC 61131-3 compares names (identifiers and
// keywords are case-insensitive; only ASCII letters have a case there).
// Header-only: the build-time tool that embeds the library uses it too
// (stdlib/library_mentions.h).
#pragma once

#include <cstddef>
#include <string_view>

namespace strun::stdlib {

inline char upperAscii(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - ('a' - 'A')) : c; }

inline bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (upperAscii(a[i]) != upperAscii(b[i])) return false;
    return true;
}

}  // namespace strun::stdlib
