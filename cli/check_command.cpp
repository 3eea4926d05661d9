// strun check [options] FILE...: compile only; print diagnostics.
#include "cli/commands.h"
#include "cli/compile_step.h"

namespace strun::cli {

CLI::App* addCheckCommand(CLI::App& app, CommandLine& line) {
    CLI::App* check = app.add_subcommand("check", "compile only; print diagnostics");
    addFileArguments(*check, line);
    addCompileOptions(*check, line);
    return check;
}

int checkCommand(const CommandLine& line) {
    Compiled compiled;
    compileCommandLine(line, compiled);
    return compiled.exitCode;
}

}  // namespace strun::cli
