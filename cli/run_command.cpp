// strun run [options] FILE...: compile the FILEs as one project and run it.
#include <algorithm>
#include <filesystem>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/compile_step.h"
#include "cli/exit_codes.h"
#include "cli/option_types.h"
#include "cli/diagnostic_render.h"
#include "cli/live_options.h"
#include "cli/modbus_options.h"
#include "cli/run_report.h"
#include "cli/stimulus_args.h"
#include "cli/usage_errors.h"
#include "interpreter/project/stimulus_build.h"
#include "interpreter/source/closest_name.h"
#include "interpreter/project/vcd_signals.h"
#include "runtime/vcd_recorder.h"
#include "interpreter/project/dump_json.h"
#include "interpreter/project/retain_store.h"
#include "runtime/system_area.h"
#include "runtime/file_sandbox.h"
#include "interpreter/project/task_runner.h"
#include "interpreter/project/variable_path.h"
#include "runtime/output_files.h"
#include "runtime/plc_profile.h"
#include "runtime/scheduler.h"
#include "stdlib/time_literals.h"
#include "stdlib/value_format.h"

namespace strun::cli {

namespace {

extern "C" void onStopSignal(int) { rt::Scheduler::requestStop(); }

// The files the run reads: no output may name one of them.
std::vector<std::string> runInputs(const SourceSet& sources, const std::vector<std::string>& stimulusFiles) {
    std::vector<std::string> inputs = stimulusFiles;
    for (int i = 0; i < sources.size(); ++i)
        if (!sources.file(i).path.empty()) inputs.push_back(sources.file(i).path);
    return inputs;
}

// Closes an output written through stdio; false (reported) when a write, the flush or the close failed.
bool closeOutput(std::FILE* file, const char* option, const std::string& path) {
    const bool written = !std::ferror(file);
    errno = 0;
    const bool closed = std::fclose(file) == 0;
    if (written && closed) return true;
    std::cerr << "strun: " << option << ": cannot write '" << path << "'" << (errno ? std::string(": ") + std::strerror(errno) : "")
              << "; the file is incomplete\n";
    return false;
}

}  // namespace

// The run options that do not depend on the compiled project.
bool buildRunOptions(const CommandLine& line, rt::RunOptions& run, std::string& error) {
    run.virtualClock = line.virtualClock;
    if (line.stmtCost && !line.virtualClock) {
        error = "--stmt-cost needs --virtual";
        return false;
    }
    if (line.start && !line.virtualClock) {
        error = "--start needs --virtual";
        return false;
    }
    // The calendar is 64-bit ns since 1970: a start after 2116 could not take
    // PLC time to its limit (2^62 ns) without overflowing it (decision 0252).
    constexpr int64_t kLatestStart = int64_t{53325} * 86400 * 1'000'000'000;  // DT#2116-01-01-00:00:00
    static_assert(std::numeric_limits<int64_t>::max() - kLatestStart >= rt::kPlcTimeLimit + 2 * rt::kMaxStmtCost, "room for all PLC time");
    if (line.start && (*line.start < 0 || *line.start > kLatestStart)) {
        error = "--start: the PLC calendar runs from DT#1970-01-01-00:00:00 to DT#2116-01-01-00:00:00 (all of its PLC time, "
                "up to 146 years, must fit the 64-bit nanosecond calendar)";
        return false;
    }
    if (line.stmtCost && *line.stmtCost > rt::kMaxStmtCost) {
        error = "--stmt-cost: above the limit of 1d";
        return false;
    }
    run.stmtCost = line.stmtCost.value_or(line.virtualClock ? 1000 : 0);
    run.cycles = line.cycles;
    run.duration = line.forDuration;
    run.startCalendarNanos = line.start.value_or(0);
    run.realtime = line.realtime;
    run.profile = rt::findProfile(line.compile.target);
    if (line.trace) run.trace = &std::cerr;
    return true;
}

CLI::App* addRunCommand(CLI::App& app, CommandLine& line) {
    CLI::App* run = app.add_subcommand("run", "compile the FILEs as one project and run it");
    addFileArguments(*run, line);
    addCompileOptions(*run, line);
    run->add_flag("--virtual", line.virtualClock, "simulated clock: deterministic, as fast as the host can");
    run->add_option_function<std::string>(
           "--stmt-cost", [&line](const std::string& text) { line.stmtCost = validatedDuration(text); },
           "virtual time one executed statement costs (default 1us; only with --virtual)")
        ->transform(durationValidator())
        ->type_name("DURATION");
    run->add_option_function<std::string>(
           "--cycles", [&line](const std::string& text) { line.cycles = std::stoull(text); },
           "stop after the task named by --task completed N cycles")
        ->transform(positiveCountValidator())
        ->type_name("N");
    run->add_option("--task", line.task, "the task --cycles counts (default MainTask, or the first TASK declared)")->type_name("NAME");
    run->add_option_function<std::string>(
           "--for", [&line](const std::string& text) { line.forDuration = validatedDuration(text); },
           "stop after DURATION of PLC time")
        ->transform(durationValidator())
        ->type_name("DURATION");
    run->add_option_function<std::string>(
           "--start", [&line](const std::string& text) { line.start = stdlib::parseDateTimeLiteral(text).value(); },
           "calendar date-time the virtual clock starts at (default DT#1970-01-01-00:00:00)")
        ->transform(dateTimeValidator())
        ->type_name("DT");
    run->add_flag("--dump", line.dump, "when the run stops, print the final state as one JSON object on stdout");
    run->add_flag("--trace", line.trace, "print task events with PLC time on stderr");
    run->add_flag("--quiet", line.quiet, "no summary on stderr when the run ends (fault lines are still printed)");
    run->add_flag("--realtime", line.realtime, "ask for SCHED_FIFO and locked memory (real clock)");
    run->add_option("--set", line.sets,
                    "at PLC time TIME (default 0) write the ST literal VALUE to a variable or direct input (repeatable)")
        ->type_name("NAME=VALUE[@TIME]")
        ->allow_extra_args(false);  // one value per --set: FILEs follow
    run->add_option("--vcd", line.vcdFile, "write a Value Change Dump of the run (tasks and variables; opens in GTKWave)")
        ->type_name("FILE");
    run->add_option("--watch", line.watches, "the variables --vcd records, by path with * wildcards (repeatable; default: all)")
        ->type_name("PATTERN")
        ->allow_extra_args(false);
    run->add_flag("--vcd-text", line.vcdText, "--vcd records enumerations by their value names and STRINGs as text (string signals)");
    run->add_option("--stimulus", line.stimulusFiles, "a CSV file of TIME,NAME,VALUE lines: many --set at once")
        ->check(readableFileValidator())
        ->type_name("FILE")
        ->allow_extra_args(false);
    run->add_option("--retain", line.retainFile,
                    "keep RETAIN/PERSISTENT variables in FILE: restored at start, saved periodically and at the end")
        ->type_name("FILE");
    run->add_option("--files", line.filesDir,
                    "the directory the PLC's file blocks (FB_FileOpen ...) work in; no path leaves it (default: "
                    "strun-files beside the --retain file, else a temporary directory removed at the end)")
        ->type_name("DIR");
    run->add_flag("--cold", line.cold, "cold start: ignore the --retain file at start (initial values)");
    run->add_option_function<std::string>(
           "--retain-every", [&line](const std::string& text) { line.retainEvery = validatedDuration(text); },
           "save the --retain file every DURATION of real time (default 1s; 0: only at the end)")
        ->transform(durationValidator())
        ->type_name("DURATION");
    addLiveOptions(*run, line.live);
    addModbusOptions(*run, line);
    return run;
}

bool parseRunArguments(const std::vector<std::string>& arguments, CommandLine& line, std::string& error) {
    CLI::App app{"strun", "strun"};
    addRunCommand(app, line);
    std::vector<std::string> argv{"run"};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    std::reverse(argv.begin(), argv.end());
    try {
        app.parse(argv);
    } catch (const CLI::ParseError& e) {
        error = e.what();
        return false;
    }
    return true;
}

int runCommand(const CommandLine& line) {
    rt::RunOptions run;
    std::string error;
    if (!buildRunOptions(line, run, error)) return usage(error);
    ModbusSetup modbusSetup;  // --modbus, --modbus-client (cli/modbus_options.h)
    if (!prepareModbus(line, modbusSetup, error)) return usage(error);
    if (!line.watches.empty() && line.vcdFile.empty()) return usage("--watch selects what --vcd records: give --vcd FILE too");
    if (line.vcdText && line.vcdFile.empty()) return usage("--vcd-text changes what --vcd records: give --vcd FILE too");

    Compiled compiled;
    compileCommandLine(line, compiled);
    if (!compiled.model) return compiled.exitCode;
    sema::ProgramModel& model = *compiled.model;

    for (int i = 0; i < compiled.sources.size(); ++i) run.sourceFiles.push_back(compiled.sources.file(i).path);
    // Faults in sources converted from XML are reported at the XML line and column, like compile errors.
    run.originalPosition = [&sources = compiled.sources](int file, int line, int col) {
        return file < sources.size() ? sources.file(file).original(line, col) : std::pair<int, int>{line, col};
    };
    std::vector<rt::TaskSpec> specs;
    for (const auto& t : model.tasks) specs.push_back(t.spec);
    if (run.cycles && specs.empty()) return usage("--cycles: the project declares no TASK (its CONFIGURATION has none)");
    if (!line.task.empty()) {
        if (!rt::Scheduler::hasTask(specs, line.task)) {
            std::vector<std::string> names;
            for (const auto& spec : specs) names.push_back(spec.name);
            const std::string near = closestName(line.task, names);
            return usage("--task: no task named '" + line.task + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?"));
        }
        run.cyclesTask = line.task;
    } else if (!specs.empty()) {
        run.cyclesTask = specs.front().name;  // MainTask without a CONFIGURATION, else the first TASK declared
    }
    rt::Stimulus stimulus;
    if (!buildCommandLineStimulus(line, model, run.profile ? *run.profile : rt::defaultProfile(), stimulus, error))
        return usage(error);
    if (!stimulus.empty()) run.stimulus = &stimulus;

    // Output files are checked before anything is written (docs/cli.md "Files strun reads and writes").
    const std::vector<std::string> inputs = runInputs(compiled.sources, line.stimulusFiles);
    if (!line.vcdFile.empty()) {
        std::vector<std::string> taken = inputs;
        if (!line.retainFile.empty()) taken.push_back(line.retainFile);
        if (std::string problem = rt::outputPathProblem("--vcd", line.vcdFile, taken); !problem.empty()) return usage(problem);
    }

    // --retain: RETAIN/PERSISTENT variables restored now (warm start unless
    // --cold), saved periodically between activations and at the end.
    std::unique_ptr<project::RetainStore> retain;
    if (!line.retainFile.empty()) {
        retain = std::make_unique<project::RetainStore>(model, line.retainFile, std::cerr);
        if (run.profile && run.profile->systemVariables == rt::SystemVariables::Modicon)
            retain->keepSystemWords(model, rt::SystemArea::wordsKeptOverWarmStart());  // max/min cycle times (decision 0296)
        if (!retain->start(line.cold, inputs, error)) return usage(error);
        retain->setInterval(std::chrono::nanoseconds(line.retainEvery.value_or(1'000'000'000)));
    } else if (line.cold || line.retainEvery) {
        return usage(std::string(line.cold ? "--cold" : "--retain-every") + " needs --retain FILE");
    }

    // --files: where FB_FileOpen and the other file blocks work (decision 0221).
    if (!line.filesDir.empty()) rt::fileSandbox().setRoot(line.filesDir);
    else if (!line.retainFile.empty()) rt::fileSandbox().setRoot((std::filesystem::path(line.retainFile).parent_path() / "strun-files").string());

    // --vcd: the recorder observes the run; without it the scheduler has no observer at all.
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> vcdFile(nullptr, std::fclose);
    std::unique_ptr<rt::VcdRecorder> recorder;
    if (!line.vcdFile.empty()) {
        vcdFile.reset(rt::openRegularOutput(line.vcdFile, error));
        if (!vcdFile) return usage("--vcd: " + error);
        std::vector<std::string> unmatched, variablePatterns;
        std::vector<std::string> taskNames;
        for (const auto& t : model.tasks) taskNames.push_back(t.spec.name);
        // --watch 'task:PATTERN' / '!task:PATTERN' choose the task waveforms (decision 0241).
        std::vector<bool> taskWaveforms = project::vcdTaskSelection(taskNames, line.watches, variablePatterns, unmatched);
        std::vector<rt::VcdSignal> signals;  // --watch with task patterns only: no variable
        bool truncated = false;
        if (line.watches.empty() || !variablePatterns.empty())
            signals = project::vcdSignals(model, variablePatterns, unmatched, truncated, line.vcdText);
        if (truncated)
            std::cerr << "strun: warning: --vcd: more than " << project::kMaxVcdSignals
                      << " variables to record; the first ones are recorded (--watch picks which)\n";
        for (const std::string& pattern : unmatched) {
            // A plain path gets the resolver's reason, with its "did you mean".
            std::string why;
            const bool task = std::find(variablePatterns.begin(), variablePatterns.end(), pattern) == variablePatterns.end();
            if (!task && pattern.find_first_of("*?") == std::string::npos) project::resolveVariablePath(model, pattern, why);
            std::cerr << "strun: warning: --watch '" << pattern << "' matches no " << (task ? "task" : "variable")
                      << (why.empty() ? "" : " (" + why + ")") << "\n";
        }
        recorder = std::make_unique<rt::VcdRecorder>(vcdFile.get(), taskNames, std::move(signals), "strun " STRUN_VERSION, taskWaveforms);
        run.observer = recorder.get();
    }

    // --force, --paused, --serve: the control plane of a live run (cli/live_options.h).
    std::unique_ptr<LiveSession> live =
        LiveSession::start(line.live, model, run.profile ? *run.profile : rt::defaultProfile(), specs, run.cyclesTask, run, error);
    if (!live && !error.empty()) return usage(error);
    ModbusRun modbus;
    if (live && !modbus.start(modbusSetup, live->control(), run, std::cerr, error)) return usage(error);

    std::vector<std::unique_ptr<project::TaskRunner>> runners;
    std::vector<rt::TaskBody*> bodies;
    for (const auto& t : model.tasks) {
        runners.push_back(std::make_unique<project::TaskRunner>(model, t));
        runners.back()->setRetainStore(retain.get());
        bodies.push_back(runners.back().get());
    }
    rt::Scheduler scheduler(model.machine, specs, bodies, run);
    // The virtual clock runs as fast as the host can: without an end it would look hung.
    if (run.virtualClock && !run.cycles && !run.duration && !line.quiet)
        std::cerr << "strun: note: --virtual without --for or --cycles runs until interrupted (Ctrl-C)\n";
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
    rt::PlcState state = scheduler.run();
    if (live) live->runEnded(scheduler);
    modbus.stop();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    // Every output is checked to its end: one that failed is reported and the exit status is 2.
    bool outputFailed = retain && !retain->save();  // however the run ended
    if (vcdFile && !closeOutput(vcdFile.release(), "--vcd", line.vcdFile)) outputFailed = true;
    rt::fileSandbox().finish();
    printFaultReport(std::cerr, scheduler, compiled.sources, line.diagnostics, stderrWantsColor(line.diagnostics.color));
    if (!line.dump && !line.quiet)
        printRunSummary(std::cerr, scheduler, state, line.diagnostics.format,
                        live ? live->forcesJson() : nlohmann::ordered_json::object());
    if (line.dump) {
        nlohmann::ordered_json out;
        out["state"] = rt::plcStateName(state);
        out["time"] = stdlib::formatDuration(scheduler.endTime());
        out["target"] = line.compile.target;
        out["globals"] = project::globalsJson(model);
        out["programs"] = project::programsJson(model);
        out["tasks"] = scheduler.tasksJson();
        out["diagnostics"] = scheduler.diagnosticsJson();
        out["forces"] = live ? live->forcesJson() : nlohmann::ordered_json::object();
        out["physical_outputs"] = project::physicalOutputsJson(model);
        std::cout << out.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << std::endl;
        if (!std::cout) {
            std::cerr << "strun: --dump: cannot write the state to standard output\n";
            outputFailed = true;
        }
    }
    if (outputFailed) return kExitUsage;
    return state == rt::PlcState::Run ? kExitOk : kExitStopped;
}

}  // namespace strun::cli
