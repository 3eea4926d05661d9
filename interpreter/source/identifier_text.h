// Whether a text read from a project file (an XML element's content or
// attribute) can be written back into generated ST as a name: letters,
// digits and '_', not starting with a digit, at most 127 characters.
#pragma once

#include <algorithm>
#include <cctype>
#include <string_view>

namespace strun::source {

inline bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

inline bool isPlainIdentifier(std::string_view s) {
    if (s.empty() || s.size() > 127 || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
    return std::all_of(s.begin(), s.end(), isIdentifierChar);
}

}  // namespace strun::source
