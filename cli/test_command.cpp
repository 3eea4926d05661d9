#include "cli/test_command.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "interpreter/testing/test_registry.h"
#include "interpreter/testing/test_report.h"
#include "interpreter/testing/test_session.h"
#include "stdlib/time_literals.h"

namespace strun::cli {

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitUsage = 2;

int usage(const std::string& message) {
    std::cerr << "strun: " << message << "\n";
    return kExitUsage;
}

bool isProjectFile(const std::filesystem::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return ext == ".st" || ext == ".xml" || ext == ".tcpou" || ext == ".tcdut" || ext == ".tcgvl" || ext == ".tcio";
}

}  // namespace

bool expandPaths(const std::vector<std::string>& paths, std::vector<std::string>& files, std::string& error) {
    namespace fs = std::filesystem;
    for (const auto& path : paths) {
        std::error_code ec;
        if (fs::is_directory(path, ec)) {
            std::vector<std::string> found;
            fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, ec), end;
            for (; !ec && it != end; it.increment(ec))
                if (it->is_regular_file(ec) && isProjectFile(it->path())) found.push_back(it->path().string());
            if (ec) {
                error = "cannot read the directory '" + path + "'";
                return false;
            }
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else if (fs::exists(path, ec)) {
            files.push_back(path);
        } else {
            error = "cannot open '" + path + "'";
            return false;
        }
    }
    return true;
}

CLI::App* addTestCommand(CLI::App& app, TestCommandOptions& o) {
    auto* test = app.add_subcommand("test", "run the unit tests (TcUnit / CfUnit API) of the project");
    test->add_option("FILE", o.paths, "source files or directories")->required();
    test->add_option("--stmt-cost", o.stmtCost, "virtual time one executed statement costs (default 1us)");
    test->add_option("--timeout", o.timeout, "PLC time after which unfinished tests fail (default T#10s)");
    test->add_option("--junit", o.junit, "also write a JUnit XML report to FILE");
    test->add_option("--filter", o.filter, "run only the tests whose Suite.Test matches PATTERN (* and ? wildcards)");
    test->add_flag("--list", o.list, "print the tests without running them");
    return test;
}

int runTestCommand(const TestCommandOptions& o) {
    rt::RunOptions run;
    run.virtualClock = true;
    run.stmtCost = 1000;
    if (!o.stmtCost.empty()) {
        auto r = stdlib::parseDurationLiteral(o.stmtCost);
        if (!r || r.value() < 0) return usage("--stmt-cost: '" + o.stmtCost + "' is not a duration (e.g. 1us, T#2us)");
        run.stmtCost = r.value();
    }
    run.duration = 10'000'000'000LL;
    if (!o.timeout.empty()) {
        auto r = stdlib::parseDurationLiteral(o.timeout);
        if (!r || r.value() <= 0) return usage("--timeout: '" + o.timeout + "' is not a positive duration (e.g. T#10s, 500ms)");
        run.duration = r.value();
    }
    std::vector<std::string> files;
    std::string err;
    if (!expandPaths(o.paths, files, err)) return usage(err);
    if (files.empty()) return usage("no source files found in the given directories");
    SourceSet sources;
    std::vector<int> indices;
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        if (!in) return usage("cannot open '" + f + "'");
        std::stringstream ss;
        ss << in.rdbuf();
        indices.push_back(sources.add(f, ss.str()));
    }
    CompileLog log;
    auto model = testing::compileForTests(sources, indices, log);
    log.print(std::cerr, sources);
    if (!model) return kExitFailed;
    testing::TestRegistry& reg = *model->tests;
    reg.filter = o.filter;
    if (o.list) {
        testing::printTestList(reg, std::cout);
        return kExitOk;
    }
    if (reg.suites.empty())
        std::cerr << "strun: warning: no test suite runs: declare instances of FUNCTION_BLOCKs that EXTEND FB_TestSuite "
                     "in a PROGRAM that calls RUN() (or have no RUN() and no CONFIGURATION)\n";
    testing::TestRunResult result = testing::runTests(*model, run, o.filter);
    testing::TestCounts counts = testing::printResults(reg, sources, std::cout);
    std::cout.flush();
    if (!o.junit.empty() && !testing::writeJUnit(reg, sources, result.endTime, o.junit, err)) {
        std::cerr << "strun: --junit: " << err << "\n";
        return kExitFailed;
    }
    return counts.failed == 0 ? kExitOk : kExitFailed;
}

}  // namespace strun::cli
