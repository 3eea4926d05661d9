#include "cli/test_command.h"
#include "runtime/file_sandbox.h"

#include <iostream>

#include "cli/commands.h"
#include "cli/diagnostic_render.h"
#include "cli/exit_codes.h"
#include "cli/option_types.h"
#include "cli/stimulus_args.h"
#include "interpreter/project/stimulus_build.h"
#include "interpreter/source/project_inputs.h"
#include "interpreter/testing/test_registry.h"
#include "interpreter/testing/test_report.h"
#include "interpreter/testing/test_session.h"
#include "runtime/plc_profile.h"

namespace strun::cli {

namespace {

constexpr int64_t kDefaultTimeout = 10'000'000'000LL;  // T#10s (contract)

int usage(const std::string& message) {
    std::cerr << "strun: " << message << "\n";
    return kExitUsage;
}

// The text already passed durationValidator().
int64_t validatedDuration(const std::string& text) {
    std::string unused;
    return parseDuration(text, unused).value_or(0);
}

}  // namespace

CLI::App* addTestCommand(CLI::App& app, CommandLine& line, TestCommandLine& test) {
    CLI::App* cmd = app.add_subcommand("test", "run the unit tests (TcUnit / CfUnit API) of the project");
    addFileArguments(*cmd, line);
    addCompileOptions(*cmd, line);
    cmd->add_option_function<std::string>(
           "--stmt-cost", [&test](const std::string& text) { test.stmtCost = validatedDuration(text); },
           "virtual time one executed statement costs (default 1us)")
        ->transform(durationValidator())
        ->type_name("DURATION");
    cmd->add_option_function<std::string>(
           "--timeout", [&test](const std::string& text) { test.timeout = validatedDuration(text); },
           "PLC time after which unfinished tests fail with `timeout` (default T#10s)")
        ->transform(durationValidator())
        ->type_name("DURATION");
    cmd->add_option("--junit", test.junit, "also write a JUnit XML report to FILE")->type_name("FILE");
    cmd->add_option("--filter", test.filter, "run only the tests whose Suite.Test matches PATTERN (* and ? wildcards)")->type_name("PATTERN");
    cmd->add_flag("--list", test.list, "print the tests the suites declare without running them");
    cmd->add_option("--set", line.sets,
                    "at PLC time TIME (default 0) write the ST literal VALUE to a variable or direct input (repeatable)")
        ->type_name("NAME=VALUE[@TIME]")
        ->allow_extra_args(false);  // one value per --set: FILEs follow
    cmd->add_option("--stimulus", line.stimulusFiles, "a CSV file of TIME,NAME,VALUE lines: many --set at once")
        ->check(readableFileValidator())
        ->type_name("FILE")
        ->allow_extra_args(false);
    return cmd;
}

int testCommand(const CommandLine& line, const TestCommandLine& test) {
    rt::RunOptions run;
    run.virtualClock = true;
    run.stmtCost = test.stmtCost.value_or(1000);
    run.duration = test.timeout.value_or(kDefaultTimeout);
    if (*run.duration <= 0) return usage("--timeout: the timeout must be longer than 0");
    run.profile = rt::findProfile(line.compile.target);

    std::string error;
    SourceSet sources;
    std::vector<int> indices;
    CompileLog log;
    if (!source::readProjectInputs(line.files, sources, indices, log, error)) return usage(error);
    auto model = testing::compileForTests(sources, indices, log, line.compile);
    if (printDiagnostics(log, sources, line.diagnostics, std::cerr, stderrWantsColor(line.diagnostics.color))) return kExitCompile;
    if (!model) return kExitCompile;
    testing::TestRegistry& reg = *model->tests;
    reg.filter = test.filter;
    if (test.list) {
        testing::printTestList(reg, std::cout);
        return kExitOk;
    }
    // Stimulus, as for run (with the target's input aliases).
    rt::Stimulus stimulus;
    if (!buildCommandLineStimulus(line, *model, run.profile ? *run.profile : rt::defaultProfile(), stimulus, error)) return usage(error);
    if (!stimulus.empty()) run.stimulus = &stimulus;
    if (reg.suites.empty())
        std::cerr << "strun: warning: no test suite runs: declare instances of FUNCTION_BLOCKs that EXTEND FB_TestSuite "
                     "in a PROGRAM that calls RUN(), or leave RUN() out and strun adds one\n";
    testing::TestRunResult result = testing::runTests(*model, run, test.filter);
    rt::fileSandbox().finish();  // the file blocks' temporary directory (docs/libraries.md)
    testing::TestCounts counts = testing::printResults(reg, sources, std::cout);
    std::cout.flush();
    if (!test.junit.empty() && !testing::writeJUnit(reg, sources, result.endTime, test.junit, error)) {
        std::cerr << "strun: --junit: " << error << "\n";
        return kExitCompile;
    }
    return counts.failed == 0 ? kExitOk : kExitCompile;
}

}  // namespace strun::cli
