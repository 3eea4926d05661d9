// Test support for the interpreter stage: compile ST source text as a
// project (together with the embedded standard library, as the CLI does) and
// run it on the virtual clock with the real scheduler and the project's
// TaskRunner, then look at what the --dump would show.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "interpreter/project/compile.h"
#include "interpreter/project/dump_json.h"
#include "interpreter/project/task_runner.h"
#include "runtime/scheduler.h"

namespace strun::test {

// The file name user sources get; messages about them carry this file index.
inline constexpr const char* kTestFile = "test.st";

struct Compiled {
    SourceSet sources;
    CompileLog log;
    int userFile = -1;
    std::unique_ptr<sema::ProgramModel> model;  // null when it does not compile

    bool ok() const { return model != nullptr; }
    // Every message of one severity, in the order reported.
    std::vector<CompileMessage> messages(Severity severity) const {
        std::vector<CompileMessage> out;
        for (const auto& m : log.messages())
            if (m.severity == severity) out.push_back(m);
        return out;
    }
    std::vector<CompileMessage> errors() const { return messages(Severity::Error); }
    std::vector<CompileMessage> warnings() const { return messages(Severity::Warning); }
    // True when some message of `severity` contains `text`.
    bool has(Severity severity, const std::string& text) const {
        for (const auto& m : log.messages())
            if (m.severity == severity && m.message.find(text) != std::string::npos) return true;
        return false;
    }
    bool hasError(const std::string& text) const { return has(Severity::Error, text); }
    bool hasWarning(const std::string& text) const { return has(Severity::Warning, text); }
    // The first message containing `text`, for location checks.
    std::optional<CompileMessage> find(const std::string& text) const {
        for (const auto& m : log.messages())
            if (m.message.find(text) != std::string::npos) return m;
        return std::nullopt;
    }
    // A variable of a POU (PROGRAM, FUNCTION_BLOCK, FUNCTION) by name, any case; null when absent.
    const sema::VarSym* var(const std::string& pou, const std::string& name) const {
        if (!model) return nullptr;
        for (const auto& p : model->pouStore) {
            if (sema::upper(p->name) != sema::upper(pou)) continue;
            auto it = p->vars.find(sema::upper(name));
            if (it != p->vars.end()) return it->second;
        }
        return nullptr;
    }
    // The type of a variable of a POU (null when absent).
    const sema::Type* typeOf(const std::string& pou, const std::string& name) const {
        const sema::VarSym* v = var(pou, name);
        return v ? v->type : nullptr;
    }
    // Every message, compiler style, for failure output.
    std::string printed() const {
        std::ostringstream out;
        log.print(out, sources);
        return out.str();
    }
};

// `strict`: --strict (IEC typing; the default is CODESYS-compatible, decision 0090).
// `inlineCalls`: small leaf FUNCTIONs inlined (decision 0317; off under the debugger).
inline std::unique_ptr<Compiled> compileSt(const std::string& source, bool strict = false, bool inlineCalls = true) {
    auto c = std::make_unique<Compiled>();
    c->userFile = c->sources.add(kTestFile, source);
    sema::CompileOptions options;
    options.strict = strict;
    options.inlineCalls = inlineCalls;
    c->model = project::compileProject(c->sources, {c->userFile}, c->log, options);
    return c;
}

struct RunOutcome {
    std::unique_ptr<Compiled> compiled;  // keeps the model (process image, types) alive
    rt::PlcState state = rt::PlcState::Run;
    rt::PlcTime endTime = 0;
    nlohmann::ordered_json programs;  // project::programsJson
    nlohmann::ordered_json globals;   // project::globalsJson
    nlohmann::json tasks;
    std::vector<rt::DiagEntry> diagnostics;

    bool ok() const { return compiled && compiled->ok(); }
    sema::ProgramModel& model() const { return *compiled->model; }
    const rt::ProcessImage& image() const { return compiled->model->machine.image; }
    // programs[instance][var], the usual thing a test looks at.
    const nlohmann::ordered_json& var(const std::string& program, const std::string& name) const {
        return programs.at(program).at(name);
    }
    size_t count(rt::DiagCode code) const {
        size_t n = 0;
        for (const auto& d : diagnostics) n += d.code == code;
        return n;
    }
    const char* stateName() const { return rt::plcStateName(state); }
};

struct RunSettings {
    uint64_t cycles = 1;
    std::string cyclesTask;  // "" = the first task (MainTask without a CONFIGURATION)
    rt::PlcTime stmtCost = 1000;
    // Called after compiling, before the run: set physical inputs and the like.
    std::function<void(sema::ProgramModel&)> beforeRun;
};

// Compiles and runs `source` for `settings.cycles` cycles. When it does not
// compile, the outcome has no programs and `compiled->log` says why.
inline RunOutcome runSt(const std::string& source, RunSettings settings) {
    RunOutcome out;
    out.compiled = compileSt(source);
    if (!out.compiled->ok()) return out;
    sema::ProgramModel& model = *out.compiled->model;
    std::vector<rt::TaskSpec> specs;
    for (const auto& t : model.tasks) specs.push_back(t.spec);
    std::vector<std::unique_ptr<project::TaskRunner>> runners;
    std::vector<rt::TaskBody*> bodies;
    for (const auto& t : model.tasks) {
        runners.push_back(std::make_unique<project::TaskRunner>(model, t));
        bodies.push_back(runners.back().get());
    }
    rt::RunOptions options;
    options.virtualClock = true;
    options.stmtCost = settings.stmtCost;
    options.cycles = settings.cycles;
    options.cyclesTask = !settings.cyclesTask.empty() ? settings.cyclesTask : (specs.empty() ? "" : specs.front().name);
    if (settings.beforeRun) settings.beforeRun(model);
    rt::Scheduler scheduler(model.machine, specs, bodies, options);
    out.state = scheduler.run();
    out.endTime = scheduler.endTime();
    out.programs = project::programsJson(model);
    out.globals = project::globalsJson(model);
    out.tasks = scheduler.tasksJson();
    out.diagnostics = scheduler.diagnostics();
    return out;
}

inline RunOutcome runSt(const std::string& source, uint64_t cycles = 1) {
    RunSettings settings;
    settings.cycles = cycles;
    return runSt(source, settings);
}

// Wraps statements in PROGRAM Main with the given declarations and runs it.
inline RunOutcome runMain(const std::string& vars, const std::string& body, uint64_t cycles = 1) {
    return runSt("PROGRAM Main\nVAR\n" + vars + "\nEND_VAR\n" + body + "\nEND_PROGRAM\n", cycles);
}

// Compiles PROGRAM Main with the given declarations and body (for checker tests).
inline std::unique_ptr<Compiled> compileMain(const std::string& vars, const std::string& body, bool strict = false) {
    return compileSt("PROGRAM Main\nVAR\n" + vars + "\nEND_VAR\n" + body + "\nEND_PROGRAM\n", strict);
}

}  // namespace strun::test
