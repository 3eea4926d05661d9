#include "interpreter/project/compile.h"

#include <set>

#include "interpreter/ast/parse.h"
#include "interpreter/sema/checker.h"
#include "interpreter/builtins/register_builtins.h"
#include "stdlib/embedded_sources.h"

namespace strun::project {

std::unique_ptr<sema::ProgramModel> compileProject(SourceSet& sources, const std::vector<int>& userFiles, CompileLog& log,
                                                   const sema::CompileOptions& options) {
    std::vector<ast::CompilationUnit> units;
    std::set<int> libraryFiles;
    for (const auto& src : stdlib::embeddedSources()) {
        int index = sources.add(std::string(src.path), std::string(src.text));
        libraryFiles.insert(index);
        units.push_back(ast::parseFile(sources, index, log));
    }
    for (int f : userFiles) units.push_back(ast::parseFile(sources, f, log));
    if (log.hasErrors()) return nullptr;
    auto model = std::make_unique<sema::ProgramModel>();
    sema::Checker checker(*model, log);
    checker.setLibraryFiles(libraryFiles);
    checker.setCompileOptions(options);
    stdlib::registerBuiltins(checker);
    checker.run(units);
    if (log.hasErrors()) return nullptr;
    // The AST is referenced by nothing at run time: all names are resolved.
    return model;
}

}  // namespace strun::project
