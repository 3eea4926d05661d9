#include "interpreter/project/library_selection.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <string>

#include "interpreter/sema/types.h"
#include "stdlib/library_registry.h"

namespace strun::project {

namespace {

// Character classes of the word scan: 1 starts a word, 2 continues one
// (digits), 0 neither. A table, because the scan sees every byte of the
// project and of the selected library files at every start.
constexpr std::array<unsigned char, 256> kWordClass = [] {
    std::array<unsigned char, 256> table{};
    for (int c = 'A'; c <= 'Z'; ++c) table[c] = table[c + ('a' - 'A')] = 1;
    table['_'] = 1;
    for (int c = '0'; c <= '9'; ++c) table[c] = 2;
    return table;
}();

// Calls f(word, end) for every identifier-shaped word of the text (end: the
// offset just after it).
template <typename F>
void forEachWord(std::string_view text, F&& f) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    size_t i = 0;
    const size_t n = text.size();
    while (i < n) {
        const unsigned char kind = kWordClass[bytes[i]];
        if (kind == 0) {
            ++i;
            continue;
        }
        const size_t start = i;
        while (i < n && kWordClass[bytes[i]] != 0) ++i;
        // A digit run (16#FF, 2.5E3) is no name: skipped whole.
        if (kind == 1) f(text.substr(start, i - start), i);
    }
}

// A registry row that selects something: a declaration in an embedded file
// or a native function. Rows of names strun does not provide select nothing.
bool selects(const stdlib::LibraryName& n) { return n.kind != 'U'; }

// A qualified_only namespace (kind Q: CAA, FILE) is used only as `NS.x`, so
// its name selects its file only where a '.' and a name follow it: "the
// file" in a comment does not load CAA File (decision 0323).
bool qualifiedUse(std::string_view text, size_t end) {
    while (end < text.size() && (text[end] == ' ' || text[end] == '\t')) ++end;
    return end + 1 < text.size() && text[end] == '.' && kWordClass[static_cast<unsigned char>(text[end + 1])] == 1;
}

// Bit L of [c]: some selecting name of length L (< 64) starts (ends) with
// the letter c in either case. Most words of a program fail this test, and
// then need no upper-casing and lookup. The tables are generated with the
// registry (stdlib/library_registry.h): nothing is built at start-up.
struct NameMasks {
    std::span<const uint64_t, 256> byFirst = stdlib::libraryNameMasksByFirst();
    std::span<const uint64_t, 256> byLast = stdlib::libraryNameMasksByLast();
    bool mayBeName(std::string_view w) const {
        if (w.size() >= 64) return true;
        if (w.empty()) return false;
        const uint64_t bit = uint64_t{1} << w.size();
        return (byFirst[static_cast<unsigned char>(w.front())] & bit) != 0 && (byLast[static_cast<unsigned char>(w.back())] & bit) != 0;
    }
};

// The registry rows of an upper-case word (the registry is sorted by it).
std::pair<const stdlib::LibraryName*, const stdlib::LibraryName*> rowsOf(std::string_view upperWord) {
    const auto all = stdlib::libraryNames();
    auto lo = std::lower_bound(all.begin(), all.end(), upperWord, [](const stdlib::LibraryName& a, std::string_view w) { return a.upper < w; });
    auto hi = lo;
    while (hi != all.end() && hi->upper == upperWord) ++hi;
    return {&*all.begin() + (lo - all.begin()), &*all.begin() + (hi - all.begin())};
}

}  // namespace

LibrarySelection selectLibraries(const std::vector<std::string_view>& projectTexts) {
    const auto& sources = stdlib::embeddedSources();
    const NameMasks masks;
    std::vector<bool> selected(sources.size(), false);
    std::vector<size_t> toScan;  // selected files whose own mentions are not yet followed
    LibrarySelection out;
    std::string folded;
    auto scan = [&](std::string_view text) {
        forEachWord(text, [&](std::string_view w, size_t end) {
            // `x : BOOL R_EDGE;` is checked as a hidden R_TRIG (F_EDGE: F_TRIG; decision 0339).
            if (w.size() == 6 && (w[0] == 'R' || w[0] == 'r' || w[0] == 'F' || w[0] == 'f') && (w[1] == '_')) {
                folded.assign(w);
                sema::upperInPlace(folded);
                if (folded == "R_EDGE") w = "R_TRIG";
                if (folded == "F_EDGE") w = "F_TRIG";
            }
            if (!masks.mayBeName(w)) return;
            folded.assign(w);
            sema::upperInPlace(folded);
            auto [first, last] = rowsOf(folded);
            for (const stdlib::LibraryName* n = first; n != last; ++n) {
                if (n->kind == 'X') {
                    if (std::find(out.nativeLibraries.begin(), out.nativeLibraries.end(), n->library) == out.nativeLibraries.end())
                        out.nativeLibraries.push_back(n->library);
                    continue;
                }
                if (!selects(*n) || n->file < 0) continue;
                if (n->kind == 'Q' && !qualifiedUse(text, end)) continue;
                const auto file = static_cast<size_t>(n->file);
                if (file < selected.size() && !selected[file]) {
                    selected[file] = true;
                    toScan.push_back(file);
                }
            }
        });
    };
    for (std::string_view text : projectTexts) scan(text);
    while (!toScan.empty()) {
        const size_t file = toScan.back();
        toScan.pop_back();
        scan(sources[file].text);
    }
    for (size_t i = 0; i < sources.size(); ++i)
        if (selected[i]) out.files.push_back(&sources[i]);
    return out;
}

std::vector<const stdlib::EmbeddedSource*> embeddedSourcesFor(const std::vector<std::string_view>& projectTexts) {
    return selectLibraries(projectTexts).files;
}

const LibraryNames& embeddedLibraryNames() {
    static const LibraryNames names = [] {
        LibraryNames built;
        for (const stdlib::LibraryName& n : stdlib::libraryNames()) {
            if (n.kind == 'F' || n.kind == 'X') built.functions.emplace_back(n.written);
            if (n.kind == 'B' || n.kind == 'I' || n.kind == 'T') built.types.emplace_back(n.written);
        }
        return built;
    }();
    return names;
}

}  // namespace strun::project
