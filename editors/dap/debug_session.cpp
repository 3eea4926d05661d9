#include "editors/dap/debug_session.h"

#include "editors/dap/debug_values.h"

namespace strun::editors::dap {

DebugSession::DebugSession(sema::ProgramModel& model, std::vector<project::TaskRunner*> runners, std::vector<std::string> taskNames,
                           std::set<int> userFiles, std::function<int(int, int)> userLine, SessionEvents events,
                           FrameEvaluator& evaluator, std::mutex& evaluatorMutex, const std::vector<int>& lineCounts)
    : model_(model),
      runners_(std::move(runners)),
      taskNames_(std::move(taskNames)),
      userFiles_(std::move(userFiles)),
      userLine_(std::move(userLine)),
      events_(std::move(events)),
      evaluator_(evaluator),
      evaluatorMutex_(evaluatorMutex),
      tracks_(runners_.size()),
      lineCounts_(lineCounts) {
    isUser_.assign(lineCounts_.size(), 0);
    for (size_t f = 0; f < lineCounts_.size(); ++f) {
        isUser_[f] = userFiles_.count(static_cast<int>(f)) ? 1 : 0;
        const size_t n = isUser_[f] ? static_cast<size_t>(lineCounts_[f]) + 2 : 0;
        breakpointLines_.emplace_back(n ? new std::atomic<uint8_t>[n] : nullptr);
        for (size_t l = 0; l < n; ++l) breakpointLines_.back()[l].store(0, std::memory_order_relaxed);
    }
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

void DebugSession::attach(rt::Scheduler* scheduler, bool virtualClock) {
    virtualClock_ = virtualClock;
    scheduler_.store(scheduler);
    updateWatching();
}

void DebugSession::setBreakpoints(int file, std::vector<LineBreakpoint> breakpoints) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        for (auto it = breakpoints_.begin(); it != breakpoints_.end();)
            it = it->first.first == file ? breakpoints_.erase(it) : std::next(it);
        for (auto& bp : breakpoints) breakpoints_[{bp.file, bp.line}].push_back(std::move(bp));
        hasBreakpoints_ = !breakpoints_.empty();
        // The compiled lines whose statements are on a breakpoint's line.
        if (file >= 0 && static_cast<size_t>(file) < breakpointLines_.size() && breakpointLines_[static_cast<size_t>(file)])
            for (int l = 1; l <= lineCounts_[static_cast<size_t>(file)]; ++l)
                breakpointLines_[static_cast<size_t>(file)][static_cast<size_t>(l)].store(breakpoints_.count({file, userLine_(file, l)}) ? 1 : 0,
                                                                                          std::memory_order_relaxed);
    }
    updateWatching();
}

// Decision 0271: the session looks at every statement only while something
// can stop there. Otherwise the scheduler keeps its own deadline and the run
// pays nothing per statement (an attached debugger with no breakpoint runs
// at the speed of `strun run`).
void DebugSession::updateWatching() {
    std::lock_guard<std::mutex> lock(watchMutex_);
    const bool want = hasBreakpoints_ || stepping_ || pauseRequested_ || entryPending_ || stopOnFaults_;
    if (want && !watching_) watchEpoch_.fetch_add(1);
    watching_ = want;
    if (rt::Scheduler* s = sched()) s->watchEveryStatement(want);
}

// The frames of a track are complete when every call level up to the
// innermost was seen since watching began.
bool DebugSession::complete(const TaskTrack& track) {
    for (const FrameRecord& f : track.frames)
        if (!f.stmt) return false;
    return !track.frames.empty();
}

bool DebugSession::runWhileStopped(const std::function<void()>& work) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!stopped_ || terminating_ || work_) return false;
    work_ = &work;
    workDone_ = false;
    resumed_.notify_all();
    resumed_.wait(lock, [&] { return workDone_ || terminating_; });
    const bool done = workDone_;
    work_ = nullptr;
    return done;
}

void DebugSession::resume(StepMode mode) {
    {
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
    updateWatching();
}

void DebugSession::terminate() {
    terminating_ = true;
    rt::Scheduler::requestStop();
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = false;
    resumed_.notify_all();
}

std::vector<FrameRecord> DebugSession::frames(int task) const {
    if (task < 0 || static_cast<size_t>(task) >= tracks_.size() || !stopped_) return {};
    const TaskTrack& track = tracks_[static_cast<size_t>(task)];
    std::vector<FrameRecord> known = track.epoch == watchEpoch_.load() ? track.frames : std::vector<FrameRecord>{};
    if (task != stoppedTask_) {
        // Another task: shown only while it is in the middle of an activation
        // (preempted by the stopped one). Its evaluator registers still say
        // where it was preempted; the outer levels come from its track.
        rt::Scheduler* s = sched();
        if (!s || !s->isActive(runners_[static_cast<size_t>(task)])) return {};
        const exec::Ctx& c = runners_[static_cast<size_t>(task)]->context();
        if (c.stmt && !c.userStmt && c.stmt->file >= 0 && static_cast<size_t>(c.stmt->file) < isUser_.size() && isUser_[static_cast<size_t>(c.stmt->file)]) {
            const size_t depth = static_cast<size_t>(c.depth);
            known.resize(depth + 1);
            known[depth] = FrameRecord{c.stmt, c.pouName, c.self, c.frame, false};
        }
    }
    std::vector<FrameRecord> out;
    for (const FrameRecord& f : known)
        if (f.stmt) out.push_back(f);
    return out;
}

int DebugSession::runningTask() const {
    rt::Scheduler* s = sched();
    if (!s) return -1;
    const rt::TaskBody* body = s->runningBody();
    for (size_t k = 0; k < runners_.size(); ++k)
        if (runners_[k] == body) return static_cast<int>(k);
    return -1;
}

bool DebugSession::onAttention() {
    rt::Scheduler* s = sched();
    if (watching_.load(std::memory_order_relaxed) && !terminating_) {
        const int task = runningTask();
        if (task >= 0) observe(task, runners_[static_cast<size_t>(task)]->context());
        // The scheduler itself is asked only when it wants to be (its own
        // deadline on the virtual clock); the real clock's timer lowers the
        // machine's deadline, which is at its minimum while watching, so there
        // every boundary is passed on.
        if (virtualClock_ && !terminating_ && !rt::Scheduler::stopRequested() && s->now() < s->ownDeadline()) return false;
    }
    if (terminating_) rt::Scheduler::requestStop();
    return s->onAttention();
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
    sched()->onFault(code, pou, line, std::move(message), file, col);
}

void DebugSession::observe(int task, const exec::Ctx& c) {
    TaskTrack& track = tracks_[static_cast<size_t>(task)];
    if (const uint64_t epoch = watchEpoch_.load(std::memory_order_relaxed); track.epoch != epoch) {
        // Watching (re)started: what was recorded before is stale.
        track.frames.clear();
        track.lastFile = track.lastLine = -1;
        track.epoch = epoch;
    }
    if (!c.stmt) {
        // The tick before an activation's first statement.
        track.frames.clear();
        track.lastFile = track.lastLine = -1;
        return;
    }
    const int file = c.stmt->file;
    if (c.userStmt || file < 0 || static_cast<size_t>(file) >= isUser_.size() || !isUser_[static_cast<size_t>(file)]) return;  // inside strun's library
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
    // Lines of the compiled text here (the file's own only for the lookup below).
    const int line = c.stmt->line;
    const bool newLine = track.lastFile != file || track.lastLine != line;
    track.lastFile = file;
    track.lastLine = line;
    if (entryPending_.load(std::memory_order_relaxed) && entryPending_.exchange(false)) return stopHere(task, "entry", "", {});
    // A pause waits for a statement whose whole call stack is known (at
    // once when watching began at this call level or outside any call).
    if (pauseRequested_ && complete(track) && pauseRequested_.exchange(false)) return stopHere(task, "pause", "", {});
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
    if (!newLine || line < 0 || line > lineCounts_[static_cast<size_t>(file)] ||
        !breakpointLines_[static_cast<size_t>(file)][static_cast<size_t>(line)].load(std::memory_order_relaxed))
        return;
    std::vector<int> hit;
    std::vector<std::string> logs;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = breakpoints_.find({file, userLine_(file, line)});
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
    rt::Scheduler* s = sched();
    // PLC time at the stop (on the real clock it goes on meanwhile).
    const rt::PlcTime stoppedAt = s ? s->currentTime() : 0;
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
    for (;;) {
        resumed_.wait(lock, [&] { return !stopped_ || terminating_ || (work_ && !workDone_); });
        if (!stopped_ || terminating_) break;
        // Work the protocol thread hands over (a write through the control plane).
        const std::function<void()>* work = work_;
        lock.unlock();
        (*work)();
        lock.lock();
        workDone_ = true;
        resumed_.notify_all();
    }
    lock.unlock();
    // The stop does not count against the watchdogs (decision 0273).
    if (s && !terminating_) s->excludeFromWatchdogs(s->currentTime() - stoppedAt);
}

}  // namespace strun::editors::dap
