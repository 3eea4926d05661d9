#include "interpreter/source/twincat_library_namespaces.h"

#include <cctype>
#include <filesystem>

#include "interpreter/source/project_inputs.h"
#include "stdlib/library_registry.h"
#include "stdlib/number_scan.h"

namespace strun::source {

namespace {

namespace fs = std::filesystem;

// Code can only write a namespace that is an identifier ("LCLS_General", not "LCLS General").
bool isIdentifier(const std::string& s) {
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
    for (unsigned char c : s)
        if (!std::isalnum(c) && c != '_') return false;
    return true;
}

// Whether a reference `Include="name"` names `p`: TwinCAT matches a
// placeholder by the library's title; projects also write its name.
bool names(const std::string& reference, const PlcProject& p) {
    return (!p.title.empty() && stdlib::equalsIgnoreCase(reference, p.title)) || (!p.name.empty() && stdlib::equalsIgnoreCase(reference, p.name)) ||
           (!p.defaultNamespace.empty() && stdlib::equalsIgnoreCase(reference, p.defaultNamespace));
}

// Whether strun provides the library `p` is a copy of (by title, name or
// namespace): a library of its registry, or TcUnit, which strun builds in
// (stdlib/st/tcunit.st, decision 0140).
bool providedByStrun(const PlcProject& p) {
    for (const std::string* n : {&p.title, &p.name, &p.defaultNamespace})
        if (!n->empty() && (stdlib::findLibrary(*n) || stdlib::equalsIgnoreCase(*n, "TcUnit"))) return true;
    return false;
}

// How deep `dir` is when `file` lies below it; -1 when it does not.
int depthBelow(const fs::path& file, const fs::path& dir) {
    const fs::path folder = dir.lexically_normal();
    const fs::path rel = file.lexically_normal().lexically_relative(folder);
    if (rel.empty() || *rel.begin() == "..") return -1;
    return static_cast<int>(std::distance(folder.begin(), folder.end()));
}

}  // namespace

void assignLibraryNamespaces(const std::vector<GivenPlcProject>& projects, std::vector<int>& userFiles, SourceSet& sources) {
    std::vector<std::string> spaces(projects.size());  // "" for a project no one references
    std::vector<bool> isLibrary(projects.size(), false);
    for (size_t lib = 0; lib < projects.size(); ++lib) {
        bool referenced = false;
        for (size_t user = 0; user < projects.size() && spaces[lib].empty(); ++user) {
            if (user == lib) continue;
            const PlcProject& p = projects[user].project;
            for (size_t k = 0; k < p.libraries.size(); ++k) {
                if (!names(p.libraries[k], projects[lib].project)) continue;
                referenced = true;
                sources.dropReferencedLibrary(p.libraries[k]);  // given: not missing
                if (k < p.libraryNamespaces.size() && isIdentifier(p.libraryNamespaces[k])) {
                    spaces[lib] = p.libraryNamespaces[k];
                    break;
                }
            }
        }
        if (referenced && spaces[lib].empty() && isIdentifier(projects[lib].project.defaultNamespace))
            spaces[lib] = projects[lib].project.defaultNamespace;
        // The project's own copy of a library strun provides (TcUnit's source
        // beside its verifier): its code replaces strun's at the top level,
        // as any project code does (decision 0454).
        if (providedByStrun(projects[lib].project)) spaces[lib].clear();
        isLibrary[lib] = referenced;
    }
    std::erase_if(userFiles, [&](int f) {
        const std::string& path = sources.file(f).path;
        if (!isTwinCatObject(path)) return false;
        // The deepest project folder holding the file is its project.
        int best = -1, bestDepth = -1;
        for (size_t k = 0; k < projects.size(); ++k) {
            const int depth = depthBelow(path, projects[k].folder);
            if (depth > bestDepth) best = static_cast<int>(k), bestDepth = depth;
        }
        if (best < 0) return false;
        // A library has no tasks of its own: the task objects of its project
        // folder (the test task its developers run it with) are not the application's.
        if (isLibrary[static_cast<size_t>(best)] && stdlib::lowerAscii(fs::path(path).extension().string()) == ".tctto") return true;
        if (!spaces[static_cast<size_t>(best)].empty()) sources.setLibraryNamespace(f, spaces[static_cast<size_t>(best)]);
        return false;
    });
}

}  // namespace strun::source
