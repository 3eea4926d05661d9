// The subcommands of strun: each registers its options on the CLI11 app and
// runs from the parsed CommandLine.
#pragma once

#include "cli/cli11_fwd.h"

#include "cli/command_line.h"
#include "runtime/scheduler.h"

namespace strun::cli {

CLI::App* addRunCommand(CLI::App& app, CommandLine& line);
// `strun run ARGUMENTS...` parsed into `line` (ARGUMENTS without "run"),
// for the debugger's launch request; false with CLI11's message.
bool parseRunArguments(const std::vector<std::string>& arguments, CommandLine& line, std::string& error);
CLI::App* addCheckCommand(CLI::App& app, CommandLine& line);
// Options that change compilation, shared by run and check (and test).
void addCompileOptions(CLI::App& command, CommandLine& line);
void addFileArguments(CLI::App& command, CommandLine& line);

CLI::App* addExplainCommand(CLI::App& app, std::string& code);

int runCommand(const CommandLine& line);    // strun run
// The run options that do not depend on the compiled project (clock,
// --stmt-cost, --start and their limits, --cycles, --for, --target, --trace);
// false with the usage error. `strun run` and `strun debug` both use it.
bool buildRunOptions(const CommandLine& line, rt::RunOptions& run, std::string& error);
int checkCommand(const CommandLine& line);  // strun check
int explainCommand(const std::string& code);  // strun explain [CODE]

}  // namespace strun::cli
