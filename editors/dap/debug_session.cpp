#include "editors/dap/debug_session.h"

#include "editors/dap/debug_values.h"

namespace strun::editors::dap {

DebugSession::DebugSession(sema::ProgramModel& model, std::vector<project::TaskRunner*> runners, std::vector<std::string> taskNames,
                           std::set<int> userFiles, std::function<int(int, int)> userLine, SessionEvents events,
                           FrameEvaluator& evaluator, std::mutex& evaluatorMutex)
    : model_(model),
      runners_(std::move(runners)),
      taskNames_(std::move(taskNames)),
      userFiles_(std::move(userFiles)),
      userLine_(std::move(userLine)),
      events_(std::move(events)),
      evaluator_(evaluator),
      evaluatorMutex_(evaluatorMutex),
      tracks_(runners_.size()) {
    for (const auto& info : model_.pouStore) {
        if (info->code) pouByName_[&info->code->name] = info.get();
        for (const auto& [name, m] : info->methods)
            if (m->code) pouByName_[&m->code->name] = m;
    }
}

sema::PouInfo* DebugSession::pouOf(const std::string* name) const {
    auto it = pouByName_.find(name);
    if (it != pouByName_.end()) return it->second;
    // Names are compared by text when the pointer is another copy (model names).
    if (name)
        for (const auto& [key, info] : pouByName_)
            if (*key == *name) return info;
    return nullptr;
}

void DebugSession::setBreakpoints(int file, std::vector<LineBreakpoint> breakpoints) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = breakpoints_.begin(); it != breakpoints_.end();)
        it = it->first.first == file ? breakpoints_.erase(it) : std::next(it);
    for (auto& bp : breakpoints) breakpoints_[{bp.file, bp.line}].push_back(std::move(bp));
    hasBreakpoints_ = !breakpoints_.empty();
}

void DebugSession::resume(StepMode mode) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!stopped_) return;
    step_ = mode;
    stepping_ = mode != StepMode::None;
    stepTask_ = stoppedTask_;
    const int task = stoppedTask_;
    stepDepth_ = task >= 0 && !tracks_[static_cast<size_t>(task)].frames.empty() ? tracks_[static_cast<size_t>(task)].frames.size() - 1 : 0;
    stopped_ = false;
    resumed_.notify_all();
}

void DebugSession::terminate() {
    terminating_ = true;
    rt::Scheduler::requestStop();
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = false;
    resumed_.notify_all();
}

std::vector<FrameRecord> DebugSession::frames(int task) const {
    if (task < 0 || static_cast<size_t>(task) >= tracks_.size()) return {};
    std::vector<FrameRecord> out;
    for (const FrameRecord& f : tracks_[static_cast<size_t>(task)].frames)
        if (f.stmt) out.push_back(f);
    return out;
}

int DebugSession::runningTask() const {
    if (!scheduler_) return -1;
    const rt::TaskBody* body = scheduler_->runningBody();
    for (size_t k = 0; k < runners_.size(); ++k)
        if (runners_[k] == body) return static_cast<int>(k);
    return -1;
}

bool DebugSession::onAttention() {
    if (!terminating_) {
        const int task = runningTask();
        if (task >= 0) observe(task, runners_[static_cast<size_t>(task)]->context());
    }
    if (terminating_) rt::Scheduler::requestStop();
    return scheduler_->onAttention();
}

void DebugSession::onFault(rt::DiagCode code, std::string_view pou, int line, std::string message, int file, int col) {
    if (stopOnFaults_ && !terminating_) {
        const int task = runningTask();
        if (task >= 0) {
            // The faulting statement is the task's current one: the frames are
            // brought up to date before stopping (the fault comes mid-statement).
            const exec::Ctx& c = runners_[static_cast<size_t>(task)]->context();
            TaskTrack& track = tracks_[static_cast<size_t>(task)];
            const exec::Stmt* stmt = c.userStmt ? c.userStmt : c.stmt;
            if (stmt && !c.userStmt) {
                const size_t depth = static_cast<size_t>(c.depth);
                if (track.frames.size() < depth + 1) track.frames.resize(depth + 1);
                track.frames.resize(depth + 1);
                track.frames[depth] = FrameRecord{stmt, c.pouName, c.self, c.frame, false};
            }
            const std::string codeName = rt::diagCodeName(code);
            stopHere(task, "exception", codeName + ": " + message, {});
        }
    }
    scheduler_->onFault(code, pou, line, std::move(message), file, col);
}

void DebugSession::observe(int task, const exec::Ctx& c) {
    TaskTrack& track = tracks_[static_cast<size_t>(task)];
    if (!c.stmt) {
        // The tick before an activation's first statement.
        track.frames.clear();
        track.lastFile = track.lastLine = -1;
        return;
    }
    if (c.userStmt || !userFiles_.count(c.stmt->file)) return;  // inside strun's library
    const size_t depth = static_cast<size_t>(c.depth);
    if (track.frames.size() > depth + 1) track.frames.resize(depth + 1);
    // A loop's back edge ticks with the statement that ran last: the same
    // statement as the boundary before, at the same depth, which was not a
    // back edge itself (a one-statement loop body alternates the two).
    const bool backEdge = track.frames.size() == depth + 1 && track.frames[depth].stmt == c.stmt && !track.frames[depth].backEdge;
    if (track.frames.size() < depth + 1) track.frames.resize(depth + 1);
    track.frames[depth] = FrameRecord{c.stmt, c.pouName, c.self, c.frame, backEdge};
    if (backEdge) {
        track.lastLine = -1;
        return;
    }
    const int line = userLine_(c.stmt->file, c.stmt->line);
    const bool newLine = track.lastFile != c.stmt->file || track.lastLine != line;
    track.lastFile = c.stmt->file;
    track.lastLine = line;
    if (entryPending_.exchange(false)) return stopHere(task, "entry", "", {});
    if (pauseRequested_.exchange(false)) return stopHere(task, "pause", "", {});
    if (stepping_) {
        std::unique_lock<std::mutex> lock(mutex_);
        if (step_ != StepMode::None && stepTask_ == task) {
            const bool arrived = step_ == StepMode::In || (step_ == StepMode::Over && depth <= stepDepth_) ||
                                 (step_ == StepMode::Out && (depth < stepDepth_ || (stepDepth_ == 0 && depth == 0)));
            if (arrived) {
                lock.unlock();
                return stopHere(task, "step", "", {});
            }
        }
    }
    if (!hasBreakpoints_ || !newLine) return;
    std::vector<int> hit;
    std::vector<std::string> logs;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = breakpoints_.find({c.stmt->file, line});
        if (it == breakpoints_.end()) return;
        for (LineBreakpoint& bp : it->second) {
            std::string log;
            if (!breakpointFires(bp, track.frames[depth], log)) continue;
            if (bp.logPoint) logs.push_back(std::move(log));
            else hit.push_back(bp.id);
        }
    }
    for (const std::string& text : logs) events_.output(text + "\n");
    if (!hit.empty()) stopHere(task, "breakpoint", "", hit);
}

bool DebugSession::breakpointFires(LineBreakpoint& bp, const FrameRecord& frame, std::string& log) {
    sema::PouInfo* pou = pouOf(frame.pou);
    const uint32_t frameSize = pou && pou->code ? pou->code->frameSize : 0;
    std::lock_guard<std::mutex> lock(evaluatorMutex_);
    if (bp.condition) {
        EvaluatedValue v = evaluator_.evaluate(*bp.condition, frame.self, frame.frame, frameSize);
        if (!v.ok || v.bytes.empty() || v.bytes[0] == 0) return false;
    }
    ++bp.hits;
    if (bp.hitTarget > 0 && bp.hits < bp.hitTarget) return false;
    if (bp.logPoint) {
        for (const auto& [text, expr] : bp.logParts) {
            log += text;
            if (!expr) continue;
            EvaluatedValue v = evaluator_.evaluate(*expr, frame.self, frame.frame, frameSize);
            log += v.ok ? stLiteral(v.type, v.bytes.data()) : "<" + v.error + ">";
        }
    }
    return true;
}

void DebugSession::stopHere(int task, const std::string& reason, const std::string& text, const std::vector<int>& hitIds) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (terminating_) return;
    step_ = StepMode::None;
    stepping_ = false;
    pauseRequested_ = false;
    entryPending_ = false;
    stoppedTask_ = task;
    stopped_ = true;
    lock.unlock();
    events_.stopped(reason, task + 1, text, hitIds);
    lock.lock();
    resumed_.wait(lock, [&] { return !stopped_ || terminating_; });
}

}  // namespace strun::editors::dap
