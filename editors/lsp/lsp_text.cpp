#include "editors/lsp/lsp_text.h"

#include <cctype>

namespace strun::editors::lsp {

namespace {

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Bytes of the UTF-8 sequence led by `lead` (1 for a stray continuation byte).
size_t sequenceLength(unsigned char lead) {
    if (lead >= 0xF0) return 4;
    if (lead >= 0xE0) return 3;
    if (lead >= 0xC0) return 2;
    return 1;
}

}  // namespace

std::string pathOfUri(std::string_view uri) {
    constexpr std::string_view scheme = "file://";
    if (uri.size() < scheme.size()) return {};
    for (size_t i = 0; i < scheme.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(uri[i])) != scheme[i]) return {};
    std::string_view rest = uri.substr(scheme.size());
    // file://host/path: only the local host is ours.
    if (!rest.empty() && rest.front() != '/') {
        const size_t slash = rest.find('/');
        if (slash == std::string_view::npos) return {};
        rest = rest.substr(slash);
    }
    std::string path;
    for (size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == '%' && i + 2 < rest.size()) {
            const int hi = hexValue(rest[i + 1]), lo = hexValue(rest[i + 2]);
            if (hi >= 0 && lo >= 0) {
                path.push_back(static_cast<char>(hi * 16 + lo));
                i += 2;
                continue;
            }
        }
        if (rest[i] == '?' || rest[i] == '#') break;
        path.push_back(rest[i]);
    }
    return path;
}

std::string uriOfPath(std::string_view path) {
    static const char* hex = "0123456789ABCDEF";
    std::string uri = "file://";
    for (unsigned char c : path) {
        if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') uri.push_back(static_cast<char>(c));
        else {
            uri.push_back('%');
            uri.push_back(hex[c >> 4]);
            uri.push_back(hex[c & 15]);
        }
    }
    return uri;
}

std::string_view lineOf(std::string_view text, int line) {
    size_t start = 0;
    for (int l = 1; l < line; ++l) {
        const size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos) return {};
        start = nl + 1;
    }
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    if (end > start && text[end - 1] == '\r') --end;
    return text.substr(start, end - start);
}

int columnOfCharacter(std::string_view lineText, int character) {
    int units = 0, col = 1;
    size_t i = 0;
    while (i < lineText.size() && units < character) {
        const size_t n = sequenceLength(static_cast<unsigned char>(lineText[i]));
        units += n == 4 ? 2 : 1;
        i += n;
        ++col;
    }
    if (units < character) col += character - units;  // past the end of the line
    return col;
}

int characterOfColumn(std::string_view lineText, int col) {
    int units = 0;
    size_t i = 0;
    for (int c = 1; c < col; ++c) {
        if (i >= lineText.size()) { ++units; continue; }
        const size_t n = sequenceLength(static_cast<unsigned char>(lineText[i]));
        units += n == 4 ? 2 : 1;
        i += n;
    }
    return units;
}

size_t byteOfColumn(std::string_view lineText, int col) {
    size_t i = 0;
    for (int c = 1; c < col && i < lineText.size(); ++c) i += sequenceLength(static_cast<unsigned char>(lineText[i]));
    return i < lineText.size() ? i : lineText.size();
}

}  // namespace strun::editors::lsp
