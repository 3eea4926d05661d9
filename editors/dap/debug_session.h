// The run side of strun debug: sees every statement boundary of a run and
// stops it there (breakpoints, steps, pause, runtime faults), while the
// protocol side (dap_server.h) reads and writes the stopped frames.
//
// How it sees statements without slowing runs that have no debugger
// (decision 0190): the interpreter calls Machine::tick() at every statement
// boundary and the scheduler's AttentionHandler::onAttention() only when PLC
// time reaches Machine::deadline. With a debugger, RunOptions::front makes
// this session the machine's handler and the scheduler keeps the deadline at
// its minimum, so every boundary lands here first; the session looks at the
// running task's evaluator registers (TaskRunner::context(): statement, POU,
// instance, frame, call depth) and forwards the call to the scheduler. A
// run without `debug` has no front handler and executes exactly the code it
// did before.
//
// Stopping blocks the PLC thread inside the tick: no task runs, and on the
// virtual clock PLC time stands still; on the real clock it goes on.
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "editors/dap/frame_evaluator.h"
#include "interpreter/exec/node.h"
#include "interpreter/project/task_runner.h"
#include "runtime/machine.h"
#include "runtime/scheduler.h"

namespace strun::editors::dap {

// One POU activation of a stopped task, innermost last.
struct FrameRecord {
    const exec::Stmt* stmt = nullptr;
    const std::string* pou = nullptr;
    uint8_t* self = nullptr;
    uint8_t* frame = nullptr;
    bool backEdge = false;  // the last boundary seen at this depth was a loop's back edge
};

struct LineBreakpoint {
    int id = 0;
    int file = -1;
    int line = 0;  // in the file the user has (XML line for TwinCAT / PLCopen)
    std::shared_ptr<CompiledExpression> condition;
    int64_t hitTarget = 0;  // 0: none
    int64_t hits = 0;
    bool logPoint = false;
    // A log point's text: literal parts and compiled {EXPR} parts, alternating.
    std::vector<std::pair<std::string, std::shared_ptr<CompiledExpression>>> logParts;
};

enum class StepMode { None, In, Over, Out };

// What the session tells the protocol side (called on the PLC thread).
struct SessionEvents {
    std::function<void(const std::string& reason, int threadId, const std::string& text, const std::vector<int>& hitIds)> stopped;
    std::function<void(const std::string& text)> output;
};

class DebugSession final : public rt::AttentionHandler {
public:
    DebugSession(sema::ProgramModel& model, std::vector<project::TaskRunner*> runners, std::vector<std::string> taskNames,
                 std::set<int> userFiles, std::function<int(int file, int line)> userLine, SessionEvents events,
                 FrameEvaluator& evaluator, std::mutex& evaluatorMutex, const std::vector<int>& lineCounts);

    // The run's scheduler (PLC thread, before it runs); `virtualClock`: its clock.
    void attach(rt::Scheduler* scheduler, bool virtualClock);
    void detach() { scheduler_.store(nullptr); }

    // ---- from the protocol thread
    void setBreakpoints(int file, std::vector<LineBreakpoint> breakpoints);  // replaces that file's
    void setExceptionBreakpoints(bool runtimeFaults) {
        stopOnFaults_ = runtimeFaults;
        updateWatching();
    }
    void setStopOnEntry(bool on) {
        entryPending_ = on;
        updateWatching();
    }
    void requestPause() {
        pauseRequested_ = true;
        updateWatching();
    }
    // Resumes a stopped run; `task` is the stopped task for a step.
    void resume(StepMode mode);
    // Ends the run: a stopped PLC thread returns and the scheduler stops.
    void terminate();
    bool stopped() const { return stopped_; }
    int stoppedTask() const { return stoppedTask_; }
    // Runs `work` on the PLC thread while the run is stopped (the thread
    // that owns the program's storage and the control plane's queue) and
    // waits for it. False (and `work` not run) when the run is not stopped.
    bool runWhileStopped(const std::function<void()>& work);
    // A task's frames (innermost last), valid while stopped: the stopped
    // task's, or those of a task preempted in the middle of an activation
    // (where it was preempted); empty for a task between activations.
    std::vector<FrameRecord> frames(int task) const;
    // The PouInfo of a frame's POU (by the PouCode name the frame carries).
    sema::PouInfo* pouOf(const std::string* name) const;

    // ---- AttentionHandler (the PLC thread)
    bool onAttention() override;
    void onFault(rt::DiagCode code, std::string_view pou, int line, std::string message, int file = -1, int col = 0) override;
    rt::PlcTime currentTime() override { return sched()->currentTime(); }
    int64_t calendarNanos() override { return sched()->calendarNanos(); }
    int64_t taskStartCalendarNanos() override { return sched()->taskStartCalendarNanos(); }
    rt::PlcTime currentTaskInterval() override { return sched()->currentTaskInterval(); }
    bool setCurrentTaskInterval(rt::PlcTime period) override { return sched()->setCurrentTaskInterval(period); }
    void onLog(std::string_view pou, int line, std::string message, int file, int col) override {
        sched()->onLog(pou, line, std::move(message), file, col);
    }
    std::string currentTaskName() const override { return sched()->currentTaskName(); }
    int currentTaskIndex() const override { return sched()->currentTaskIndex(); }
    bool taskInfo(int index, TaskInfo& out) const override { return sched()->taskInfo(index, out); }

private:
    struct TaskTrack {
        std::vector<FrameRecord> frames;  // by call depth; a null stmt: not seen since watching began
        int lastFile = -1, lastLine = -1;  // the line of the last statement started (breakpoints fire once per line reached)
        uint64_t epoch = 0;                // watchEpoch_ when these frames were recorded
    };
    rt::Scheduler* sched() const { return scheduler_.load(std::memory_order_acquire); }
    int runningTask() const;
    void observe(int task, const exec::Ctx& c);
    // Whether every statement must reach observe() (a breakpoint, a step, a
    // pause, a stop on entry or on faults is wanted); tells the scheduler.
    void updateWatching();
    static bool complete(const TaskTrack& track);
    // Blocks the PLC thread until resumed; false when the run is to end.
    void stopHere(int task, const std::string& reason, const std::string& text, const std::vector<int>& hitIds);
    bool breakpointFires(LineBreakpoint& bp, const FrameRecord& frame, std::string& log);

    sema::ProgramModel& model_;
    std::vector<project::TaskRunner*> runners_;
    std::vector<std::string> taskNames_;
    std::set<int> userFiles_;
    std::function<int(int, int)> userLine_;
    SessionEvents events_;
    FrameEvaluator& evaluator_;
    std::mutex& evaluatorMutex_;
    std::map<const std::string*, sema::PouInfo*> pouByName_;
    std::atomic<rt::Scheduler*> scheduler_{nullptr};
    bool virtualClock_ = true;
    std::vector<TaskTrack> tracks_;
    // By source index: a user's file (breakpoints and frames are only there).
    std::vector<char> isUser_;
    // By source index, then compiled-text line: 1 where a breakpoint is (the
    // PLC thread reads it at every statement without taking the lock).
    std::vector<std::unique_ptr<std::atomic<uint8_t>[]>> breakpointLines_;
    std::vector<int> lineCounts_;
    // Watching every statement (see updateWatching); each time it starts the
    // epoch grows, and frames recorded before are stale.
    std::atomic<bool> watching_{false};
    std::atomic<uint64_t> watchEpoch_{1};
    std::mutex watchMutex_;
    const std::function<void()>* work_ = nullptr;  // under mutex_: runWhileStopped's
    bool workDone_ = false;

    mutable std::mutex mutex_;
    std::condition_variable resumed_;
    std::map<std::pair<int, int>, std::vector<LineBreakpoint>> breakpoints_;  // (file, user line)
    std::atomic<bool> hasBreakpoints_{false};
    std::atomic<bool> stopOnFaults_{false};
    std::atomic<bool> entryPending_{false};
    std::atomic<bool> pauseRequested_{false};
    std::atomic<bool> terminating_{false};
    std::atomic<bool> stopped_{false};
    std::atomic<int> stoppedTask_{-1};
    StepMode step_ = StepMode::None;
    std::atomic<bool> stepping_{false};  // step_ != None, read without the lock at every statement
    int stepTask_ = -1;
    size_t stepDepth_ = 0;
};

}  // namespace strun::editors::dap
