#include "interpreter/project/compile.h"
#include "interpreter/project/ax_project.h"

#include <algorithm>
#include <exception>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/ast/large_stack.h"
#include "interpreter/ast/parse.h"
#include "interpreter/project/library_selection.h"
#include "interpreter/project/missing_libraries.h"
#include "interpreter/project/syntax_recovery.h"
#include "interpreter/source/project_inputs.h"
#include "interpreter/sema/checker.h"
#include "interpreter/builtins/libraries/task_info.h"
#include "interpreter/builtins/register_builtins.h"
#include "interpreter/testing/register_axunit.h"
#include "interpreter/testing/register_tcunit.h"
#include "interpreter/testing/suite_finder.h"
#include "interpreter/testing/tcunit_parameters.h"
#include "interpreter/testing/test_registry.h"
#include "stdlib/embedded_sources.h"

namespace strun::project {

namespace {

// Puts a TwinCAT library project's POUs and types into the namespace its
// consumer's reference gives it (decision 0454); its global lists keep their
// names (`Lib.GVL_X.x` already names one). Once: the LSP lends units it
// parsed before.
void placeInNamespace(ast::Pou& pou, const std::string& ns) {
    if (pou.nameSpace != ns && pou.nameSpace.rfind(ns + ".", 0) != 0) pou.nameSpace = pou.nameSpace.empty() ? ns : ns + "." + pou.nameSpace;
    for (auto& m : pou.methods) placeInNamespace(*m, ns);
    for (auto& p : pou.properties)
        for (ast::Pou* accessor : {p.getter.get(), p.setter.get()})
            if (accessor) placeInNamespace(*accessor, ns);
}

void placeInLibraryNamespace(ast::CompilationUnit& unit, const std::string& ns) {
    for (auto& p : unit.pous) placeInNamespace(*p, ns);
    for (auto& t : unit.types)
        if (t.nameSpace != ns && t.nameSpace.rfind(ns + ".", 0) != 0) t.nameSpace = t.nameSpace.empty() ? ns : ns + "." + t.nameSpace;
}

}  // namespace

std::unique_ptr<ParsedLibrary> parseLibrary(CompileLog& log) {
    auto library = std::make_unique<ParsedLibrary>();
    std::vector<int> files;
    for (const auto& src : stdlib::embeddedSources()) {
        int index = library->sources.add(std::string(src.path), std::string(src.text));
        library->files.insert(index);
        files.push_back(index);
    }
    library->units = ast::parseFiles(library->sources, files, log);
    return library;
}

namespace {
std::unique_ptr<sema::ProgramModel> compileOnLargeStack(SourceSet& sources, const std::vector<int>& userFiles, CompileLog& log,
                                                        const sema::CompileOptions& options, ParsedLibrary* library,
                                                        std::vector<ast::CompilationUnit>* keepUnits, CompileExtras* extras);
}  // namespace

// The whole compile runs on one thread with a large stack: the parser's and
// the checker's runWithLargeStack then run where they are, instead of
// starting a thread of 256 MB each (one per parsed file and one for the
// checker; issue 28's start-up).
std::unique_ptr<sema::ProgramModel> compileProject(SourceSet& sources, const std::vector<int>& userFiles, CompileLog& log,
                                                   const sema::CompileOptions& options, ParsedLibrary* library,
                                                   std::vector<ast::CompilationUnit>* keepUnits, CompileExtras* extras) {
    std::unique_ptr<sema::ProgramModel> model;
    std::exception_ptr failure;
    ast::runWithLargeStack([&] {
        try {
            model = compileOnLargeStack(sources, userFiles, log, options, library, keepUnits, extras);
        } catch (...) {
            failure = std::current_exception();
        }
    });
    if (failure) std::rethrow_exception(failure);
    return model;
}

namespace {
std::unique_ptr<sema::ProgramModel> compileOnLargeStack(SourceSet& sources, const std::vector<int>& userFiles, CompileLog& log,
                                                        const sema::CompileOptions& options, ParsedLibrary* library,
                                                        std::vector<ast::CompilationUnit>* keepUnits, CompileExtras* extras) {
    std::vector<ast::CompilationUnit> units;
    std::set<int> libraryFiles;
    // Only the library files the project mentions (decision 0150), also when
    // they come parsed from a lent library: checking unused library bodies
    // was most of the cost of a small compile.
    std::vector<std::string_view> userTexts;
    for (int f : userFiles) userTexts.push_back(sources.file(f).text);
    const LibrarySelection selection = selectLibraries(userTexts);
    const std::vector<const stdlib::EmbeddedSource*>& wanted = selection.files;
    std::vector<size_t> borrowed;  // indices into library->units, parallel to the first units
    std::vector<int> toParse;      // the library files (unless lent), then the user's
    if (library) {
        const auto& all = stdlib::embeddedSources();
        for (size_t i = 0; i < all.size() && i < library->units.size(); ++i) {
            if (std::find(wanted.begin(), wanted.end(), &all[i]) == wanted.end()) continue;
            borrowed.push_back(i);
            units.push_back(std::move(library->units[i]));
            libraryFiles.insert(static_cast<int>(i));
        }
    } else {
        for (const stdlib::EmbeddedSource* src : wanted) {
            const bool tcunit = !options.tcunitParameters.empty() && src->path == "stdlib/tcunit.st";
            int index = sources.add(std::string(src->path), tcunit ? testing::withTcUnitParameters(src->text, options.tcunitParameters)
                                                                   : std::string(src->text));
            libraryFiles.insert(index);
            toParse.push_back(index);
        }
    }
    // Files strun wrote as a project library (SourceSet::markProjectLibrary)
    // come first, so that a user declaration of the same name replaces theirs.
    std::vector<int> ordered = userFiles;
    std::stable_partition(ordered.begin(), ordered.end(), [&](int f) { return sources.isProjectLibrary(f); });
    for (int f : ordered)
        if (!extras || !extras->parsed.count(f)) toParse.push_back(f);
    if (extras && extras->libraryUnitsUsed) *extras->libraryUnitsUsed = borrowed;
    // Hands the lent library units back however this function ends.
    struct GiveBack {
        ParsedLibrary* library;
        std::vector<ast::CompilationUnit>& units;
        const std::vector<size_t>& borrowed;
        ~GiveBack() {
            if (!library) return;
            for (size_t k = 0; k < borrowed.size() && k < units.size(); ++k) library->units[borrowed[k]] = std::move(units[k]);
        }
    } giveBack{library, units, borrowed};
    // Hands the AST to the caller who keeps it, however this function ends.
    struct Keep {
        std::vector<ast::CompilationUnit>* out;
        std::vector<ast::CompilationUnit>& units;
        ~Keep() {
            if (out) *out = std::move(units);
        }
    } keep{library == nullptr ? keepUnits : nullptr, units};
    // Lent user units (CompileExtras::parsed), handed back however this function ends.
    struct GiveBackParsed {
        std::vector<std::pair<size_t, ast::CompilationUnit*>> lent;  // index in `units` -> owner
        std::vector<ast::CompilationUnit>& units;
        ~GiveBackParsed() {
            for (auto& [k, owner] : lent)
                if (k < units.size()) *owner = std::move(units[k]);
        }
    } giveBackParsed{{}, units};
    std::vector<ast::CompilationUnit> parsedHere = ast::parseFiles(sources, toParse, log);
    size_t next = 0;
    for (ast::CompilationUnit& unit : parsedHere) {
        // The library's files (when not lent) come first, as before.
        if (libraryFiles.count(unit.file) == 0) break;
        units.push_back(std::move(unit));
        ++next;
    }
    for (int f : ordered) {
        auto lent = extras ? extras->parsed.find(f) : std::map<int, ast::CompilationUnit*>::iterator();
        if (extras && lent != extras->parsed.end()) {
            giveBackParsed.lent.emplace_back(units.size(), lent->second);
            units.push_back(std::move(*lent->second));
        } else if (next < parsedHere.size()) {
            units.push_back(std::move(parsedHere[next++]));
        }
    }
    // After local syntax errors the recovered tree is still checked, so that
    // the later mistakes of the file are reported too (decision 0161).
    for (ast::CompilationUnit& unit : units)
        if (const std::string& ns = sources.libraryNamespace(unit.file); !ns.empty()) placeInLibraryNamespace(unit, ns);
    const SyntaxDamage damage = assessSyntaxErrors(log);
    if (log.hasErrors() && !damage.checkable) return nullptr;
    auto model = std::make_unique<sema::ProgramModel>();
    auto checkerOwner = std::make_unique<sema::Checker>(*model, log);
    sema::Checker& checker = *checkerOwner;
    if (extras && extras->observer) checker.setExprObserver(extras->observer);
    for (int f : ordered)
        if (sources.isProjectLibrary(f)) libraryFiles.insert(f);
    checker.setLibraryFiles(libraryFiles);
    sema::CompileOptions effective = options;
    for (int f : userFiles) effective.twincatRealText = effective.twincatRealText || source::isTwinCatObject(sources.file(f).path);
    for (int f = 0; f < sources.size(); ++f) effective.sourcePaths.push_back(sources.file(f).path);
    {
        std::vector<std::string> userPaths;
        for (int f : userFiles) userPaths.push_back(sources.file(f).path);
        effective.axStrings = effective.axStrings || isAxProject(userPaths);  // decision 0394
    }
    effective.twincatDurations = effective.twincatDurations || effective.twincatRealText;
    checker.setCompileOptions(effective);
    if (const rt::PlcProfile* profile = rt::findProfile(options.target)) checker.setProfile(*profile);
    stdlib::registerParameterAliases(checker);
    model->tests = std::make_shared<testing::TestRegistry>();
    // The built-in functions, registered when the checker first looks one up
    // (decision 0478); the registrar owns what it needs, since a kept checker
    // (extras->keepChecker) may look one up after this function returns.
    checker.setBuiltinRegistrar([libraries = std::vector<std::string>(selection.nativeLibraries.begin(), selection.nativeLibraries.end()),
                                 tests = model->tests](sema::Checker& ck) {
        stdlib::registerBuiltins(ck);
        // Native functions of the vendor libraries the project names (decision 0220).
        stdlib::registerLibraryBuiltins(ck, std::vector<std::string_view>(libraries.begin(), libraries.end()));
        testing::registerTcUnit(ck, *tests);
        testing::registerAxUnit(ck, *tests);  // SIMATIC AX (decision 0364)
    });
    // The checker recurses once per nested declaration and expression level;
    // both are capped (docs/limits.md), and compileProject's large stack
    // gives the caps a wide margin, also under sanitizers.
    checker.run(units);
    if (!damage.lines.empty()) dropSyntaxCascades(log, damage);
    groupMissingLibraryNames(log, sources.referencedLibraries());  // a .plcproj's libraries strun lacks
    explainPinnedTypes(log, sources.pinnedTypes());                 // a .plcproj's pinned types strun could not read
    if (extras && extras->keepChecker) *extras->keepChecker = std::move(checkerOwner);
    if (log.hasErrors()) {
        if (extras && extras->modelEvenWithErrors) *extras->modelEvenWithErrors = std::move(model);
        return nullptr;
    }
    testing::recordProject(*model, *model->tests);
    // Tc2_System's _TaskInfo[] follows the tasks (only when its file was selected).
    for (const stdlib::EmbeddedSource* src : wanted)
        if (src->library == "Tc2_System") {
            if (exec::Stmt* refresh = stdlib::makeTaskInfoRefresh(*model)) model->activationPrologue.push_back(refresh);
            break;
        }
    // The AST is referenced by nothing at run time: all names are resolved.
    return model;
}
}  // namespace

}  // namespace strun::project
