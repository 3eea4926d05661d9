#include "cli/test_command.h"
#include "runtime/file_sandbox.h"

#include <algorithm>
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/diagnostic_render.h"
#include "cli/exit_codes.h"
#include "cli/option_types.h"
#include "cli/stimulus_args.h"
#include "cli/usage_errors.h"
#include "cli/test_parallel.h"
#include "interpreter/project/stimulus_build.h"
#include "interpreter/source/project_inputs.h"
#include "interpreter/testing/junit_merge.h"
#include "interpreter/testing/suite_slices.h"
#include "interpreter/testing/tcunit_parameters.h"
#include "interpreter/testing/test_registry.h"
#include "interpreter/testing/test_report.h"
#include "interpreter/testing/test_session.h"
#include "runtime/output_files.h"
#include "runtime/plc_profile.h"

namespace strun::cli {

namespace {

// A project that brings TcUnit's own library source (its FB_TestSuite replaces
// strun's): its suites register with that source's runner, not with strun's
// built-in TcUnit, so `strun test` finds no test. Say so and what to do.
void explainOwnTcUnit(const sema::ProgramModel& model, const SourceSet& sources) {
    // (The POUs' syntax trees are gone by now: the file comes from the registry.)
    for (const auto& p : model.pouStore) {
        if (p->owner || !p->code || p->code->library || sema::upper(p->name) != "FB_TESTSUITE") continue;
        auto file = model.tests->pouFiles.find(p->code->name);
        if (file == model.tests->pouFiles.end()) continue;
        std::cerr << "strun: the project declares its own FB_TestSuite (" << sources.file(file->second).path
                  << "), TcUnit's library source: strun test runs suites with its built-in TcUnit, so leave TcUnit's "
                     "sources out of the inputs; `strun run` runs TcUnit's own engine, which reports through its ADS log\n";
        return;
    }
}

}  // namespace

namespace {

constexpr int64_t kDefaultTimeout = 10'000'000'000LL;  // T#10s (contract)

// --shard K/N: 1 <= K <= N.
CLI::Validator shardValidator() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            text = trimmed(text);
            size_t slash = text.find('/');
            auto digits = [](const std::string& t) { return !t.empty() && t.size() < 7 && t.find_first_not_of("0123456789") == std::string::npos; };
            if (slash == std::string::npos || !digits(text.substr(0, slash)) || !digits(text.substr(slash + 1)))
                return "'" + text + "' is not K/N (the K-th of N slices, e.g. 2/4)";
            long k = std::stol(text.substr(0, slash)), n = std::stol(text.substr(slash + 1));
            if (n < 1 || k < 1 || k > n) return "'" + text + "': K must be between 1 and N";
            return {};
        },
        "", "K/N");
}

// One slice of the suites run here, the verdicts on stdout (the summary only
// when `summary`), the JUnit report to `junit` (when not empty).
struct SliceOutcome {
    testing::TestCounts counts;
    bool junitWritten = true;
};

SliceOutcome runSlice(sema::ProgramModel& model, const rt::RunOptions& run, const TestCommandLine& test, const SourceSet& sources,
                      const std::string& junit, bool summary, bool color) {
    SliceOutcome outcome;
    testing::TestRegistry& reg = *model.tests;
    testing::TestRunResult result = testing::runTests(model, run, test.filter);
    rt::fileSandbox().finish();  // the file blocks' temporary directory (docs/libraries.md)
    outcome.counts = testing::printResults(reg, sources, std::cout, summary, color);
    std::cout.flush();
    std::string error;
    if (!junit.empty() && !testing::writeJUnit(reg, sources, result.endTime, junit, error)) {
        std::cerr << "strun: --junit: " << error << "\n";
        outcome.junitWritten = false;
    }
    return outcome;
}

}  // namespace

CLI::App* addTestCommand(CLI::App& app, CommandLine& line, TestCommandLine& test) {
    CLI::App* cmd = app.add_subcommand("test", "run the unit tests (TcUnit / CfUnit API) of the project");
    cmd->footer("Exit status: 0 every test passed; 1 a test failed, no test ran (without --allow-empty), the JUnit\n"
                "file cannot be written, or the project does not compile; 2 bad command line.");
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
    cmd->add_flag("--allow-empty", test.allowEmpty, "exit 0 when there is no test to run (no suite, or --filter matches none)");
    cmd->add_option_function<std::string>(
           "-j,--jobs", [&test](const std::string& text) { test.jobs = std::stoul(text); },
           "run the suites in N processes at once, output in declaration order (default 1; 0: one per processor)")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                text = trimmed(text);
                bool digits = !text.empty() && text.size() < 7 && text.find_first_not_of("0123456789") == std::string::npos;
                return digits ? std::string() : "'" + text + "' is not a number of processes (0 or more)";
            },
            "", "N"))
        ->type_name("N");
    cmd->add_option_function<std::string>(
           "--shard",
           [&test](const std::string& text) {
               test.shard = std::stoul(text.substr(0, text.find('/')));
               test.shards = std::stoul(text.substr(text.find('/') + 1));
           },
           "run only the K-th of N slices of the suites (declaration order), e.g. one per CI machine")
        ->transform(shardValidator())
        ->type_name("K/N");
    cmd->add_option("--tcunit-param", test.tcunitParams,
                    "set one of TcUnit's library parameters (GVL_Param_TcUnit), e.g. MaxNumberOfTestsForEachTestSuite=200 (repeatable)")
        ->type_name("NAME=VALUE")
        ->allow_extra_args(false);
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
    if (!test.junit.empty()) {
        // Checked before anything runs: a regular file or a new one, none of the inputs.
        std::vector<std::string> inputs = line.stimulusFiles;
        for (int i = 0; i < sources.size(); ++i) inputs.push_back(sources.file(i).path);
        if (std::string problem = rt::outputPathProblem("--junit", test.junit, inputs); !problem.empty()) return usage(problem);
    }
    // TcUnit's library parameters: --tcunit-param wins over a .plcproj under a project folder.
    sema::CompileOptions compile = line.compile;
    for (const auto& p : test.tcunitParams)
        if (!testing::parseTcUnitParameter(p, compile.tcunitParameters, error)) return usage(error);
    for (const auto& path : line.files)
        if (!testing::readPlcprojParameters(path, compile.tcunitParameters, error)) return usage(error);
    auto model = testing::compileForTests(sources, indices, log, compile);
    if (printDiagnostics(log, sources, line.diagnostics, std::cerr, stderrWantsColor(line.diagnostics.color))) return kExitCompile;
    if (!model) return kExitCompile;
    testing::TestRegistry& reg = *model->tests;
    reg.filter = test.filter;
    const size_t declaredSuites = reg.suites.size();
    if (test.shards > 0) testing::keepSlice(reg, test.shard - 1, test.shards);
    if (test.list) {
        testing::printTestList(reg, std::cout);
        return kExitOk;
    }
    // Stimulus, as for run (with the target's input aliases).
    rt::Stimulus stimulus;
    if (!buildCommandLineStimulus(line, *model, run.profile ? *run.profile : rt::defaultProfile(), stimulus, error)) return usage(error);
    if (!stimulus.empty()) run.stimulus = &stimulus;
    if (declaredSuites == 0)
        std::cerr << "strun: " << (test.allowEmpty ? "warning: " : "") << "no test suite runs: declare instances of FUNCTION_BLOCKs that EXTEND FB_TestSuite "
                     "in a PROGRAM that calls RUN(), or leave RUN() out and strun adds one\n";
    if (declaredSuites > 0 && reg.suites.empty()) {
        // More shards than suites: the other shards run them all, so this one is not a silent pass.
        std::cout << "0 passed, 0 failed\n";
        std::cerr << "strun: note: shard " << test.shard << "/" << test.shards << " holds no suite (the project has " << declaredSuites
                  << ")\n";
        if (!test.junit.empty() && !testing::writeJUnit(reg, sources, 0, test.junit, error)) {
            std::cerr << "strun: --junit: " << error << "\n";
            return kExitCompile;
        }
        return kExitOk;
    }
    const bool color = fdWantsColor(line.diagnostics.color, 1);
    size_t jobs = test.jobs == 0 ? processorCount() : test.jobs;
    jobs = std::min(jobs, reg.suites.size());
    testing::TestCounts counts;
    bool junitWritten = true;
    std::vector<ChildSlice> slices;
    if (jobs > 1) {
        // Each child runs its slice of the suites and leaves its counts and JUnit report in its directory.
        slices = runInChildren(jobs, [&](size_t k, const std::string& dir) {
            testing::keepSlice(reg, k, jobs);
            SliceOutcome o = runSlice(*model, run, test, sources, test.junit.empty() ? std::string() : dir + "/junit.xml", false, color);
            std::ofstream(dir + "/counts") << o.counts.passed << ' ' << o.counts.failed << ' ' << o.counts.skipped << '\n';
            return o.junitWritten ? 0 : 1;
        });
    }
    if (!slices.empty()) {
        std::vector<std::string> reports;
        for (const auto& slice : slices) {
            testing::TestCounts c;
            if (!(std::ifstream(slice.dir + "/counts") >> c.passed >> c.failed >> c.skipped)) {
                std::cerr << "strun: a test process ended without results\n";
                c.failed = 1;
            }
            counts.passed += c.passed;
            counts.failed += c.failed;
            counts.skipped += c.skipped;
            if (slice.exitCode != 0) junitWritten = false;
            reports.push_back(slice.dir + "/junit.xml");
        }
        std::cout << counts.passed << " passed, " << counts.failed << " failed\n";
        std::cout.flush();
        if (!test.junit.empty() && junitWritten && !testing::mergeJUnit(reports, test.junit, error)) {
            std::cerr << "strun: --junit: " << error << "\n";
            junitWritten = false;
        }
        removeSliceDirs(slices);
    } else {
        SliceOutcome o = runSlice(*model, run, test, sources, test.junit, true, color);
        counts = o.counts;
        junitWritten = o.junitWritten;
    }
    if (!junitWritten) return kExitCompile;
    // No test at all is a silent pass in CI (a wrong path, a mistyped --filter): an error unless asked for.
    bool empty = counts.passed + counts.failed == 0;
    if (empty && declaredSuites > 0)
        std::cerr << "strun: " << (test.allowEmpty ? "warning: " : "") << "no test ran"
                  << (test.filter.empty() ? std::string(": the suites declare none") : ": --filter '" + test.filter + "' matches no test")
                  << "\n";
    if (empty) explainOwnTcUnit(*model, sources);
    if (empty && !test.allowEmpty) return kExitCompile;
    return counts.failed == 0 ? kExitOk : kExitCompile;
}

}  // namespace strun::cli
