#include "interpreter/project/library_selection.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include "interpreter/sema/types.h"
#include "stdlib/library_mentions.h"
#include "stdlib/library_registry.h"

namespace strun::project {

namespace {

namespace mentions = stdlib::mentions;

// Bit L of [c]: some selecting name of length L (< 64) starts (ends) with
// the letter c in either case; and the bit of the word's folded hash in the
// set of the names' (decision 0493). Nearly every word of a program fails
// one of the two tests, and then needs no upper-casing and lookup. The
// tables are generated with the registry (stdlib/library_registry.h):
// nothing is built at start-up.
struct NameMasks {
    std::span<const uint64_t, 256> byFirst = stdlib::libraryNameMasksByFirst();
    std::span<const uint64_t, 256> byLast = stdlib::libraryNameMasksByLast();
    std::span<const uint64_t> hashSet = stdlib::libraryNameHashSet();
    bool mayBeName(std::string_view w) const {
        if (w.empty()) return false;
        if (w.size() < 64) {
            const uint64_t bit = uint64_t{1} << w.size();
            if ((byFirst[static_cast<unsigned char>(w.front())] & bit) == 0 || (byLast[static_cast<unsigned char>(w.back())] & bit) == 0) return false;
        }
        return mentions::mayBeInNameHashSet(hashSet, w);
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
    std::vector<size_t> toFollow;  // selected files whose own uses are not yet followed
    LibrarySelection out;
    auto addNatives = [&](std::string_view library) {
        if (std::find(out.nativeLibraries.begin(), out.nativeLibraries.end(), library) == out.nativeLibraries.end())
            out.nativeLibraries.push_back(library);
    };
    auto select = [&](size_t file) {
        if (file < selected.size() && !selected[file]) {
            selected[file] = true;
            toFollow.push_back(file);
        }
    };
    std::string folded;
    for (std::string_view text : projectTexts)
        mentions::forEachWord(text, [&](std::string_view w, size_t end, bool afterUsing) {
            w = mentions::edgeBlock(w);
            if (!masks.mayBeName(w)) return;
            folded.assign(w);
            sema::upperInPlace(folded);
            auto [first, last] = rowsOf(folded);
            for (const stdlib::LibraryName* n = first; n != last; ++n) {
                if (n->kind == 'X') addNatives(n->library);
                else if (n->file >= 0 && mentions::mentionSelects(n->kind, n->written, text, end, afterUsing)) select(static_cast<size_t>(n->file));
            }
        });
    // What the selected library files need was found at build time.
    while (!toFollow.empty()) {
        const size_t file = toFollow.back();
        toFollow.pop_back();
        for (int used : stdlib::libraryFileUses(file)) select(static_cast<size_t>(used));
        for (std::string_view library : stdlib::libraryFileNatives(file)) addNatives(library);
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
