// `strun test [options] FILE...|DIR`: runs the TcUnit / CfUnit unit tests of a
// project (contract "Tests: strun test"; docs/testing.md).
#pragma once

#include <string>
#include <vector>

namespace CLI { class App; }

namespace strun::cli {

struct TestCommandOptions {
    std::vector<std::string> paths;
    std::string stmtCost;
    std::string timeout;
    std::string junit;
    std::string filter;
    bool list = false;
};

// Declares the subcommand and its options on `app`; returns it.
CLI::App* addTestCommand(CLI::App& app, TestCommandOptions& options);

// Exit status: 0 every test passed, 1 a test failed or the project does not compile, 2 bad command line.
int runTestCommand(const TestCommandOptions& options);

// The files a DIR stands for: every .st, .xml, .TcPOU, .TcDUT, .TcGVL, .TcIO
// under it, recursively, in path order. A FILE stands for itself. False (with
// `error`) when a path does not exist.
bool expandPaths(const std::vector<std::string>& paths, std::vector<std::string>& files, std::string& error);

}  // namespace strun::cli
