// The task scheduler: runs the configured tasks on one CPU by priority, with
// preemption at statement boundaries, on the virtual or the real clock.
//
// How it runs the interpreter: the interpreter calls Machine::tick() at every
// statement boundary; when PLC time reaches Machine::deadline, tick() calls
// onAttention(). The deadline is the earliest moment the scheduler must look
// again: the next release, the watchdog expiry of an active activation, the
// next event/status sampling tick, the end of --for. Preemption is nesting:
// inside onAttention() a ready task of strictly higher priority runs right
// there, on the same C++ stack, and the preempted task resumes when it
// returns. The rules are in docs/decisions/0010..0017 and docs/diagnostics.md.
#pragma once

#include <atomic>
#include <functional>
#include <utility>
#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/diag_buffer.h"
#include "runtime/live_hooks.h"
#include "runtime/machine.h"
#include "runtime/plc_profile.h"
#include "runtime/run_observer.h"
#include "runtime/stimulus.h"
#include "runtime/task_spec.h"

namespace strun::rt {

class AttentionTimer;
class SystemArea;

struct RunOptions {
    bool virtualClock = true;
    PlcTime stmtCost = 1000;  // ns per statement, virtual clock only (values < 1 count as 1)
    std::optional<uint64_t> cycles;  // stop after this many completed cycles of cyclesTask
    std::string cyclesTask;          // "" = the first task of the list
    std::optional<PlcTime> duration;  // --for: stop when PLC time reaches it
    int64_t startCalendarNanos = 0;   // --start, virtual clock only
    std::ostream* trace = nullptr;    // --trace: one line per task event
    bool realtime = false;            // --realtime: SCHED_FIFO + mlockall where permitted
    // Additions to the interface the brief fixed:
    const PlcProfile* profile = nullptr;  // nullptr: defaultProfile()
    size_t diagnosticCapacity = 1000;     // entries kept; older ones are dropped and counted
    std::ostream* warnings = nullptr;     // --realtime notes ("strun: warning: ..."); nullptr: std::cerr
    Stimulus* stimulus = nullptr;         // --set / --stimulus writes (runtime/stimulus.h); nullptr: none
    RunObserver* observer = nullptr;      // --vcd recorder (runtime/run_observer.h); nullptr: none
    LiveHooks* live = nullptr;            // --serve, --force, --paused, ... (live/control_plane.h); nullptr: none
    std::vector<std::string> sourceFiles;  // paths by source index, for the "file" of diagnostics
    // Maps a fault's position in the compiled text to the file the user has
    // (the XML line and column of a converted TwinCAT/PLCopen source); none: as is.
    std::function<std::pair<int, int>(int file, int line, int col)> originalPosition;
    // strun debug: a handler that the interpreter calls instead of the
    // scheduler; it forwards every call to the scheduler (decision 0190).
    // nullptr: the scheduler itself, as in every run without a debugger.
    AttentionHandler* front = nullptr;
};

enum class PlcState { Run, Stop, Halt };
const char* plcStateName(PlcState state);  // "RUN", "STOP", "HALT"

// One task's statistics as --dump reports them ("tasks"), copied out without
// allocating (Scheduler::copyTaskStats) so a live front end can publish them.
struct TaskStats {
    TaskKind kind = TaskKind::Cyclic;  // may change at run time (M340 %SW0)
    uint64_t cycles = 0, overruns = 0, watchdogTrips = 0, started = 0;
    PlcTime lastExec = 0, minExec = kNever, maxExec = 0, sumExec = 0;
    PlcTime minLatency = kNever, maxLatency = 0;
};
// The --dump "tasks" array for tasks named and prioritised by `specs`.
nlohmann::ordered_json taskStatsJson(const std::vector<TaskSpec>& specs, const std::vector<TaskStats>& stats);
// The --dump "diagnostics" array; `files` names the source indices.
nlohmann::ordered_json diagnosticsJson(const std::vector<DiagEntry>& entries, const std::vector<std::string>& files);

class Scheduler : public AttentionHandler {
public:
    // `bodies` is parallel to `tasks`. Throws std::invalid_argument when they
    // differ in size or when options.cycles names no task (the CLI checks
    // --task first with hasTask()).
    Scheduler(Machine& machine, std::vector<TaskSpec> tasks, std::vector<TaskBody*> bodies, RunOptions options);
    ~Scheduler() override;
    Scheduler(const Scheduler&) = delete;
    Scheduler& operator=(const Scheduler&) = delete;

    // Runs until --cycles / --for is reached, the PLC goes to STOP/HALT, or
    // requestStop() is called. Ends in RUN unless a fault stopped the PLC.
    // Call it once per Scheduler; it installs itself as machine.handler and
    // sets machine.stmtCost (the statement cost on the virtual clock, 0 on the real one).
    PlcState run();
    // Async-signal-safe (a SIGINT handler may call it): the running run()
    // returns cleanly at the next statement boundary or idle point.
    static void requestStop();
    static bool hasTask(const std::vector<TaskSpec>& tasks, std::string_view name);  // case-insensitive
    // True from requestStop() until the run has ended.
    static bool stopRequested() { return stopRequested_.load(std::memory_order_relaxed); }

    PlcState state() const { return state_; }
    PlcTime endTime() const { return endTime_; }
    // The --dump "tasks" and "diagnostics" arrays; keys in a fixed order (docs/cli.md).
    nlohmann::ordered_json tasksJson() const;
    nlohmann::ordered_json diagnosticsJson() const;
    const std::vector<DiagEntry>& diagnostics() const { return diagnostics_.entries(); }
    uint64_t droppedDiagnostics() const { return diagnostics_.dropped(); }
    // The faults that sent the PLC to STOP/HALT (usually one), in order.
    const std::vector<DiagEntry>& stopFaults() const { return stopFaults_; }
    const std::vector<std::string>& sourceFiles() const { return options_.sourceFiles; }
    std::string currentTaskName() const override;
    int currentTaskIndex() const override;
    bool taskInfo(int index, TaskInfo& out) const override;
    // The body of the running activation (the innermost when preempted); null between activations.
    const TaskBody* runningBody() const { return stack_.empty() ? nullptr : stack_.back()->body; }
    // True while `body`'s task is in the middle of an activation (running or preempted).
    bool isActive(const TaskBody* body) const {
        for (const TaskRun* t : stack_)
            if (t->body == body) return true;
        return false;
    }
    // The statistics of every task, in task order, into `out` (resized; no
    // allocation once it has the size). Scheduler thread, or after run().
    void copyTaskStats(std::vector<TaskStats>& out) const;
    PlcTime now() const { return machine_.time(); }
    uint64_t cyclesOf(size_t task) const { return tasks_[task].cycles; }
    // Activations started, all tasks together (the benchmark's task switches).
    uint64_t activations() const { return activations_; }

    // AttentionHandler (called by the interpreter).
    bool onAttention() override;
    void onFault(DiagCode code, std::string_view pou, int line, std::string message, int file = -1, int col = 0) override;
    void onLog(std::string_view pou, int line, std::string message, int file = -1, int col = 0) override;
    PlcTime currentTime() override;
    int64_t calendarNanos() override;
    int64_t taskStartCalendarNanos() override;
    PlcTime currentTaskInterval() override;
    bool setCurrentTaskInterval(PlcTime period) override;

    // Called (through the stimulus's input listener) after a write to
    // ProcessImage::physicalInputs that took effect at PLC time `at`: each
    // EXTERNAL task whose input bit changed with one of its edges is released
    // at `at` + the target's detection delay (no sooner than its minimum
    // spacing after its previous release).
    void physicalInputsChanged(PlcTime at);
    // A fault outside the program (IO_FAULT: a --modbus-client device stopped
    // answering): recorded at the current PLC time with no task and no POU;
    // the run goes on. Scheduler thread only (a LiveHooks call).
    void recordOutsideFault(DiagCode code, std::string message);

    // strun debug (RunOptions::front, decision 0271). While `on`, every
    // statement boundary calls the front handler; while off, only the
    // moments the scheduler needs one do, so an attached debugger with
    // nothing to watch costs the run nothing. Any thread.
    void watchEveryStatement(bool on) {
        frontEveryStatement_.store(on);
        if (on) machine_.requestAttentionFromOtherThread();
    }
    // The PLC time at which the scheduler itself next needs onAttention()
    // (virtual clock; the real clock's timer lowers the machine's deadline
    // instead): a front handler that sees every statement forwards only then.
    PlcTime ownDeadline() const { return ownDeadline_.load(std::memory_order_relaxed); }
    // A debugger stop of `stopped` PLC time inside the running activation:
    // it does not count against the watchdogs (CODESYS suspends them at a
    // breakpoint too). Scheduler thread (inside onAttention's caller).
    void excludeFromWatchdogs(PlcTime stopped);

private:
    enum class Phase : uint8_t { Idle, Ready, Active };

    struct TaskRun {
        TaskSpec spec;
        TaskBody* body = nullptr;
        int tieRank = 0;  // order among equal priority and equal waiting time
        bool isFaultTask = false;  // program-error or execution-timeout task
        PlcTime period = 0;        // cyclic: the current period (SetCurrentTaskCycle, %SW0..%SW5 change it)
        bool inhibited = false;    // M340 %S30..%S35 = 0: released, inputs and outputs copied, body not run
        bool restartPending = false;  // M241: released again as soon as this activation has written its outputs
        PlcTime restartNominal = 0;
        PlcTime lastExternalRelease = 0;  // EXTERNAL: the latest planned release (minimum spacing)
        bool hasExternalRelease = false;
        bool drivesFastOutputs = false;   // M241: it has switched FQ0/FQ1 (the 15 ms spacing applies)
        Phase phase = Phase::Idle;
        bool abortRequested = false;  // its watchdog tripped; abort at its next statement boundary
        bool lastTrigger = false;     // event tasks: the BOOL at the previous sample
        PlcTime releasedAt = 0;       // the pending or running activation's nominal release
        PlcTime startedAt = 0;
        PlcTime watchdogAt = kNever;  // while active
        PlcTime nextRelease = kNever;  // cyclic grid point / next time event, PLC time
        int64_t nextOccurrence = kNever;  // time events: calendar ns of nextRelease
        // Statistics for --dump.
        uint64_t cycles = 0, overruns = 0, watchdogTrips = 0, started = 0;
        PlcTime lastExec = 0, minExec = kNever, maxExec = 0, sumExec = 0;
        PlcTime minLatency = kNever, maxLatency = 0;
    };
    TaskStats statsOf(const TaskRun& task) const;
    enum class LiveEvent : uint8_t { Starting, InputsLatched, Ending, EndedCompleted, EndedAborted, Running, Stopped };
    [[gnu::noinline, gnu::cold]] bool liveHold();  // false: the run ends
    [[gnu::noinline, gnu::cold]] void liveEvent(LiveEvent event, const TaskRun& task);

    void mainLoop();
    void idle();
    void refreshNow();
    void startRegularTasks();
    void startTask(TaskRun& task, PlcTime now);
    void onMasterEnd();
    void setPeriod(TaskRun& task, PlcTime period);
    void switchMasterMode(TaskRun& mast, PlcTime period);
    bool sampleOnTicks() const { return hasTriggers_ && !scanSampling_; }
    void processDue();
    void recomputeEarliestRelease();
    void scheduleNext(TaskRun& task);
    bool release(TaskRun& task, PlcTime nominal, bool reportOverrun);
    void sampleTriggers();
    TaskRun* pickReady(const TaskRun* running) const;
    void runActivation(TaskRun& task);
    void finishActivation(TaskRun& task, bool completed);
    void checkWatchdogs();
    void noteBusy(const TaskRun* next);
    void checkSystemWatchdog();
    std::string virtualCostNote(PlcTime elapsed) const;  // the WATCHDOG message's virtual-clock part
    void tripWatchdog(TaskRun& task);
    void faultStop(const TaskRun* task, DiagCode code, PlcState state);
    void armNextAttention();
    void requestOwnAttention();  // the next statement boundary, also through a front handler
    void record(DiagCode code, const TaskRun* task, std::string_view pou, int line, std::string message, int file = -1, int col = 0);
    void trace(const TaskRun* task, const char* event, const char* detail = nullptr);
    PlcTime calendarToPlc(int64_t calendar) const;
    void observeRunning(const TaskRun& task, bool running);

    Machine& machine_;
    std::vector<TaskRun> tasks_;
    RunOptions options_;
    const PlcProfile& profile_;
    DiagBuffer diagnostics_;
    std::vector<TaskRun*> stack_;  // active activations, the running one last
    TaskRun* startup_ = nullptr;
    TaskRun* errorTask_ = nullptr;
    TaskRun* timeoutTask_ = nullptr;
    TaskRun* cyclesTask_ = nullptr;
    TaskRun* master_ = nullptr;     // the task in the first fixed slot (M340 MAST, or MainTask)
    bool masterOnlyPhase_ = false;  // M340: the first MAST cycle runs alone
    bool scanSampling_ = false;     // XGI: event/status BOOLs sampled only when the scan program ends
    std::unique_ptr<SystemArea> system_;  // M340 %S / %SW
    PlcState state_ = PlcState::Run;
    bool ending_ = false;          // the run is over: every level unwinds
    // Since when tasks within the profile's system-watchdog priorities have
    // held the processor without a pause (kNever: not now).
    PlcTime highBusySince_ = kNever;
    bool regularStarted_ = false;  // false while the startup task has not finished
    bool hasTriggers_ = false;     // event or status tasks exist
    PlcTime nextSample_ = kNever;  // next scheduler tick that samples event/status BOOLs
    PlcTime earliestRelease_ = kNever;
    PlcTime forEnd_ = kNever;
    PlcTime endTime_ = 0;
    PlcTime stopTime_ = 0;
    int64_t calendarBase_ = 0;  // calendar ns at PLC time 0
    int64_t monotonicOrigin_ = 0;
    uint64_t activations_ = 0;
    std::unique_ptr<AttentionTimer> timer_;
    std::atomic<bool> frontEveryStatement_{false};
    std::atomic<PlcTime> ownDeadline_{kNever};
    std::string traceLine_;
    std::vector<DiagEntry> stopFaults_;

    static std::atomic<bool> stopRequested_;
    static std::atomic<Machine*> runningMachine_;
};

}  // namespace strun::rt
