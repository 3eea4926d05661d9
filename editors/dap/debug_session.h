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
                 FrameEvaluator& evaluator, std::mutex& evaluatorMutex);

    void attach(rt::Scheduler* scheduler) { scheduler_ = scheduler; }
    void detach() { scheduler_ = nullptr; }

    // ---- from the protocol thread
    void setBreakpoints(int file, std::vector<LineBreakpoint> breakpoints);  // replaces that file's
    void setExceptionBreakpoints(bool runtimeFaults) { stopOnFaults_ = runtimeFaults; }
    void setStopOnEntry(bool on) { entryPending_ = on; }
    void requestPause() { pauseRequested_ = true; }
    // Resumes a stopped run; `task` is the stopped task for a step.
    void resume(StepMode mode);
    // Ends the run: a stopped PLC thread returns and the scheduler stops.
    void terminate();
    bool stopped() const { return stopped_; }
    int stoppedTask() const { return stoppedTask_; }
    // The stopped task's frames (innermost last); valid while stopped.
    std::vector<FrameRecord> frames(int task) const;
    // The PouInfo of a frame's POU (by the PouCode name the frame carries).
    sema::PouInfo* pouOf(const std::string* name) const;

    // ---- AttentionHandler (the PLC thread)
    bool onAttention() override;
    void onFault(rt::DiagCode code, std::string_view pou, int line, std::string message, int file = -1, int col = 0) override;
    rt::PlcTime currentTime() override { return scheduler_->currentTime(); }
    int64_t calendarNanos() override { return scheduler_->calendarNanos(); }
    int64_t taskStartCalendarNanos() override { return scheduler_->taskStartCalendarNanos(); }
    rt::PlcTime currentTaskInterval() override { return scheduler_->currentTaskInterval(); }
    bool setCurrentTaskInterval(rt::PlcTime period) override { return scheduler_->setCurrentTaskInterval(period); }

private:
    struct TaskTrack {
        std::vector<FrameRecord> frames;  // by call depth
        int lastFile = -1, lastLine = -1;  // the line of the last statement started (breakpoints fire once per line reached)
    };
    int runningTask() const;
    void observe(int task, const exec::Ctx& c);
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
    rt::Scheduler* scheduler_ = nullptr;
    std::vector<TaskTrack> tracks_;

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
