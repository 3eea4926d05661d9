#include "interpreter/project/library_selection.h"

#include "interpreter/sema/types.h"

#include <algorithm>
#include <string>
#include <unordered_set>

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

bool isIdentStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool isIdentPart(char c) { return isIdentStart(c) || (c >= '0' && c <= '9'); }

// Calls f(word) for every identifier-shaped word of the text.
template <typename F>
void forEachWord(std::string_view text, F&& f) {
    size_t i = 0;
    const size_t n = text.size();
    while (i < n) {
        if (!isIdentStart(text[i])) {
            // A digit run (16#FF, 2.5E3) is no name: skip it whole.
            if (text[i] >= '0' && text[i] <= '9')
                while (i < n && isIdentPart(text[i])) ++i;
            else
                ++i;
            continue;
        }
        size_t start = i;
        while (i < n && isIdentPart(text[i])) ++i;
        f(text.substr(start, i - start));
    }
}

// The names a library file declares: the word after each POU keyword (and
// after TYPE: library files declare one type per TYPE block), as written,
// with the keyword (upper case) that declares it.
struct Declared {
    std::string keyword, name;
};
std::vector<Declared> declaredWithKeyword(std::string_view text) {
    std::vector<Declared> out;
    static constexpr std::string_view kKeywords[] = {"FUNCTION_BLOCK", "FUNCTION", "INTERFACE", "PROGRAM", "NAMESPACE", "TYPE"};
    std::string_view keyword;
    std::string folded;
    forEachWord(text, [&](std::string_view word) {
        if (!keyword.empty()) {
            out.push_back({std::string(keyword), std::string(word)});
            keyword = {};
            return;
        }
        const std::string& w = upperInto(word, folded);
        for (std::string_view k : kKeywords)
            if (w == k) {
                keyword = k;
                break;
            }
    });
    return out;
}

std::vector<std::string> declaredNames(std::string_view text) {
    std::vector<std::string> names;
    for (const Declared& d : declaredWithKeyword(text)) names.push_back(upper(d.name));
    return names;
}

struct LibraryIndex {
    std::vector<std::vector<std::string>> declares;  // parallel to embeddedSources()
};

const LibraryIndex& libraryIndex() {
    static const LibraryIndex index = [] {
        LibraryIndex built;
        for (const auto& src : stdlib::embeddedSources()) built.declares.push_back(declaredNames(src.text));
        return built;
    }();
    return index;
}

}  // namespace

std::vector<const stdlib::EmbeddedSource*> embeddedSourcesFor(const std::vector<std::string_view>& projectTexts) {
    const auto& sources = stdlib::embeddedSources();
    const auto& index = libraryIndex();
    std::unordered_set<std::string> mentioned;
    std::string folded;
    auto collect = [&](std::string_view text) {
        forEachWord(text, [&](std::string_view w) { mentioned.insert(upperInto(w, folded)); });  // copies only new names
    };
    for (std::string_view text : projectTexts) collect(text);

    std::vector<bool> selected(sources.size(), false);
    for (bool grew = true; grew;) {
        grew = false;
        for (size_t i = 0; i < sources.size(); ++i) {
            if (selected[i]) continue;
            const auto& names = index.declares[i];
            if (std::any_of(names.begin(), names.end(), [&](const std::string& n) { return mentioned.count(n) > 0; })) {
                selected[i] = true;
                collect(sources[i].text);
                grew = true;
            }
        }
    }
    std::vector<const stdlib::EmbeddedSource*> out;
    for (size_t i = 0; i < sources.size(); ++i)
        if (selected[i]) out.push_back(&sources[i]);
    return out;
}

const LibraryNames& embeddedLibraryNames() {
    static const LibraryNames names = [] {
        LibraryNames built;
        for (const auto& src : stdlib::embeddedSources())
            for (const Declared& d : declaredWithKeyword(src.text)) {
                if (d.keyword == "FUNCTION") built.functions.push_back(d.name);
                if (d.keyword == "FUNCTION_BLOCK" || d.keyword == "INTERFACE" || d.keyword == "TYPE") built.types.push_back(d.name);
            }
        return built;
    }();
    return names;
}

}  // namespace strun::project
