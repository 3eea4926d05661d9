// Namespace scoping (decision 0325): the same type or POU name in two
// namespaces, as IEC 61131-3 Ed.3 and SIMATIC AX code write it
// (`NAMESPACE Simatic.Ax.StatePattern ... IState` beside
// `NAMESPACE Simatic.Ax.StateFramework ... IState`).
//
// strun resolves names flattened (decision 0094): a name is unique in the
// project and `Ns.X` finds `X`. That stays so for every name declared once.
// Only a contested name gets scoping: its namespaced declarations are renamed
// to their qualified name ("Simatic.Ax.StateFramework.IState") before they are
// declared, so everything keyed by a declaration's name works unchanged, and a
// name written in code is mapped to one of those keys from the namespace of the
// code that writes it (scopedKey).
#include <algorithm>

#include "interpreter/sema/checker.h"
#include "stdlib/library_registry.h"

namespace strun::sema {

Checker::NameScopeGuard::NameScopeGuard(Checker& c, const std::string& nameSpace, int file) : c_(c), saved_(c.nameScope_) {
    c_.nameScope_.nameSpace = upper(nameSpace);
    c_.nameScope_.file = file;
}

namespace {
struct Declared {
    std::string* name;
    const std::string* nameSpace;
    bool library;
};

// A namespace path whose outermost name is a qualified_only library
// namespace (CAA File's FILE, CAA Types' CAA; registry kind Q).
bool inQualifiedOnlyLibrary(const std::string& nameSpace) {
    if (nameSpace.empty()) return false;
    const std::string root = nameSpace.substr(0, nameSpace.find('.'));
    for (const stdlib::LibraryName& n : stdlib::libraryNamesFor(root))
        if (n.kind == 'Q') return true;
    return false;
}
}  // namespace

// A name is contested within the user's files, or within the library's, when
// it is declared under two different namespace paths (the top level counting
// as one), or when a namespaced declaration is named like a builtin function
// or an elementary type (CAA's `FILE.Delete` beside the standard DELETE). A user declaration named like a
// library one is not contested: it replaces the library's, as it always did
// (a project carrying TcUnit's own source).
void Checker::noteContestedNames(std::vector<ast::CompilationUnit>& units) {
    for (const auto& unit : units)
        for (const auto& u : unit.usings) usingsByFile_[unit.file].push_back(upper(u.nameSpace));
    std::map<std::string, std::vector<Declared>> byName;
    for (auto& unit : units) {
        const bool library = libraryFiles_.count(unit.file) != 0;
        for (auto& t : unit.types) byName[upper(t.name)].push_back({&t.name, &t.nameSpace, library});
        for (auto& p : unit.pous) byName[upper(p->name)].push_back({&p->name, &p->nameSpace, library});
    }
    for (auto& [simple, decls] : byName) {
        // A library declaration in a qualified_only namespace is reached only
        // qualified (FILE.ERROR, CAA.SIZE): a user declaration of that name
        // does not replace it; both stay, the library's under its qualified
        // name (decision 0324).
        const bool userDeclared = std::any_of(decls.begin(), decls.end(), [](const Declared& d) { return !d.library; });
        for (const Declared& d : decls) {
            if (!userDeclared || !d.library || !inQualifiedOnlyLibrary(*d.nameSpace)) continue;
            contested_[simple].insert(upper(*d.nameSpace));
            *d.name = *d.nameSpace + "." + *d.name;
        }
        // Being named like a builtin counts only for a namespaced declaration
        // (below); asked only then, so that a program without namespaces does
        // not build the builtin registry (decision 0478).
        const bool anyNamespaced = std::any_of(decls.begin(), decls.end(), [](const Declared& d) { return !d.nameSpace->empty(); });
        const bool builtin = anyNamespaced && (hasBuiltin(simple) || types().byName(simple));
        if (decls.size() < 2 && !builtin) continue;
        for (const bool library : {false, true}) {
            std::set<std::string> spaces;
            bool namespaced = false;
            for (const Declared& d : decls)
                if (d.library == library) {
                    spaces.insert(upper(*d.nameSpace));
                    namespaced = namespaced || !d.nameSpace->empty();
                }
            if (spaces.size() < 2 && !(namespaced && builtin)) continue;
            for (const Declared& d : decls) {
                if (d.library != library || d.nameSpace->empty() || d.name->find('.') != std::string::npos) continue;  // renamed above
                contested_[simple].insert(upper(*d.nameSpace));
                *d.name = *d.nameSpace + "." + *d.name;
            }
        }
    }
}

namespace {
// "A.B.C" -> "A.B.C", "A.B", "A": the namespace of the code and the ones around it.
template <typename F>
bool forEachEnclosing(const std::string& nameSpace, F&& f) {
    for (std::string ns = nameSpace; !ns.empty();) {
        if (f(ns)) return true;
        const auto dot = ns.rfind('.');
        ns = dot == std::string::npos ? std::string() : ns.substr(0, dot);
    }
    return false;
}
}  // namespace

std::string Checker::scopedKey(const std::string& written) const {
    if (contested_.empty()) return written;
    const auto dot = written.rfind('.');
    const std::string simple = dot == std::string::npos ? written : written.substr(dot + 1);
    const auto it = contested_.find(simple);
    if (it == contested_.end()) return written;
    const std::set<std::string>& spaces = it->second;
    // Written qualified: the namespace as written, else relative to the
    // namespaces around the code or to one of its file's USINGs. Written
    // simple: the namespace of the code, the ones around it, the top level,
    // then the file's USINGs.
    const std::string qualifier = dot == std::string::npos ? std::string() : written.substr(0, dot);
    std::string found;
    auto tryIn = [&](const std::string& ns) {
        const std::string path = qualifier.empty() ? ns : ns.empty() ? qualifier : ns + "." + qualifier;
        if (!spaces.count(path)) return false;
        found = path + "." + simple;
        return true;
    };
    if (!qualifier.empty() && tryIn("")) return found;
    if (forEachEnclosing(nameScope_.nameSpace, tryIn)) return found;
    // The top level is the outermost enclosing namespace: its declaration comes
    // before what a USING brings in, as in C# (decision 0325).
    if (qualifier.empty() && (pous_.count(simple) || typeDecls_.count(simple))) return written;
    if (auto usings = usingsByFile_.find(nameScope_.file); usings != usingsByFile_.end())
        for (const std::string& u : usings->second)
            if (tryIn(u)) return found;
    // The top-level declaration (still keyed by its simple name), a builtin, or
    // a library prefix the callers strip (`Tc2_Standard.TON`).
    return written;
}

std::string Checker::writtenPath(const ast::Expr& e) {
    if (e.kind == ast::ExprKind::Name) return upper(e.name);
    if (e.kind != ast::ExprKind::Member || e.kids.empty()) return "";
    std::string base = writtenPath(*e.kids[0]);
    return base.empty() ? "" : base + "." + upper(e.name);
}

const ast::Expr& Checker::chainRoot(const ast::Expr& e) {
    const ast::Expr* p = &e;
    while (p->kind == ast::ExprKind::Member && !p->kids.empty()) p = p->kids[0].get();
    return *p;
}

std::string Checker::ambiguityOf(const std::string& written) const {
    const auto it = contested_.find(written);
    if (it == contested_.end() || scopedKey(written) != written || pous_.count(written) || typeDecls_.count(written)) return "";
    std::string list;
    for (const std::string& ns : it->second) {
        const std::string key = ns + "." + written;
        const auto pou = pous_.find(key);
        const auto type = typeDecls_.find(key);
        const std::string shown = pou != pous_.end() ? pou->second->name : type != typeDecls_.end() ? type->second->name : key;
        list += (list.empty() ? "'" : "', '") + shown;
    }
    return list + "'";
}

}  // namespace strun::sema
