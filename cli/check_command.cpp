// strun check [options] FILE...: compile only; print diagnostics.
#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/compile_step.h"

namespace strun::cli {

CLI::App* addCheckCommand(CLI::App& app, CommandLine& line) {
    CLI::App* check = app.add_subcommand("check", "compile only; print diagnostics");
    addFileArguments(*check, line);
    addCompileOptions(*check, line);
    return check;
}

// The process ends right after a check (main.cpp leaves through _Exit), so
// the AST and the program model are left to the operating system: freeing
// them was a tenth of checking a large project (decision 0159). Sanitizer
// builds free them, so that their leak checks still see everything else.
int checkCommand(const CommandLine& line) {
    auto compiled = std::make_unique<Compiled>();
    compiled->keepAst = true;
    // Nothing runs: inlining calls (decision 0317) would be work for nothing.
    CommandLine checkLine = line;
    checkLine.compile.inlineCalls = false;
    compileCommandLine(checkLine, *compiled);
    const int exitCode = compiled->exitCode;
#ifndef STRUN_SANITIZED
    (void)compiled.release();
#endif
    return exitCode;
}

}  // namespace strun::cli
