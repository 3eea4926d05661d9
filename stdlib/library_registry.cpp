#include "stdlib/library_registry.h"

#include <algorithm>
#include <cctype>

namespace strun::stdlib {

namespace {

std::string upperOf(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

std::span<const LibraryName> libraryNamesFor(std::string_view name) {
    const std::string key = upperOf(name);
    const auto all = libraryNames();
    auto range = std::equal_range(all.begin(), all.end(), key, [](const auto& a, const auto& b) {
        if constexpr (std::is_same_v<std::decay_t<decltype(a)>, LibraryName>) return a.upper < std::string_view(b);
        else return std::string_view(a) < b.upper;
    });
    return {range.first, range.second};
}

const LibraryInfo* findLibrary(std::string_view name) {
    const std::string key = upperOf(name);
    for (const LibraryInfo& l : libraries())
        if (upperOf(l.name) == key) return &l;
    return nullptr;
}

std::string libraryHint(std::string_view name) {
    // Not a library's: TwinCAT generates these lists from the project's event classes (decision 0372).
    if (const std::string upper = upperOf(name); upper == "TC_EVENTS" || upper == "TC_EVENT_CLASSES")
        return "'" + std::string(name) + "' is generated from the project's event classes: strun makes it when the TwinCAT project "
               "folder is given whole and its .tsproj or .tmc files declare event classes (docs/libraries.md)";
    // `FILE.DirOpen`: the library's own name after its namespace.
    if (libraryNamesFor(name).empty() && name.rfind('.') != std::string_view::npos) name = name.substr(name.rfind('.') + 1);
    for (const LibraryName& n : libraryNamesFor(name)) {
        if (n.library.empty()) continue;
        const LibraryInfo* lib = findLibrary(n.library);
        std::string hint = "'" + std::string(n.written) + "' comes from library " + std::string(n.library);
        if (n.kind == 'U' || (lib && lib->status == "absent"))
            return hint + ", which strun does not provide (docs/libraries.md lists what it provides)";
        return hint;
    }
    return "";
}

}  // namespace strun::stdlib
