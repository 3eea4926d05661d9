// Source files -> checked, runnable program model. Parses the embedded ST
// standard library files the project mentions (library_selection.h)
// together with the user's files, so both are checked as one project.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <vector>

#include "interpreter/sema/compile_options.h"
#include "interpreter/sema/program_model.h"
#include "interpreter/source/source_set.h"

namespace strun::sema {
class Checker;
class ExprObserver;
}  // namespace strun::sema

namespace strun::project {

// The embedded standard library parsed once, for callers that compile many
// projects in one process (the fuzz target): parsing it is most of the cost
// of a small compile. `sources` holds its files; a project compiled with it
// starts from a copy of `sources` and adds its own files after them.
struct ParsedLibrary {
    SourceSet sources;
    std::vector<ast::CompilationUnit> units;
    std::set<int> files;
};
std::unique_ptr<ParsedLibrary> parseLibrary(CompileLog& log);

// What the editor services (strun lsp, strun debug) want from a compile
// besides the runnable model; `run` and `check` pass none.
struct CompileExtras {
    sema::ExprObserver* observer = nullptr;  // told about every checked expression
    // Receives the model also when the project has errors (the declarations
    // that did check: an editor still navigates a project with mistakes).
    std::unique_ptr<sema::ProgramModel>* modelEvenWithErrors = nullptr;
    // Receives the checker, for expressions checked later in a POU's scope
    // (it refers to the model, the log and the kept AST).
    std::unique_ptr<sema::Checker>* keepChecker = nullptr;
    // User files parsed already (file index -> its unit), lent as a
    // ParsedLibrary's units are: moved in, checked (the checker does not
    // change them) and handed back however the compile ends; only the other
    // files are parsed. Their syntax diagnostics must be in the log already.
    // An editor re-parses only the file an edit changed (decision 0270).
    std::map<int, ast::CompilationUnit*> parsed;
    // Receives the indices of the lent library's units the project's
    // selection checked (library_selection.h).
    std::vector<size_t>* libraryUnitsUsed = nullptr;
};

// Returns null when the project does not compile (errors are in `log`).
// With `library`, its parsed units are lent to the checker (which does not
// change them) instead of parsing the standard library again. With
// `keepUnits` (and no library), the AST ends up there instead of being
// freed: a process that ends right after compiling need not free it.
std::unique_ptr<sema::ProgramModel> compileProject(SourceSet& sources, const std::vector<int>& userFiles, CompileLog& log,
                                                   const sema::CompileOptions& options = {}, ParsedLibrary* library = nullptr,
                                                   std::vector<ast::CompilationUnit>* keepUnits = nullptr,
                                                   CompileExtras* extras = nullptr);

}  // namespace strun::project
