#include "interpreter/project/missing_libraries.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <string_view>

#include "stdlib/number_scan.h"

namespace strun::project {

namespace {

// The name and library of a help line "'NAME' comes from library LIB, which
// strun does not provide" (Checker::suggest, stdlib::libraryHint); false for
// any other line. Scanned by hand rather than with <regex> (decision 0491).
bool parseLibraryHint(std::string_view h, std::string_view& name, std::string_view& lib) {
    constexpr std::string_view kComesFrom = "' comes from library ";
    constexpr std::string_view kNotProvided = ", which strun does not provide";
    if (h.size() < 2 || h[0] != '\'') return false;
    const size_t close = h.find('\'', 1);
    if (close == std::string_view::npos || close == 1 || h.substr(close, kComesFrom.size()) != kComesFrom) return false;
    name = h.substr(1, close - 1);
    const size_t libStart = close + kComesFrom.size();
    size_t libEnd = libStart;
    while (libEnd < h.size() && (std::isalnum(static_cast<unsigned char>(h[libEnd])) || h[libEnd] == '_')) ++libEnd;
    if (libEnd == libStart || h.substr(libEnd, kNotProvided.size()) != kNotProvided) return false;
    lib = h.substr(libStart, libEnd - libStart);
    return true;
}

// The library a name error is about, as its help line says, when the
// project references it; "" otherwise.
std::string missingLibraryOf(const Diagnostic& d, const std::vector<std::string>& referenced, std::string* name) {
    if (d.severity != Severity::Error) return "";
    for (const std::string& h : d.help) {
        std::string_view hintName, hintLib;
        if (!parseLibraryHint(h, hintName, hintLib)) continue;
        for (const std::string& lib : referenced)
            if (stdlib::equalsIgnoreCase(lib, hintLib)) {
                if (name) *name = std::string(hintName);
                return lib;
            }
    }
    return "";
}

}  // namespace

void groupMissingLibraryNames(CompileLog& log, const std::vector<std::string>& referenced) {
    if (referenced.empty()) return;
    struct Group {
        ast::Loc loc;
        std::string code;
        std::vector<std::string> names;
    };
    std::vector<std::pair<std::string, Group>> groups;  // in the order of their first error
    for (const Diagnostic& d : log.messages()) {
        std::string name;
        const std::string lib = missingLibraryOf(d, referenced, &name);
        if (lib.empty()) continue;
        auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == lib; });
        if (it == groups.end()) {
            groups.push_back({lib, Group{d.loc, d.code, {}}});
            it = groups.end() - 1;
        }
        auto& names = it->second.names;
        if (std::none_of(names.begin(), names.end(), [&](const std::string& n) { return stdlib::equalsIgnoreCase(n, name); })) names.push_back(name);
    }
    if (groups.empty()) return;
    log.eraseIf([&](const Diagnostic& d) { return !missingLibraryOf(d, referenced, nullptr).empty(); });
    constexpr size_t kNamesShown = 8;
    for (const auto& [lib, g] : groups) {
        std::string list;
        for (size_t k = 0; k < g.names.size() && k < kNamesShown; ++k) list += (k ? ", " : "") + g.names[k];
        if (g.names.size() > kNamesShown) list += fmt::format(" and {} more", g.names.size() - kNamesShown);
        // The code of the first message it replaces (E0101 undeclared, E0102 unknown type, ...).
        log.error(diag::fromText(g.code).value_or(diag::E0101), g.loc,
                  fmt::format("library {} is not available: {} {} unknown", lib, list, g.names.size() == 1 ? "is" : "are"))
            .withHelp(fmt::format("the project's .plcproj references {}, which strun does not provide (docs/libraries.md lists "
                                  "what it provides)",
                                  lib));
    }
}

void explainPinnedTypes(CompileLog& log, const std::vector<std::string>& pinned) {
    if (pinned.empty()) return;
    log.decorate([&](Diagnostic& d) {
        if (d.code != diag::text(diag::E0102)) return;
        for (const std::string& type : pinned)
            if (stdlib::equalsIgnoreCase(d.message, "unknown type '" + type + "'")) {
                d.withHelp(fmt::format("'{}' is a global data type the project's .plcproj pins (<PinnedGlobalDataType>): TwinCAT "
                                       "keeps it in the solution's type system; give strun the solution folder (with the "
                                       ".tsproj) or the project's .tmc",
                                       type));
                return;
            }
    });
}

}  // namespace strun::project
