// strun test [options] FILE...|DIR: runs the TcUnit / CfUnit unit tests of a
// project (contract "Tests: strun test"; docs/testing.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/cli11_fwd.h"

#include "cli/command_line.h"

namespace strun::cli {

// What `test` takes besides the FILEs, compile options and stimulus of CommandLine.
struct TestCommandLine {
    std::optional<int64_t> stmtCost;    // --stmt-cost, ns
    std::optional<int64_t> timeout;     // --timeout, ns
    std::string junit;                  // --junit FILE
    std::string filter;                 // --filter PATTERN
    bool list = false;                  // --list
    bool allowEmpty = false;            // --allow-empty: no test to run is not an error
    size_t jobs = 1;                    // -j N: suites in N processes (0: one per processor)
    size_t shard = 0, shards = 0;       // --shard K/N (1-based K); 0/0: every suite
    std::vector<std::string> tcunitParams;  // --tcunit-param NAME=VALUE (GVL_Param_TcUnit)
};

CLI::App* addTestCommand(CLI::App& app, CommandLine& line, TestCommandLine& test);

// Exit status: 0 every test passed, 1 a test failed, no test ran (unless
// --allow-empty) or the project does not compile, 2 bad command line.
int testCommand(const CommandLine& line, const TestCommandLine& test);

}  // namespace strun::cli
