#include "editors/dap/dap_server.h"

#include <algorithm>
#include <cstring>
#include <iostream>
#include <filesystem>
#include <sstream>

#include "cli/commands.h"
#include "cli/diagnostic_render.h"
#include "cli/run_report.h"
#include "cli/stimulus_args.h"
#include "editors/dap/debug_values.h"
#include "live/control_plane.h"
#include "interpreter/project/compile.h"
#include "interpreter/project/literal_value.h"
#include "interpreter/source/project_inputs.h"
#include "runtime/plc_profile.h"
#include "runtime/scheduler.h"

namespace strun::editors::dap {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

std::string normalPath(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::absolute(fs::path(path), ec);
    if (ec) p = fs::path(path);
    return p.lexically_normal().string();
}

void statementLinesOf(const ast::StmtList& list, const SourceFile& file, std::vector<int>& out) {
    for (const auto& s : list) {
        if (!s) continue;
        if (s->kind != ast::StmtKind::Label && s->kind != ast::StmtKind::Empty && s->loc.line > 0)
            out.push_back(file.original(s->loc.line, s->loc.col).first);
        for (const auto& b : s->blocks) statementLinesOf(b, file, out);
        for (const auto& c : s->cases) statementLinesOf(c.body, file, out);
        statementLinesOf(s->body, file, out);
        if (s->elseBlock) statementLinesOf(*s->elseBlock, file, out);
    }
}

// Frame ids: task and call depth in one number.
constexpr int kDepthsPerTask = 64;
int frameIdOf(int task, size_t depth) { return task * kDepthsPerTask + static_cast<int>(depth) + 1; }

}  // namespace

DapServer::DapServer(std::FILE* in, std::FILE* out) : reader_(in), writer_(out) {}

DapServer::~DapServer() {
    if (runThread_.joinable()) {
        if (session_) session_->terminate();
        runThread_.join();
    }
}

void DapServer::event(const std::string& name, json body) {
    std::lock_guard<std::mutex> lock(seqMutex_);
    json message = {{"seq", seq_++}, {"type", "event"}, {"event", name}};
    if (!body.is_null()) message["body"] = std::move(body);
    writer_.send(message);
}

void DapServer::respond(const json& request, bool ok, json body, const std::string& message) {
    std::lock_guard<std::mutex> lock(seqMutex_);
    json r = {{"seq", seq_++},
              {"type", "response"},
              {"request_seq", request.contains("seq") && request["seq"].is_number_integer() ? request["seq"] : json(0)},
              {"success", ok},
              {"command", request.contains("command") && request["command"].is_string() ? request["command"] : json("")}};
    if (!ok) {
        r["message"] = message;
        r["body"] = {{"error", {{"id", 1}, {"format", message}, {"showUser", true}}}};
    } else if (!body.is_null()) {
        r["body"] = std::move(body);
    }
    writer_.send(r);
}

int DapServer::run() {
    Incoming incoming;
    while (reader_.next(incoming)) {
        if (!incoming.message) {
            // Not a message: answered with an error event-free response the client can log.
            event("output", {{"category", "stderr"}, {"output", "strun debug: ignored a malformed message (" + incoming.error + ")\n"}});
            continue;
        }
        const json& message = *incoming.message;
        if (message.value("type", json()).get<std::string>() != "request" && !(message.contains("command") && message["command"].is_string())) continue;
        if (!message.contains("command") || !message["command"].is_string()) {
            respond(message, false, nullptr, "a request needs a command");
            continue;
        }
        const std::string command = message["command"].get<std::string>();
        const json args = message.contains("arguments") && message["arguments"].is_object() ? message["arguments"] : json::object();
        bool ok = true;
        std::string error;
        json body;
        try {
            body = dispatch(command, args, ok, error);
        } catch (const json::exception& e) {
            ok = false;
            error = std::string("invalid arguments: ") + e.what();
        } catch (const std::exception& e) {
            ok = false;
            error = e.what();
        }
        if (command == "disconnect" || command == "terminate") {
            endRun();
            respond(message, true, nullptr, "");
            if (command == "terminate") event("terminated", nullptr);
            return 0;
        }
        respond(message, ok, std::move(body), error);
        // Ready for configuration requests as soon as initialize is answered;
        // breakpoints set before `launch` are verified when it has compiled the project.
        if (command == "initialize" && ok) event("initialized", nullptr);
        if (reportHeldPause_) {
            reportHeldPause_ = false;
            event("stopped", {{"reason", "pause"}, {"threadId", 1}, {"allThreadsStopped", true}});
        }
        if (command == "launch" && !ok) event("terminated", nullptr);
        if ((command == "configurationDone" || command == "launch") && ok && launched_ && configured_ && !runThread_.joinable()) startRun();
    }
    endRun();
    return 0;
}

json DapServer::dispatch(const std::string& command, const json& args, bool& ok, std::string& error) {
    auto needStopped = [&]() {
        if (session_ && session_->stopped()) return true;
        ok = false;
        error = runEnded_ ? "the run has ended" : "the PLC is running: pause it first";
        return false;
    };
    if (command == "initialize") return initialize(args);
    if (command == "launch") {
        ok = launch(args, error);
        return nullptr;
    }
    if (command == "attach") {
        ok = false;
        error = "strun debug launches the project itself: use a launch configuration";
        return nullptr;
    }
    if (command == "configurationDone") {
        configured_ = true;
        return nullptr;
    }
    if (command == "setBreakpoints") return setBreakpoints(args);
    if (command == "setExceptionBreakpoints") {
        bool faults = false;
        for (const auto& f : args.value("filters", json::array()))
            if (f.is_string() && f.get<std::string>() == "runtime-fault") faults = true;
        for (const auto& f : args.value("filterOptions", json::array()))
            if (f.is_object() && f.value("filterId", "") == "runtime-fault") faults = true;
        if (session_) session_->setExceptionBreakpoints(faults);
        else pendingBreakpoints_["<faults>"] = faults;
        return {{"breakpoints", json::array()}};
    }
    if (command == "setFunctionBreakpoints") return {{"breakpoints", json::array()}};
    if (command == "threads") {
        json threads = json::array();
        if (model_)
            for (size_t k = 0; k < model_->tasks.size(); ++k) threads.push_back({{"id", static_cast<int>(k) + 1}, {"name", model_->tasks[k].spec.name}});
        return {{"threads", threads}};
    }
    if (command == "stackTrace") return stackTrace(args);
    if (command == "scopes") return scopes(args, ok, error);
    if (command == "variables") return variables(args, ok, error);
    if (command == "evaluate") return evaluate(args, ok, error);
    if (command == "setVariable") return setVariable(args, ok, error);
    if (command == "exceptionInfo") {
        return {{"exceptionId", "runtime-fault"}, {"description", "runtime fault"}, {"breakMode", "always"}};
    }
    if (command == "continue" && session_ && !session_->stopped() && live_ && live_->control().paused()) {
        // A run started with --paused (or paused between activations by
        // another live front end) resumes through the control plane.
        live_->control().resume();
        return {{"allThreadsContinued", true}};
    }
    if (command == "continue" || command == "next" || command == "stepIn" || command == "stepOut") {
        if (!needStopped()) return nullptr;
        containers_.clear();
        const StepMode mode = command == "continue" ? StepMode::None
                              : command == "next"   ? StepMode::Over
                              : command == "stepIn" ? StepMode::In
                                                    : StepMode::Out;
        session_->resume(mode);
        return command == "continue" ? json{{"allThreadsContinued", true}} : json(nullptr);
    }
    if (command == "pause") {
        if (session_ && !session_->stopped() && live_ && live_->control().paused()) {
            // Held between two activations by the control plane already
            // (--paused, or a pause from another live front end): that is the
            // stop; `continue` resumes it through the plane.
            reportHeldPause_ = true;  // the stopped event follows the response
            return nullptr;
        }
        if (session_) session_->requestPause();
        return nullptr;
    }
    if (command == "disconnect" || command == "terminate") return nullptr;
    if (command == "source") {
        ok = false;
        error = "sources are files: open them by path";
        return nullptr;
    }
    ok = false;
    error = "unsupported request '" + command + "'";
    return nullptr;
}

json DapServer::initialize(const json& args) {
    linesStartAt1_ = args.value("linesStartAt1", true);
    columnsStartAt1_ = args.value("columnsStartAt1", true);
    return {
        {"supportsConfigurationDoneRequest", true},
        {"supportsConditionalBreakpoints", true},
        {"supportsHitConditionalBreakpoints", true},
        {"supportsLogPoints", true},
        {"supportsEvaluateForHovers", true},
        {"supportsSetVariable", true},
        {"supportsTerminateRequest", true},
        {"supportsExceptionInfoRequest", true},
        {"supportTerminateDebuggee", true},
        {"exceptionBreakpointFilters",
         json::array({{{"filter", "runtime-fault"},
                       {"label", "Runtime faults"},
                       {"description", "stop at a statement that faults (DIV_BY_ZERO, ARRAY_BOUNDS, ...) before the PLC reacts"},
                       {"default", false}}})},
    };
}

// ---------------------------------------------------------------- launch

bool DapServer::launch(const json& args, std::string& error) {
    if (launched_) {
        error = "already launched";
        return false;
    }
    std::vector<std::string> programs;
    const json program = args.value("program", json());
    if (program.is_string()) programs.push_back(program.get<std::string>());
    else if (program.is_array())
        for (const auto& p : program)
            if (p.is_string()) programs.push_back(p.get<std::string>());
    if (programs.empty()) {
        error = "launch needs \"program\": a FILE, a DIR or a list of them";
        return false;
    }
    const std::string cwd = args.value("cwd", json()).is_string() ? args["cwd"].get<std::string>() : "";
    for (auto& p : programs)
        if (!cwd.empty() && fs::path(p).is_relative()) p = (fs::path(cwd) / p).string();
    std::vector<std::string> options;
    for (const auto& a : args.value("args", json::array()))
        if (a.is_string()) options.push_back(a.get<std::string>());
    stopOnEntry_ = args.value("stopOnEntry", false);
    // The options are `run`'s, parsed by the same command-line definition.
    cli::CommandLine line;
    std::vector<std::string> arguments = options;
    arguments.push_back("--");
    arguments.insert(arguments.end(), programs.begin(), programs.end());
    std::string parseError;
    if (!cli::parseRunArguments(arguments, line, parseError)) {
        error = "bad \"args\": " + parseError;
        return false;
    }
    line_ = line;
    // The debugger follows calls by their frames and depth: no call is inlined (decision 0317).
    line_.compile.inlineCalls = false;
    if (line_.dump) event("output", {{"category", "console"}, {"output", "strun debug: --dump is ignored (stdout carries the protocol)\n"}});
    std::string usage;
    // The checker kept for evaluate reports into log_: it must live as long.
    if (!source::readProjectInputs(line_.files, sources_, userFiles_, log_, usage)) {
        error = usage;
        return false;
    }
    project::CompileExtras extras;
    extras.keepChecker = &checker_;
    model_ = project::compileProject(sources_, userFiles_, log_, line_.compile, nullptr, &units_, &extras);
    std::ostringstream diagnostics;
    cli::DiagnosticOptions plain;
    plain.color = cli::ColorMode::Never;
    const bool errors = cli::printDiagnostics(log_, sources_, plain, diagnostics, false);
    if (!diagnostics.str().empty()) event("output", {{"category", errors ? "stderr" : "console"}, {"output", diagnostics.str()}});
    if (errors || !model_) {
        model_.reset();
        error = diagnostics.str().empty() ? "the project does not compile" : diagnostics.str();
        return false;
    }
    if (model_->tasks.empty()) {
        error = "the project has no task to run";
        return false;
    }
    if (!line_.task.empty() && !rt::Scheduler::hasTask([&] {
            std::vector<rt::TaskSpec> s;
            for (const auto& t : model_->tasks) s.push_back(t.spec);
            return s;
        }(), line_.task)) {
        error = "--task: no task named '" + line_.task + "'";
        return false;
    }
    const rt::PlcProfile* profile = rt::findProfile(line_.compile.target);
    if (!cli::buildCommandLineStimulus(line_, *model_, profile ? *profile : rt::defaultProfile(), stimulus_, usage)) {
        error = usage;
        return false;
    }
    // The run options, as `strun run` builds them.
    rt::RunOptions& run = runOptions_;
    if (!cli::buildRunOptions(line_, run, error)) return false;
    for (int i = 0; i < sources_.size(); ++i) run.sourceFiles.push_back(sources_.file(i).path);
    run.originalPosition = [this](int file, int line, int col) {
        return file < sources_.size() ? sources_.file(file).original(line, col) : std::pair<int, int>{line, col};
    };
    std::vector<rt::TaskSpec> specs;
    for (const auto& t : model_->tasks) specs.push_back(t.spec);
    run.cyclesTask = !line_.task.empty() ? line_.task : specs.front().name;
    if (!stimulus_.empty()) run.stimulus = &stimulus_;
    // The debugger is a live front end: writes go through the control plane.
    line_.live.debugger = true;
    live_ = cli::LiveSession::start(line_.live, *model_, profile ? *profile : rt::defaultProfile(), specs, run.cyclesTask, run, usage);
    if (!live_ && !usage.empty()) {
        error = usage;
        return false;
    }
    // Statement lines, per POU, in the files the user has.
    for (const auto& unit : units_) {
        if (std::find(userFiles_.begin(), userFiles_.end(), unit.file) == userFiles_.end()) continue;
        const SourceFile& file = sources_.file(unit.file);
        std::function<void(const ast::Pou&)> add = [&](const ast::Pou& pou) {
            PouLines p;
            p.first = file.original(pou.loc.line, pou.loc.col).first;
            p.last = file.original(pou.endLoc.line ? pou.endLoc.line : pou.loc.line, 1).first;
            statementLinesOf(pou.body, file, p.lines);
            std::sort(p.lines.begin(), p.lines.end());
            if (p.first > p.last) std::swap(p.first, p.last);
            for (int l : p.lines) p.last = std::max(p.last, l), p.first = std::min(p.first, l);
            statementLines_[unit.file].push_back(std::move(p));
            for (const auto& m : pou.methods) add(*m);
            for (const auto& prop : pou.properties) {
                if (prop.getter) add(*prop.getter);
                if (prop.setter) add(*prop.setter);
            }
        };
        for (const auto& pou : unit.pous) add(*pou);
    }
    evaluator_ = std::make_unique<FrameEvaluator>(*checker_, *model_, log_);
    std::vector<project::TaskRunner*> runners;
    std::vector<std::string> names;
    for (const auto& t : model_->tasks) {
        runners_.push_back(std::make_unique<project::TaskRunner>(*model_, t));
        runners.push_back(runners_.back().get());
        names.push_back(t.spec.name);
    }
    SessionEvents events;
    events.stopped = [this](const std::string& reason, int threadId, const std::string& text, const std::vector<int>& hitIds) {
        json body = {{"reason", reason}, {"threadId", threadId}, {"allThreadsStopped", true}};
        if (!hitIds.empty()) body["hitBreakpointIds"] = hitIds;
        if (!text.empty()) {
            body["text"] = text.substr(0, text.find(':'));
            body["description"] = text;
        }
        event("stopped", body);
    };
    events.output = [this](const std::string& text) { event("output", {{"category", "console"}, {"output", text}}); };
    std::set<int> users(userFiles_.begin(), userFiles_.end());
    std::vector<int> lineCounts;
    for (int f = 0; f < sources_.size(); ++f)
        lineCounts.push_back(static_cast<int>(std::count(sources_.file(f).text.begin(), sources_.file(f).text.end(), '\n')) + 1);
    session_ = std::make_unique<DebugSession>(
        *model_, runners, names, users,
        [this](int file, int line) { return file >= 0 && file < sources_.size() ? sources_.file(file).original(line, 1).first : line; },
        events, *evaluator_, evaluatorMutex_, lineCounts);
    session_->setStopOnEntry(stopOnEntry_);
    if (auto it = pendingBreakpoints_.find("<faults>"); it != pendingBreakpoints_.end()) session_->setExceptionBreakpoints(it->second.get<bool>());
    launched_ = true;
    // Breakpoints the client set before launching: verified now.
    for (auto& [path, request] : pendingBreakpoints_) {
        if (path == "<faults>") continue;
        json result = setBreakpoints(request);
        for (const auto& bp : result["breakpoints"]) event("breakpoint", {{"reason", "changed"}, {"breakpoint", bp}});
    }
    pendingBreakpoints_.clear();
    return true;
}

void DapServer::startRun() {
    runThread_ = std::thread([this] {
        rt::RunOptions run = runOptions_;
        std::vector<rt::TaskSpec> specs;
        for (const auto& t : model_->tasks) specs.push_back(t.spec);
        run.front = session_.get();
        std::vector<rt::TaskBody*> bodies;
        for (auto& r : runners_) bodies.push_back(r.get());
        rt::PlcState state = rt::PlcState::Run;
        std::ostringstream report;
        {
            rt::Scheduler scheduler(model_->machine, specs, bodies, run);
            session_->attach(&scheduler, run.virtualClock);
            state = scheduler.run();
            session_->detach();
            if (live_) live_->runEnded(scheduler);
            cli::DiagnosticOptions plain;
            plain.color = cli::ColorMode::Never;
            cli::printFaultReport(report, scheduler, sources_, plain, false);
            cli::printRunSummary(report, scheduler, state);
            if (live_) live_->printForces(report);
        }
        runEnded_ = true;
        event("output", {{"category", "console"}, {"output", report.str()}});
        event("exited", {{"exitCode", state == rt::PlcState::Run ? 0 : 3}});
        event("terminated", nullptr);
    });
}

void DapServer::endRun() {
    if (!runThread_.joinable()) return;
    if (session_) session_->terminate();
    runThread_.join();
}

// ---------------------------------------------------------------- breakpoints

int DapServer::fileOfSourcePath(const std::string& path) const {
    const std::string key = normalPath(path);
    for (int f : userFiles_)
        if (normalPath(sources_.file(f).path) == key) return f;
    // A path written differently (a symbolic link): compare the files themselves.
    std::error_code ec;
    for (int f : userFiles_)
        if (fs::equivalent(sources_.file(f).path, path, ec)) return f;
    return -1;
}

json DapServer::setBreakpoints(const json& args) {
    const json& source = args.at("source");
    const std::string path = source.value("path", "");
    json requested = args.value("breakpoints", json::array());
    if (!requested.is_array() || requested.empty()) {
        requested = json::array();
        for (const auto& l : args.value("lines", json::array())) requested.push_back({{"line", l}});
    }
    json out = json::array();
    if (!launched_) {
        // Kept until launch; answered unverified now.
        pendingBreakpoints_[normalPath(path)] = args;
        for (size_t k = 0; k < requested.size(); ++k)
            out.push_back({{"id", nextBreakpointId_++}, {"verified", false}, {"message", "the project is not launched yet"}});
        // The ids given now are given again, verified, after launch.
        nextBreakpointId_ -= static_cast<int>(requested.size());
        return {{"breakpoints", out}};
    }
    const int file = fileOfSourcePath(path);
    std::vector<LineBreakpoint> set;
    for (const auto& r : requested) {
        json bp = {{"id", nextBreakpointId_++}, {"verified", false}};
        int line = r.value("line", 0) + (linesStartAt1_ ? 0 : 1);
        bp["line"] = line;
        if (file < 0) {
            bp["message"] = "not a source file of the launched project";
            out.push_back(bp);
            continue;
        }
        bp["source"] = {{"name", fs::path(sources_.file(file).path).filename().string()}, {"path", sources_.file(file).path}};
        // The innermost POU around the line, then its next line with a statement.
        const PouLines* best = nullptr;
        for (const auto& p : statementLines_[file])
            if (line >= p.first && line <= p.last && (!best || p.last - p.first < best->last - best->first)) best = &p;
        auto next = best ? std::lower_bound(best->lines.begin(), best->lines.end(), line) : std::vector<int>::const_iterator{};
        if (!best || next == best->lines.end()) {
            bp["message"] = "no statement on or after this line in its POU";
            out.push_back(bp);
            continue;
        }
        LineBreakpoint b;
        b.id = bp["id"].get<int>();
        b.file = file;
        b.line = *next;
        bp["line"] = *next + (linesStartAt1_ ? 0 : -1);
        bp["verified"] = true;
        // The POU whose scope conditions and log points are written in.
        sema::PouInfo* scope = nullptr;
        int bestSpan = 1 << 30;
        for (const auto& info : model_->pouStore) {
            auto consider = [&](sema::PouInfo* p) {
                if (!p->ast || p->ast->loc.file != file) return;
                const SourceFile& sf = sources_.file(file);
                const int first = sf.original(p->ast->loc.line, 1).first;
                const int last = sf.original(p->ast->endLoc.line ? p->ast->endLoc.line : p->ast->loc.line, 1).first;
                if (b.line >= first && b.line <= last && last - first < bestSpan) {
                    bestSpan = last - first;
                    scope = p;
                }
            };
            consider(info.get());
            for (auto& [n, m] : info->methods) consider(m);
        }
        std::lock_guard<std::mutex> lock(evaluatorMutex_);
        const std::string condition = r.value("condition", "");
        if (!condition.empty()) {
            b.condition = evaluator_->compile(condition, scope);
            if (b.condition->ok && b.condition->checked.type->kind != sema::TK::Bool)
                bp["message"] = "the condition is of type " + sema::typeName(b.condition->checked.type) + ", not BOOL";
            else if (!b.condition->ok)
                bp["message"] = "condition: " + b.condition->error;
            if (bp.contains("message")) {
                bp["verified"] = false;
                out.push_back(bp);
                continue;
            }
        }
        const std::string hits = r.value("hitCondition", "");
        if (!hits.empty()) {
            // An integer N, optionally written ">= N" or "== N" as some clients do.
            std::string digits;
            for (char ch : hits)
                if (std::isdigit(static_cast<unsigned char>(ch))) digits.push_back(ch);
                else if (ch != ' ' && ch != '>' && ch != '=') digits = "x";
            if (digits.empty() || digits == "x" || digits.size() > 15) {
                bp["verified"] = false;
                bp["message"] = "hitCondition must be a whole number";
                out.push_back(bp);
                continue;
            }
            b.hitTarget = std::stoll(digits);
        }
        if (r.contains("logMessage") && r["logMessage"].is_string()) {
            b.logPoint = true;
            const std::string text = r["logMessage"].get<std::string>();
            std::string literal;
            for (size_t i = 0; i < text.size(); ++i) {
                if (text[i] == '{') {
                    const size_t close = text.find('}', i);
                    if (close != std::string::npos) {
                        b.logParts.emplace_back(literal, evaluator_->compile(text.substr(i + 1, close - i - 1), scope));
                        literal.clear();
                        i = close;
                        continue;
                    }
                }
                literal.push_back(text[i]);
            }
            b.logParts.emplace_back(literal, nullptr);
        }
        set.push_back(std::move(b));
        out.push_back(bp);
    }
    if (file >= 0) session_->setBreakpoints(file, std::move(set));
    return {{"breakpoints", out}};
}

// ---------------------------------------------------------------- stopped state

bool DapServer::frameOf(int frameId, int& task, FrameRecord& frame) const {
    if (!session_ || !session_->stopped() || frameId < 1) return false;
    task = (frameId - 1) / kDepthsPerTask;
    const size_t depth = static_cast<size_t>((frameId - 1) % kDepthsPerTask);
    const std::vector<FrameRecord> frames = session_->frames(task);
    if (depth >= frames.size()) return false;
    frame = frames[depth];
    return true;
}

json DapServer::stackTrace(const json& args) {
    json out = json::array();
    const int task = args.value("threadId", 0) - 1;
    if (!session_ || !session_->stopped()) return {{"stackFrames", out}, {"totalFrames", 0}};
    const std::vector<FrameRecord> frames = session_->frames(task);
    for (size_t k = frames.size(); k-- > 0;) {
        const FrameRecord& f = frames[k];
        json frame = {{"id", frameIdOf(task, k)}, {"name", f.pou ? *f.pou : std::string("?")}};
        if (f.stmt && f.stmt->file >= 0 && f.stmt->file < sources_.size()) {
            const SourceFile& file = sources_.file(f.stmt->file);
            auto [line, col] = file.original(f.stmt->line, f.stmt->col);
            frame["source"] = {{"name", fs::path(file.path).filename().string()}, {"path", normalPath(file.path)}};
            frame["line"] = line + (linesStartAt1_ ? 0 : -1);
            frame["column"] = std::max(col, 1) + (columnsStartAt1_ ? 0 : -1);
        } else {
            frame["line"] = 0;
            frame["column"] = 0;
        }
        out.push_back(frame);
    }
    const int levels = args.value("levels", 0), start = args.value("startFrame", 0);
    json page = json::array();
    for (int k = start; k < static_cast<int>(out.size()) && (levels <= 0 || k < start + levels); ++k) page.push_back(out[static_cast<size_t>(k)]);
    return {{"stackFrames", page}, {"totalFrames", out.size()}};
}

int DapServer::addContainer(Container c) {
    const int id = nextContainer_++;
    containers_[id] = std::move(c);
    return id;
}

json DapServer::scopes(const json& args, bool& ok, std::string& error) {
    int task = -1;
    FrameRecord frame;
    if (!frameOf(args.value("frameId", 0), task, frame)) {
        ok = false;
        error = "no such frame (the PLC is not stopped there)";
        return nullptr;
    }
    sema::PouInfo* pou = session_->pouOf(frame.pou);
    Container locals, inputs, outputs, inOuts, globals;
    auto shownOf = [&](sema::VarSym* v) {
        Shown s;
        s.name = v->name;
        s.evaluateName = v->name;
        const sema::VarSym* target = v->global ? v->global : v;
        s.type = target->type;
        s.bit = target->bit;
        switch (target->storage) {
            case sema::Storage::Self: s.address = frame.self ? frame.self + target->offset : nullptr; break;
            case sema::Storage::Frame: s.address = frame.frame ? frame.frame + target->offset : nullptr; break;
            case sema::Storage::Abs: s.address = target->abs; break;
        }
        if (s.address && target->byRef) {
            uint8_t* p = nullptr;
            std::memcpy(&p, s.address, sizeof p);
            s.address = p;
        }
        if (s.type && (s.type->kind == sema::TK::Reference) && s.address) {
            // A REFERENCE shows what it refers to.
            uint8_t* p = nullptr;
            std::memcpy(&p, s.address, sizeof p);
            s.type = s.type->target;
            s.address = p;
        }
        return s;
    };
    // In declaration order: the AST's blocks name the variables.
    auto collect = [&](sema::PouInfo* p) {
        if (!p || !p->ast) return;
        for (const auto& block : p->ast->vars)
            for (const auto& decl : block.vars)
                for (const auto& name : decl.names) {
                    auto it = p->vars.find(sema::upper(name));
                    if (it == p->vars.end() || it->second->hidden) continue;  // a graphical translation's own (decision 0290)
                    Shown s = shownOf(it->second);
                    switch (block.section) {
                        case ast::VarSection::Input: inputs.items.push_back(s); break;
                        case ast::VarSection::Output: outputs.items.push_back(s); break;
                        case ast::VarSection::InOut: inOuts.items.push_back(s); break;
                        case ast::VarSection::External:
                        case ast::VarSection::Global: break;
                        default: locals.items.push_back(s); break;
                    }
                }
        if (p->result && p->kind != ast::PouKind::Program) {
            Shown s = shownOf(p->result);
            s.name = p->name;
            locals.items.push_back(s);
        }
    };
    // Inherited variables first (FB EXTENDS), then the POU's own.
    std::vector<sema::PouInfo*> chain;
    for (sema::PouInfo* p = pou ? pou->parent : nullptr; p; p = p->parent) chain.insert(chain.begin(), p);
    for (sema::PouInfo* p : chain) collect(p);
    collect(pou);
    for (sema::VarSym* g : model_->globals) {
        Shown s = shownOf(g);
        s.name = g->globalKey();
        s.evaluateName = g->globalKey();
        globals.items.push_back(s);
    }
    json out = json::array();
    auto scope = [&](const char* name, Container& c, bool always, const char* hint) {
        if (c.items.empty() && !always) return;
        const int n = static_cast<int>(c.items.size());
        json s = {{"name", name}, {"variablesReference", addContainer(std::move(c))}, {"namedVariables", n}, {"expensive", false}};
        if (hint) s["presentationHint"] = hint;
        out.push_back(s);
    };
    scope("Locals", locals, true, "locals");
    scope("Inputs", inputs, false, "arguments");
    scope("Outputs", outputs, false, nullptr);
    scope("In/Out", inOuts, false, "arguments");
    scope("Globals", globals, true, nullptr);
    return {{"scopes", out}};
}

json DapServer::variableJson(const Shown& v) {
    json j = {{"name", v.name}, {"value", v.address ? stLiteral(v.type, v.address, v.bit) : "?"},
              {"type", v.type ? sema::typeName(v.type) : ""}, {"variablesReference", 0}, {"evaluateName", v.evaluateName}};
    if (v.address && expandable(v.type)) {
        Container c;
        for (const Member& m : membersOf(v.type, v.address)) {
            Shown s;
            s.name = m.name;
            s.evaluateName = v.evaluateName + m.path;
            s.type = m.type;
            s.address = m.address;
            s.writable = v.writable;
            c.items.push_back(s);
        }
        const int count = static_cast<int>(c.items.size());
        j["variablesReference"] = addContainer(std::move(c));
        j[v.type->kind == sema::TK::Array ? "indexedVariables" : "namedVariables"] = count;
    }
    return j;
}

json DapServer::variables(const json& args, bool& ok, std::string& error) {
    auto it = containers_.find(args.value("variablesReference", 0));
    if (it == containers_.end() || !session_ || !session_->stopped()) {
        ok = false;
        error = "no such variables (the PLC is not stopped)";
        return nullptr;
    }
    json out = json::array();
    const std::vector<Shown> items = it->second.items;  // variableJson adds containers
    const int start = args.value("start", 0), count = args.value("count", 0);
    for (int k = start; k < static_cast<int>(items.size()) && (count <= 0 || k < start + count); ++k)
        out.push_back(variableJson(items[static_cast<size_t>(k)]));
    return {{"variables", out}};
}

json DapServer::evaluate(const json& args, bool& ok, std::string& error) {
    const std::string expression = args.at("expression").get<std::string>();
    if (!model_ || !session_) {
        ok = false;
        error = "no project is launched";
        return nullptr;
    }
    if (!session_->stopped()) {
        ok = false;
        error = runEnded_ ? "the run has ended" : "the PLC is running: pause it to evaluate";
        return nullptr;
    }
    int task = -1;
    FrameRecord frame;
    if (!frameOf(args.value("frameId", 0), task, frame)) {
        const std::vector<FrameRecord> frames = session_->frames(session_->stoppedTask());
        if (!frames.empty()) frame = frames.back();
    }
    sema::PouInfo* pou = session_->pouOf(frame.pou);
    EvaluatedValue v;
    {
        std::lock_guard<std::mutex> lock(evaluatorMutex_);
        auto compiled = evaluator_->compile(expression, pou);
        v = evaluator_->evaluate(*compiled, frame.self, frame.frame, pou && pou->code ? pou->code->frameSize : 0);
    }
    if (!v.ok) {
        ok = false;
        error = v.error;
        return nullptr;
    }
    auto owned = std::make_shared<std::vector<uint8_t>>(std::move(v.bytes));
    Shown s;
    s.name = expression;
    s.evaluateName = expression;
    s.type = v.type;
    s.address = owned->data();
    s.writable = false;
    json j = variableJson(s);
    if (j["variablesReference"].get<int>() > 0) containers_[j["variablesReference"].get<int>()].owned = owned;
    return {{"result", j["value"]}, {"type", j["type"]}, {"variablesReference", j["variablesReference"]}};
}

json DapServer::setVariable(const json& args, bool& ok, std::string& error) {
    auto it = containers_.find(args.value("variablesReference", 0));
    if (it == containers_.end() || !session_ || !session_->stopped()) {
        ok = false;
        error = "no such variables (the PLC is not stopped)";
        return nullptr;
    }
    const std::string name = args.at("name").get<std::string>();
    const std::string value = args.at("value").get<std::string>();
    for (Shown& s : it->second.items) {
        if (s.name != name) continue;
        if (!s.writable || !s.address) {
            ok = false;
            error = "'" + name + "' cannot be written";
            return nullptr;
        }
        std::vector<uint8_t> bytes;
        std::string why;
        if (!project::encodeLiteral(s.type, value, bytes, why)) {
            ok = false;
            error = why;
            return nullptr;
        }
        // A variable with a path (a program's, an FB instance's, a global, an
        // address) is written through the control plane's write queue, as
        // every live front end writes (decision 0272): the value is stored
        // when the next activation of a task starts, before its input phase.
        if (const live::LiveVariable* var = live_ ? live_->control().variableAt(s.address, s.bit) : nullptr) {
            if (!live_->control().write(var->path, value, why)) {
                ok = false;
                error = why;
                return nullptr;
            }
            return {{"value", stLiteral(s.type, bytes.data(), -1)}, {"type", sema::typeName(s.type)}, {"variablesReference", 0}};
        }
        // A call frame's variable (a FUNCTION's or METHOD's VAR, VAR_TEMP)
        // exists only during this call: written now, by the PLC thread.
        const bool written = session_->runWhileStopped([&] {
            if (s.bit >= 0) {
                if (bytes[0]) *s.address |= static_cast<uint8_t>(1u << s.bit);
                else *s.address &= static_cast<uint8_t>(~(1u << s.bit));
            } else {
                std::memcpy(s.address, bytes.data(), std::min<size_t>(bytes.size(), s.type->size));
            }
        });
        if (!written) {
            ok = false;
            error = "the PLC is not stopped";
            return nullptr;
        }
        return {{"value", stLiteral(s.type, s.address, s.bit)}, {"type", sema::typeName(s.type)}, {"variablesReference", 0}};
    }
    ok = false;
    error = "no variable '" + name + "' here";
    return nullptr;
}

}  // namespace strun::editors::dap
