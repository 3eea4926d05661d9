// The control plane of a live run: the one component through which every
// live front end (the web monitor of --serve, the debugger of `strun debug`,
// the Modbus server and client) watches and steers a running PLC.
//
// What it offers (docs/live.md has the user-facing rules):
//  - Snapshots: when an activation ends with no other one in progress
//    underneath, the values of every variable, the process image (%I as the
//    program saw it, %Q, %M), PLC time and state and the task statistics are
//    copied into a snapshot and published. Readers take the latest one
//    (latest()) and read it at leisure: it is immutable, they never see two
//    activations mixed, and they never block or slow the scan (a triple
//    buffer: the scheduler copies into a buffer of its own and swaps it in
//    with one atomic exchange; no lock is ever held by the scheduler while a
//    reader reads).
//  - Writes and forces (shared/contract "Writes and forces"): write(),
//    force(), unforce(), unforceAll() resolve NAME and the ST literal VALUE
//    on the caller's thread with the resolver of --set
//    (project::resolveWrite) and refuse a bad one at once with its message;
//    a good one is queued and applied by the scheduler: a write when the
//    next activation starts (before its input phase); a force at every
//    activation start (%I: into the input image after the input phase) and
//    again at every activation end (before the output phase), until released.
//  - Pause, resume, step(task, cycles): honoured between two activations.
//    A paused PLC does not advance PLC time, on the real clock either (the
//    scheduler takes the time spent paused out of PLC time, so a pause
//    causes no overruns; the calendar, read from the host, goes on).
//  - Wake-up: sequence() grows by one per published snapshot;
//    waitForSnapshot(seen, timeout) blocks a front end's thread until a newer
//    one exists (or the timeout passes). The scheduler never waits for it.
//  - The timeline: the last kTimelineCapacity task switches (a task starts or
//    resumes running, is preempted or ends), lock-free for readers.
//
// How to attach it to a run (cli/live_options.cpp does this):
//     live::ControlPlane control(model, profile, specs, defaultStepTask);
//     control.forceAtStart(...);   control.startPaused();   // optional
//     options.live = &control;                               // rt::RunOptions
//     ... start front ends (threads of their own) ...
//     rt::Scheduler scheduler(model.machine, specs, bodies, options);
//     scheduler.run();
//     control.runEnded(scheduler);                           // final snapshot, wakes every waiter
//     ... stop front ends ...
//
// Threading: everything below "any thread" may be called from any number
// of front-end threads at once. The rt::LiveHooks methods are the
// scheduler's and must not be called by anyone else.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "interpreter/sema/program_model.h"
#include "runtime/diag_buffer.h"
#include "runtime/live_hooks.h"
#include "runtime/plc_profile.h"
#include "runtime/scheduler.h"

namespace strun::live {

using rt::PlcTime;

// The process image areas a snapshot carries.
enum class ImageArea : uint8_t { Inputs, Outputs, Memory };

// One elementary variable the snapshots carry (fixed before the run).
struct LiveVariable {
    std::string path;                   // "Main.valve.cmd", "Main.levels[3]", "GVL.gX" (as declared)
    std::string upperPath;              // for case-insensitive lookups
    const sema::Type* type = nullptr;
    int bit = -1;                       // >= 0: a BOOL at a bit address (AT %IX0.3)
    size_t offset = 0;                  // where its bytes are in Snapshot::data
    size_t size = 0;
};

// One published state of the PLC. Immutable once published.
struct Snapshot {
    uint64_t sequence = 0;     // 1, 2, ... (0: nothing published yet: initial values before the first activation)
    PlcTime time = 0;          // PLC time at publication
    rt::PlcState state = rt::PlcState::Run;
    bool ended = false;        // the run is over
    std::vector<uint8_t> data;  // variable storage (LiveVariable::offset)
    // The process image from byte 0: %I as the program saw it (after input
    // phase and forces), %Q as written to the outputs, %M.
    std::vector<uint8_t> inputs, outputs, memory;
    std::vector<rt::TaskStats> tasks;
    uint64_t diagnosticsTotal = 0;  // entries ever recorded (dropped ones included)

    const std::vector<uint8_t>& image(ImageArea area) const {
        return area == ImageArea::Inputs ? inputs : area == ImageArea::Outputs ? outputs : memory;
    }
};

// A force as the front ends show it.
struct ForceInfo {
    std::string name;                  // as declared / canonical address
    const sema::Type* type = nullptr;
    std::vector<uint8_t> bytes;        // the value's storage image
};

// One task switch for the timeline.
struct TimelineEvent {
    uint64_t index = 0;  // 0, 1, 2, ... in the order they happened
    PlcTime time = 0;
    uint32_t task = 0;
    bool running = false;
};

class ControlPlane final : public rt::LiveHooks {
public:
    static constexpr size_t kTimelineCapacity = 1 << 16;

    // `specs`: the tasks in the scheduler's order. `defaultStepTask`: the
    // task step() counts when none is named (the one --task names).
    ControlPlane(sema::ProgramModel& model, const rt::PlcProfile& profile, std::vector<rt::TaskSpec> specs,
                 std::string defaultStepTask);
    ~ControlPlane() override;
    ControlPlane(const ControlPlane&) = delete;
    ControlPlane& operator=(const ControlPlane&) = delete;

    // ---- before the run (not thread-safe; call before Scheduler::run)
    // --force NAME=VALUE: false with the --set message.
    bool forceAtStart(std::string_view name, std::string_view literal, std::string& error);
    // --paused: no task runs until resume() or step().
    void startPaused();
    // A front end that serves image bytes the program itself does not
    // address (Modbus registers) asks for them: snapshots then carry at least
    // `bytes` of that area.
    void requireImageBytes(ImageArea area, size_t bytes);

    // ---- any thread
    const std::vector<LiveVariable>& variables() const { return variables_; }
    const LiveVariable* findVariable(std::string_view path) const;  // case-insensitive; nullptr if none
    // The variable stored at `address` (`bit`: a BOOL at a bit address, else
    // -1), for a front end that found a value by its storage (the debugger's
    // variables view); nullptr if none (a function's or method's local).
    const LiveVariable* variableAt(const uint8_t* address, int bit) const;
    const std::vector<rt::TaskSpec>& tasks() const { return specs_; }
    const sema::ProgramModel& model() const { return model_; }

    // The latest snapshot (never null: before the first activation, one with
    // the initial values and sequence 0).
    std::shared_ptr<const Snapshot> latest();
    uint64_t sequence() const { return sequence_.load(std::memory_order_acquire); }
    // Blocks until sequence() > seen, the run has ended, or `timeout`
    // passes. True when a newer snapshot exists.
    bool waitForSnapshot(uint64_t seen, std::chrono::milliseconds timeout);

    // A value of `var` in `snap`, encoded as --dump does.
    static nlohmann::ordered_json valueJson(const Snapshot& snap, const LiveVariable& var);

    // Writes and forces: false with the --set message ("no variable 'x' ...",
    // "300 does not fit SINT (-128..127)") when NAME or VALUE is wrong.
    bool write(std::string_view name, std::string_view literal, std::string& error);
    // Several writes that take effect together, at the start of one activation
    // (the items of one Modbus request, the inputs of one device poll): every
    // NAME=VALUE is resolved first, then all are queued at once, so the
    // scheduler never applies a part of them. False, with nothing queued, when
    // one is refused.
    struct NamedWrite {
        std::string name, literal;
    };
    bool writeTogether(const std::vector<NamedWrite>& writes, std::string& error);
    bool force(std::string_view name, std::string_view literal, std::string& error);
    // False with `error` when NAME is wrong or not forced.
    bool unforce(std::string_view name, std::string& error);
    void unforceAll();
    std::vector<ForceInfo> forces() const;
    nlohmann::ordered_json forcesJson() const;  // {"NAME": VALUE, ...}

    void pause();
    void resume();
    bool paused() const { return paused_.load(std::memory_order_acquire); }
    // Runs until `task` ("" = the default step task) has completed `cycles`
    // more cycles, then pauses. Returns at once; false with `error` for an
    // unknown task or cycles == 0. waitUntilPaused() then waits for it.
    bool startStep(std::string_view task, uint64_t cycles, std::string& error);
    // Blocks until the scheduler holds paused (or the run ended, or timeout). True when paused/ended.
    bool waitUntilPaused(std::chrono::milliseconds timeout);

    bool ended() const { return ended_.load(std::memory_order_acquire); }
    PlcTime endTime() const;  // valid once ended()

    // The diagnostic buffer as of the latest snapshot (oldest first) and how many were dropped before them.
    std::vector<rt::DiagEntry> diagnostics(uint64_t* dropped = nullptr) const;
    const std::vector<std::string>& sourceFiles() const { return sourceFiles_; }
    void setSourceFiles(std::vector<std::string> files) { sourceFiles_ = std::move(files); }

    // Timeline events with index >= `from` still held (at most
    // kTimelineCapacity back), oldest first.
    std::vector<TimelineEvent> timeline(uint64_t from) const;
    uint64_t timelineNext() const { return timelineNext_.load(std::memory_order_acquire); }

    // ---- after Scheduler::run() returned (the scheduler's thread)
    void runEnded(const rt::Scheduler& scheduler);

    // ---- rt::LiveHooks (the scheduler's thread only)
    void runStarting(rt::Scheduler& scheduler) override;
    bool holdWhilePaused() override;
    void activationStarting(size_t task) override;
    void inputsLatched(size_t task) override;
    void activationEnding(size_t task) override;
    void activationEnded(size_t task, bool completed, bool outermost) override;
    void taskRunning(size_t task, bool running, PlcTime now) override;

private:
    // A resolved write or force target.
    struct Target {
        std::string name;                  // as declared / canonical address (ForceInfo::name)
        std::string key;                   // upper case: forces are matched by it
        const sema::Type* type = nullptr;
        uint8_t* dest = nullptr;           // write: where a write goes (%I: the physical input)
        uint8_t* forceDest = nullptr;      // force: where it holds (%I: the input image)
        bool input = false;                // an %I target: forced after the input phase
        int bit = -1;
        std::vector<uint8_t> bytes;
    };
    struct Request {
        enum class Kind : uint8_t { Write, Force, Unforce, UnforceAll } kind = Kind::Write;
        Target target;
    };

    bool resolve(std::string_view name, std::string_view literal, Target& out, std::string& error) const;
    bool canonicalKey(std::string_view name, std::string& key, std::string& error) const;
    void allocateBuffers();
    void copyDiagnostics(bool force);
    void enqueue(Request request);
    void drainRequests();
    static void store(const Target& t, uint8_t* dest);
    void applyForces(bool inputsOnly, bool skipInputs);
    void publish(bool ended);
    void fillSnapshot(Snapshot& snap, bool ended);
    void planSnapshotLayout();

    sema::ProgramModel& model_;
    const rt::PlcProfile& profile_;
    std::vector<rt::TaskSpec> specs_;
    std::string defaultStepTask_;
    std::vector<LiveVariable> variables_;
    std::vector<const uint8_t*> addresses_;  // parallel to variables_: where each lives in the running program
    std::vector<std::pair<std::string, size_t>> byUpperPath_;  // sorted, index into variables_
    struct Region {
        const uint8_t* from;
        size_t size;
        size_t offset;  // in Snapshot::data
    };
    std::vector<Region> regions_;
    size_t dataSize_ = 0;
    size_t imageBytes_[3] = {0, 0, 0};
    std::vector<std::string> sourceFiles_;

    const rt::Scheduler* scheduler_ = nullptr;
    rt::Scheduler* running_ = nullptr;  // while the run lasts: told of input writes (EXTERNAL tasks)

    // Triple buffer: the scheduler fills `back_`, then exchanges it with
    // `middle_` (its low bit set: fresh); readers (under readerMutex_) take
    // a fresh `middle_` into `front_` and hand out an immutable copy.
    std::unique_ptr<Snapshot> back_, front_;
    std::atomic<uintptr_t> middle_{0};
    mutable std::mutex readerMutex_;
    std::shared_ptr<const Snapshot> latestCopy_;  // under readerMutex_
    std::atomic<uint64_t> sequence_{0};
    std::mutex waitMutex_;
    std::condition_variable waitCv_;

    // Requests from front ends; the scheduler takes them with try_lock only.
    std::mutex requestMutex_;
    std::vector<Request> requests_;
    std::atomic<bool> requestsPending_{false};
    std::vector<Request> draining_;   // scheduler-owned
    std::vector<Target> activeForces_;  // scheduler-owned: what is applied
    mutable std::mutex forcesMutex_;
    std::vector<Target> shownForces_;  // what front ends see (updated when requested)

    // Pause and step.
    std::atomic<bool> paused_{false};
    std::atomic<bool> holding_{false};  // the scheduler is inside holdWhilePaused
    std::mutex controlMutex_;
    std::condition_variable controlCv_;  // scheduler waits here while paused; step waiters too
    uint64_t holdEpoch_ = 0;             // under controlMutex_: times the scheduler started holding
    std::atomic<int64_t> stepTask_{-1};
    std::atomic<uint64_t> stepRemaining_{0};
    std::vector<uint64_t> cyclesSeen_;  // scheduler-owned: each task's cycles at its last activation end
    mutable std::mutex resolveMutex_;   // front ends resolve names one at a time

    // Diagnostics copied when they change (the scheduler try-locks).
    mutable std::mutex diagMutex_;
    std::vector<rt::DiagEntry> diagCopy_;
    uint64_t diagDropped_ = 0;
    uint64_t diagSeenTotal_ = 0;  // scheduler-owned
    std::chrono::steady_clock::time_point lastDiagCopy_{};

    // Timeline ring: each slot holds (time, index<<17 | task<<1 | running).
    struct TimelineSlot {
        std::atomic<int64_t> time{0};
        std::atomic<uint64_t> tag{~uint64_t(0)};
    };
    std::unique_ptr<TimelineSlot[]> timeline_;
    std::atomic<uint64_t> timelineNext_{0};

    std::atomic<bool> ended_{false};
    PlcTime endTime_ = 0;
};

}  // namespace strun::live
