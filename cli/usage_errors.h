// Messages for a bad command line (exit 2): an unknown command or option
// names itself and the closest valid one; `strun help [COMMAND]`.
#pragma once

#include <string>

#include "cli/cli11_fwd.h"

namespace strun::cli {

// When the first argument is a word that is no subcommand, reports it and
// returns 2; else -1 (let CLI11 parse).
int checkSubcommandName(const CLI::App& app, int argc, char** argv);
// Prints `strun: MESSAGE` on stderr; returns 2 (kExitUsage).
int usage(const std::string& message);
// Prints a CLI11 parse error as one `strun: ...` line; returns 2.
int reportParseError(CLI::App& app, const CLI::ParseError& error);
// strun help [COMMAND]: the help of the app or of one command on stdout.
int printHelp(const CLI::App& app, const std::string& topic);

}  // namespace strun::cli
