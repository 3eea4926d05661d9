// Which words of a text select a library file (decisions 0150, 0220, 0421).
// One rule for both places that apply it: the build tool that computes which
// library files a library file needs (stdlib/embed_tool/embed_library.cpp,
// over the file's code without comments and strings), and the start-up scan
// of a project's texts (interpreter/project/library_selection.cpp). The scan
// is lexical: it may select a file a project does not need, never miss one
// it uses.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "stdlib/ascii_case.h"

namespace strun::stdlib::mentions {

// Character classes of the word scan: 1 starts a word, 2 continues one
// (digits), 0 neither. A table, because the scan sees every byte of the
// project at every start.
inline constexpr std::array<unsigned char, 256> kWordClass = [] {
    std::array<unsigned char, 256> table{};
    for (int c = 'A'; c <= 'Z'; ++c) table[c] = table[c + ('a' - 'A')] = 1;
    table['_'] = 1;
    for (int c = '0'; c <= '9'; ++c) table[c] = 2;
    return table;
}();

inline bool isWordStart(char c) { return kWordClass[static_cast<unsigned char>(c)] == 1; }

// A hash of the word's upper-case form (FNV-1a over the ASCII-folded
// bytes), reduced to kNameHashBits bits: the build tool sets the bit of
// every selecting name's, and the start-up scan looks a word up in the
// registry only when its bit is set (decision 0493). Most words that pass
// the letter masks (END_VAR, enable, timer, ...) fail here, at about four
// instructions a byte, instead of a copy, an upper-casing and a binary
// search of the registry each.
inline constexpr unsigned kNameHashBits = 16;
inline uint32_t foldedNameHash(std::string_view w) {
    uint32_t h = 2166136261u;
    for (char c : w) h = (h ^ static_cast<unsigned char>(upperAscii(c))) * 16777619u;
    return (h ^ (h >> kNameHashBits)) & ((uint32_t{1} << kNameHashBits) - 1);
}

// The set of those hashes, kNameHashBits bits in 64-bit words: one place
// for the bit's position, which the build tool sets and the scan reads.
inline void addNameHash(std::span<uint64_t> set, std::string_view w) {
    const uint32_t h = foldedNameHash(w);
    set[h / 64] |= uint64_t{1} << (h % 64);
}
inline bool mayBeInNameHashSet(std::span<const uint64_t> set, std::string_view w) {
    const uint32_t h = foldedNameHash(w);
    return (set[h / 64] >> (h % 64) & 1) != 0;
}

// The offset of the first character at or after `at` that is not a blank.
inline size_t skipBlanks(std::string_view text, size_t at) {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '\r' || text[at] == '\n')) ++at;
    return at;
}

// Calls f(word, end, afterUsing) for every identifier-shaped word of the
// text: end is the offset just after it, afterUsing whether it stands in a
// `USING A, B;` list. A digit run (16#FF, 2.5E3) is no name: skipped whole.
template <typename F>
void forEachWord(std::string_view text, F&& f) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    const size_t n = text.size();
    size_t usingListEnd = 0;  // the ';' that ends the last `USING` list
    size_t i = 0;
    while (i < n) {
        const unsigned char kind = kWordClass[bytes[i]];
        if (kind == 0) {
            ++i;
            continue;
        }
        const size_t start = i;
        while (i < n && kWordClass[bytes[i]] != 0) ++i;
        if (kind != 1) continue;
        const std::string_view word = text.substr(start, i - start);
        f(word, i, start < usingListEnd);
        if (word.size() == 5 && (word[0] == 'U' || word[0] == 'u') && equalsIgnoreCase(word, "USING")) {
            const size_t semicolon = text.find(';', i);
            usingListEnd = semicolon == std::string_view::npos ? n : semicolon;
        }
    }
}

// `x : BOOL R_EDGE;` is checked as a hidden R_TRIG (F_EDGE: F_TRIG; decision 0339).
inline std::string_view edgeBlock(std::string_view w) {
    if (w.size() == 6 && w[1] == '_') {
        if (equalsIgnoreCase(w, "R_EDGE")) return "R_TRIG";
        if (equalsIgnoreCase(w, "F_EDGE")) return "F_TRIG";
    }
    return w;
}

// Whether a namespace whose first name ends at offset `end` is used there.
// `rest` is the remainder of a dotted namespace's path ("DateTime" of
// System.DateTime, "" for CAA): the whole path written (blanks allowed around
// the dots, names in any case) is a use; an undotted one is used as `NS.x`;
// in a `USING` list a leading part of the path is a use too (`USING AxUnit;`
// reaches AxUnit.Assert as `Assert`).
inline bool namespaceUse(std::string_view text, size_t end, std::string_view rest, bool afterUsing) {
    const bool dotted = !rest.empty();
    size_t at = end;
    for (;;) {
        size_t dot = skipBlanks(text, at);
        const size_t name = dot < text.size() && text[dot] == '.' ? skipBlanks(text, dot + 1) : text.size();
        if (name >= text.size() || !isWordStart(text[name])) return afterUsing || (dotted && rest.empty());
        if (rest.empty()) return true;
        size_t nameEnd = name;
        while (nameEnd < text.size() && kWordClass[static_cast<unsigned char>(text[nameEnd])] != 0) ++nameEnd;
        const size_t restDot = rest.find('.');
        if (!equalsIgnoreCase(text.substr(name, nameEnd - name), rest.substr(0, restDot))) return false;
        rest = restDot == std::string_view::npos ? std::string_view{} : rest.substr(restDot + 1);
        at = nameEnd;
    }
}

// Whether the word just before `end` in `text`, found in the registry as a
// row of `kind` spelled `written`, selects that row's file (decision 0421):
//   F a function: only called, `NAME(` (blanks allowed): a variable, an
//     enumeration value or a state of the project named like one (`Failed`,
//     Tc3_Module's FAILED) does not load its library;
//   N a namespace, Q a qualified_only one (decision 0323) or a dotted one
//     (SIMATIC AX's `System.DateTime`, written so in the registry): only
//     where namespaceUse() says it is used; the names of an N namespace that
//     are reachable unqualified have rows of their own;
//   U a name strun does not provide: never; X (natives) select no file;
//   anything else (blocks, types, enumeration values, globals): always.
inline bool mentionSelects(char kind, std::string_view written, std::string_view text, size_t end, bool afterUsing) {
    switch (kind) {
        case 'F': {
            const size_t at = skipBlanks(text, end);
            return at < text.size() && text[at] == '(';
        }
        case 'N':
        case 'Q': {
            const size_t dot = written.find('.');
            return namespaceUse(text, end, dot == std::string_view::npos ? std::string_view{} : written.substr(dot + 1), afterUsing);
        }
        case 'U':
        case 'X': return false;
        default: return true;
    }
}

}  // namespace strun::stdlib::mentions
