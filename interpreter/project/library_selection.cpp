#include "interpreter/project/library_selection.h"

#include "interpreter/sema/types.h"
#include "stdlib/number_scan.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <cstdint>
#include <unordered_map>

namespace strun::project {

namespace {

// One case folding for the whole checker (sema/types.h).
std::string upper(std::string_view s) { return sema::upper(std::string(s)); }

// The same folding into a buffer the caller reuses: the scans below see every
// word of the selected sources, and a string per word was the largest part
// of a one-line run's start-up (decision 0156).
const std::string& upperInto(std::string_view word, std::string& buffer) {
    buffer.assign(word);
    sema::upperInPlace(buffer);
    return buffer;
}

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

// Calls f(word) for every identifier-shaped word of the text.
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
        if (kind == 1) f(text.substr(start, i - start));
    }
}

// The names a library file declares: the word after each POU keyword (and
// after TYPE: library files declare one type per TYPE block), as written,
// with the keyword (upper case) that declares it.
struct Declared {
    std::string_view keyword, name;
};

std::vector<Declared> declaredWithKeyword(std::string_view text) {
    std::vector<Declared> out;
    static constexpr std::string_view kKeywords[] = {"FUNCTION_BLOCK", "FUNCTION", "INTERFACE", "PROGRAM", "NAMESPACE", "TYPE"};
    std::string_view keyword;
    forEachWord(text, [&](std::string_view word) {
        if (!keyword.empty()) {
            out.push_back({keyword, word});
            keyword = {};
            return;
        }
        for (std::string_view k : kKeywords)
            if (word.size() == k.size() && stdlib::equalsIgnoreCase(word, k)) {
                keyword = k;
                break;
            }
    });
    return out;
}

// Built once per process from one scan of the embedded texts.
struct LibraryIndex {
    std::vector<std::vector<Declared>> declares;                         // parallel to embeddedSources()
    std::unordered_map<std::string, std::vector<size_t>> filesDeclaring;  // upper-case name -> files
    // Bit L of [c]: some name of length L (< 64) starts (ends) with the
    // letter c in either case. Most words of a program fail this test, and
    // then need no upper-casing and hashing.
    uint64_t lengthsByFirst[256] = {};
    uint64_t lengthsByLast[256] = {};

    bool mayBeName(std::string_view w) const {
        if (w.size() >= 64) return true;  // not in the masks: looked up
        if (w.empty()) return false;
        const uint64_t bit = uint64_t{1} << w.size();
        return (lengthsByFirst[static_cast<unsigned char>(w.front())] & bit) != 0 &&
               (lengthsByLast[static_cast<unsigned char>(w.back())] & bit) != 0;
    }
};

const LibraryIndex& libraryIndex() {
    static const LibraryIndex index = [] {
        LibraryIndex built;
        const auto& sources = stdlib::embeddedSources();
        for (size_t i = 0; i < sources.size(); ++i) {
            built.declares.push_back(declaredWithKeyword(sources[i].text));
            for (const Declared& d : built.declares.back()) {
                std::vector<size_t>& files = built.filesDeclaring[upper(d.name)];
                if (files.empty() || files.back() != i) files.push_back(i);
                if (d.name.empty() || d.name.size() >= 64) continue;  // such words are always looked up
                const uint64_t bit = uint64_t{1} << d.name.size();
                for (int c : {std::toupper(static_cast<unsigned char>(d.name.front())),
                              std::tolower(static_cast<unsigned char>(d.name.front()))})
                    built.lengthsByFirst[static_cast<unsigned char>(c)] |= bit;
                for (int c : {std::toupper(static_cast<unsigned char>(d.name.back())),
                              std::tolower(static_cast<unsigned char>(d.name.back()))})
                    built.lengthsByLast[static_cast<unsigned char>(c)] |= bit;
            }
        }
        return built;
    }();
    return index;
}

}  // namespace

std::vector<const stdlib::EmbeddedSource*> embeddedSourcesFor(const std::vector<std::string_view>& projectTexts) {
    const auto& sources = stdlib::embeddedSources();
    const LibraryIndex& index = libraryIndex();
    std::vector<bool> selected(sources.size(), false);
    std::vector<size_t> toScan;  // selected files whose own mentions are not yet followed
    std::string folded;
    auto scan = [&](std::string_view text) {
        forEachWord(text, [&](std::string_view w) {
            if (!index.mayBeName(w)) return;
            const auto it = index.filesDeclaring.find(upperInto(w, folded));
            if (it == index.filesDeclaring.end()) return;
            for (size_t file : it->second)
                if (!selected[file]) {
                    selected[file] = true;
                    toScan.push_back(file);
                }
        });
    };
    for (std::string_view text : projectTexts) scan(text);
    while (!toScan.empty()) {
        const size_t file = toScan.back();
        toScan.pop_back();
        scan(sources[file].text);
    }
    std::vector<const stdlib::EmbeddedSource*> out;
    for (size_t i = 0; i < sources.size(); ++i)
        if (selected[i]) out.push_back(&sources[i]);
    return out;
}

const LibraryNames& embeddedLibraryNames() {
    static const LibraryNames names = [] {
        LibraryNames built;
        for (const auto& declared : libraryIndex().declares)
            for (const Declared& d : declared) {
                if (d.keyword == "FUNCTION") built.functions.emplace_back(d.name);
                if (d.keyword == "FUNCTION_BLOCK" || d.keyword == "INTERFACE" || d.keyword == "TYPE") built.types.emplace_back(d.name);
            }
        return built;
    }();
    return names;
}

}  // namespace strun::project
