// strun: the command line of shared/contract.md.
//   strun run   [options] FILE...   compile the FILEs as one project and run it
//   strun check [options] FILE...   compile only; print diagnostics
// Exit status: 0 ok, 1 does not compile, 2 bad command line, 3 PLC STOP/HALT.
#include <csignal>
#include <fstream>
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/test_command.h"
#include "interpreter/project/compile.h"
#include "interpreter/project/dump_json.h"
#include "interpreter/project/task_runner.h"
#include "runtime/scheduler.h"
#include "stdlib/time_literals.h"
#include "stdlib/value_format.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitCompile = 1;
constexpr int kExitUsage = 2;
constexpr int kExitStopped = 3;

struct Options {
    std::vector<std::string> files;
    bool virtualClock = false;
    std::string stmtCost;
    std::string cycles;
    std::string task;
    std::string forDuration;
    std::string start;
    bool dump = false;
    bool trace = false;
    bool realtime = false;
};

int usage(const std::string& message) {
    std::cerr << "strun: " << message << "\n";
    return kExitUsage;
}

bool readFiles(const std::vector<std::string>& files, strun::SourceSet& sources, std::vector<int>& indices, std::string& error) {
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        if (!in) {
            error = "cannot open '" + f + "'";
            return false;
        }
        std::stringstream ss;
        ss << in.rdbuf();
        indices.push_back(sources.add(f, ss.str()));
    }
    return true;
}

extern "C" void onSigint(int) { strun::rt::Scheduler::requestStop(); }

int runCommand(const Options& o, bool execute) {
    strun::rt::RunOptions run;
    run.virtualClock = o.virtualClock;
    if (!o.stmtCost.empty()) {
        if (!o.virtualClock) return usage("--stmt-cost needs --virtual");
        auto r = strun::stdlib::parseDurationLiteral(o.stmtCost);
        if (!r || r.value() < 0) return usage("--stmt-cost: '" + o.stmtCost + "' is not a duration (e.g. 1us, T#2us)");
        run.stmtCost = r.value();
    } else {
        run.stmtCost = o.virtualClock ? 1000 : 0;
    }
    if (!o.cycles.empty()) {
        char* end = nullptr;
        errno = 0;
        unsigned long long n = std::strtoull(o.cycles.c_str(), &end, 10);
        if (errno || !end || *end || o.cycles[0] == '-' || o.cycles.empty()) return usage("--cycles: '" + o.cycles + "' is not a count");
        run.cycles = n;
    }
    if (!o.forDuration.empty()) {
        auto r = strun::stdlib::parseDurationLiteral(o.forDuration);
        if (!r || r.value() < 0) return usage("--for: '" + o.forDuration + "' is not a duration (e.g. T#10s, 150ms)");
        run.duration = r.value();
    }
    if (!o.start.empty()) {
        if (!o.virtualClock) return usage("--start needs --virtual");
        auto r = strun::stdlib::parseDateTimeLiteral(o.start);
        if (!r) return usage("--start: '" + o.start + "' is not a date and time (e.g. DT#2026-01-31-13:05:00): " + r.error());
        run.startCalendarNanos = r.value();
    }
    run.realtime = o.realtime;
    if (o.trace) run.trace = &std::cerr;

    strun::SourceSet sources;
    std::vector<int> files;
    std::string err;
    if (!readFiles(o.files, sources, files, err)) return usage(err);
    strun::CompileLog log;
    auto model = strun::project::compileProject(sources, files, log);
    log.print(std::cerr, sources);
    if (!model) return kExitCompile;
    if (!execute) return kExitOk;

    std::vector<strun::rt::TaskSpec> specs;
    for (const auto& t : model->tasks) specs.push_back(t.spec);
    if (!o.task.empty()) {
        if (!strun::rt::Scheduler::hasTask(specs, o.task)) return usage("--task: no task named '" + o.task + "'");
        run.cyclesTask = o.task;
    } else if (!specs.empty()) {
        run.cyclesTask = specs.front().name;  // MainTask without a CONFIGURATION, else the first TASK declared
    }
    std::vector<std::unique_ptr<strun::project::TaskRunner>> runners;
    std::vector<strun::rt::TaskBody*> bodies;
    for (const auto& t : model->tasks) {
        runners.push_back(std::make_unique<strun::project::TaskRunner>(*model, t));
        bodies.push_back(runners.back().get());
    }
    strun::rt::Scheduler scheduler(model->machine, specs, bodies, run);
    std::signal(SIGINT, onSigint);
    std::signal(SIGTERM, onSigint);
    strun::rt::PlcState state = scheduler.run();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    if (o.dump) {
        nlohmann::ordered_json out;
        out["state"] = strun::rt::plcStateName(state);
        out["time"] = strun::stdlib::formatDuration(scheduler.endTime());
        out["globals"] = strun::project::globalsJson(*model);
        out["programs"] = strun::project::programsJson(*model);
        out["tasks"] = scheduler.tasksJson();
        out["diagnostics"] = scheduler.diagnosticsJson();
        std::cout << out.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << std::endl;
    }
    return state == strun::rt::PlcState::Run ? kExitOk : kExitStopped;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        CLI::App app{"strun: IEC 61131-3 Structured Text interpreter with a PLC task runtime"};
        app.require_subcommand(1);
        Options o;
        auto* run = app.add_subcommand("run", "compile the FILEs as one project and run it");
        run->add_option("FILE", o.files, "source files")->required();
        run->add_flag("--virtual", o.virtualClock, "simulated clock: deterministic, as fast as the host can");
        run->add_option("--stmt-cost", o.stmtCost, "virtual time one executed statement costs (default 1us)");
        run->add_option("--cycles", o.cycles, "stop after the counted task completed N cycles");
        run->add_option("--task", o.task, "the task --cycles counts");
        run->add_option("--for", o.forDuration, "stop after DURATION of PLC time");
        run->add_option("--start", o.start, "calendar date-time the virtual clock starts at");
        run->add_flag("--dump", o.dump, "print the final state as JSON on stdout");
        run->add_flag("--trace", o.trace, "print task events on stderr");
        run->add_flag("--realtime", o.realtime, "ask for SCHED_FIFO and locked memory");
        auto* check = app.add_subcommand("check", "compile only; print diagnostics");
        check->add_option("FILE", o.files, "source files")->required();
        strun::cli::TestCommandOptions testOptions;
        auto* test = strun::cli::addTestCommand(app, testOptions);
        try {
            app.parse(argc, argv);
        } catch (const CLI::CallForHelp& e) {
            return app.exit(e);
        } catch (const CLI::CallForAllHelp& e) {
            return app.exit(e);
        } catch (const CLI::ParseError& e) {
            std::string what = e.what();
            if (what.empty()) what = e.get_name();
            return usage(what);
        }
        if (test->parsed()) return strun::cli::runTestCommand(testOptions);
        if (run->parsed()) return runCommand(o, true);
        return runCommand(o, false);
    } catch (const std::bad_alloc&) {
        std::cerr << "strun: out of memory\n";
        return kExitCompile;
    } catch (const std::exception& e) {
        // Never a raw exception text on the terminal: a short, stable message.
        std::cerr << "strun: internal error (" << (std::getenv("STRUN_DEBUG") ? e.what() : "set STRUN_DEBUG=1 for details") << ")\n";
        return kExitCompile;
    } catch (...) {
        std::cerr << "strun: internal error\n";
        return kExitCompile;
    }
}
