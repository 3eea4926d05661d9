// The part `run` and `check` share: read the FILEs, compile them with the
// CompileOptions, print the diagnostics.
#pragma once

#include <memory>
#include <vector>

#include "cli/command_line.h"
#include "interpreter/ast/ast.h"
#include "interpreter/sema/program_model.h"
#include "interpreter/source/source_set.h"

namespace strun::cli {

struct Compiled {
    int exitCode = 0;  // kExitOk when `model` is set
    SourceSet sources;
    std::unique_ptr<sema::ProgramModel> model;
    // Set before compiling to keep the AST here rather than free it (see
    // checkCommand).
    bool keepAst = false;
    std::vector<ast::CompilationUnit> ast;
};

// Fills `out` in place (the model may refer to the sources).
void compileCommandLine(const CommandLine& line, Compiled& out);

}  // namespace strun::cli
