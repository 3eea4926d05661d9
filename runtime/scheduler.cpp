#include "runtime/scheduler.h"

#include <algorithm>
#include <cstring>
#include <iostream>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <tuple>

#include "runtime/duration_text.h"
#include "runtime/real_clock.h"
#include "runtime/realtime.h"
#include "runtime/system_area.h"
#include "runtime/time_event.h"
#include "stdlib/number_scan.h"

namespace strun::rt {

std::atomic<bool> Scheduler::stopRequested_{false};
std::atomic<Machine*> Scheduler::runningMachine_{nullptr};

namespace {

// The real clock's idle sleep never exceeds this, so a stop request that
// arrives as a signal on another thread is seen within this time.
constexpr PlcTime kMaxIdleSleep = 20 * kMillisecond;
// SCHED_FIFO priorities for --realtime: the timer must preempt the PLC thread.
constexpr int kPlcThreadPriority = 80;
constexpr int kTimerThreadPriority = 90;

// Start-up order among tasks of equal priority released at the same moment
// (seed 000, 4.6.1.5): event-like tasks, then cyclic ones by shorter period,
// then freewheeling ones; declaration order last.
int kindRank(TaskKind kind) {
    switch (kind) {
    case TaskKind::Startup:
    case TaskKind::ProgramError:
    case TaskKind::ExecTimeout: return 0;
    case TaskKind::Event:
    case TaskKind::Status:
    case TaskKind::External:
    case TaskKind::TimeEvent: return 1;
    case TaskKind::Cyclic: return 2;
    case TaskKind::Freewheeling: return 3;
    }
    return 3;
}

// --dump reports durations in microseconds; whole numbers stay integers.
nlohmann::json micros(PlcTime nanos) {
    if (nanos % 1000 == 0) return nanos / 1000;
    return double(nanos) / 1000.0;
}

}  // namespace

const char* plcStateName(PlcState state) {
    switch (state) {
    case PlcState::Run: return "RUN";
    case PlcState::Stop: return "STOP";
    case PlcState::Halt: return "HALT";
    }
    return "STOP";
}

bool Scheduler::hasTask(const std::vector<TaskSpec>& tasks, std::string_view name) {
    return std::any_of(tasks.begin(), tasks.end(), [&](const TaskSpec& t) { return stdlib::equalsIgnoreCase(t.name, name); });
}

Scheduler::Scheduler(Machine& machine, std::vector<TaskSpec> tasks, std::vector<TaskBody*> bodies, RunOptions options)
    : machine_(machine),
      options_(std::move(options)),
      profile_(options_.profile ? *options_.profile : defaultProfile()),
      diagnostics_(options_.diagnosticCapacity) {
    if (tasks.size() != bodies.size()) throw std::invalid_argument("scheduler: one task body per task is required");
    tasks_.resize(tasks.size());
    for (size_t i = 0; i < tasks.size(); ++i) {
        TaskRun& run = tasks_[i];
        run.spec = std::move(tasks[i]);
        run.body = bodies[i];
        run.isFaultTask = run.spec.kind == TaskKind::ProgramError || run.spec.kind == TaskKind::ExecTimeout;
        run.period = run.spec.interval;
        if (run.spec.systemSlot == 0 && !master_) master_ = &run;
        if (run.spec.isScanProgram && profile_.triggerSampling == TriggerSampling::EndOfScan) scanSampling_ = true;
        if (run.spec.kind == TaskKind::Startup && !startup_) startup_ = &run;
        if (run.spec.kind == TaskKind::ProgramError && !errorTask_) errorTask_ = &run;
        if (run.spec.kind == TaskKind::ExecTimeout && !timeoutTask_) timeoutTask_ = &run;
    }
    std::vector<size_t> order(tasks_.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        const TaskSpec& x = tasks_[a].spec;
        const TaskSpec& y = tasks_[b].spec;
        if (kindRank(x.kind) != kindRank(y.kind)) return kindRank(x.kind) < kindRank(y.kind);
        if (x.kind == TaskKind::Cyclic && y.kind == TaskKind::Cyclic) return x.interval < y.interval;
        return false;
    });
    for (size_t rank = 0; rank < order.size(); ++rank) tasks_[order[rank]].tieRank = int(rank);

    if (options_.cycles) {
        if (tasks_.empty()) throw std::invalid_argument("--cycles: the project has no task");
        const std::string& name = options_.cyclesTask.empty() ? tasks_.front().spec.name : options_.cyclesTask;
        for (TaskRun& run : tasks_)
            if (stdlib::equalsIgnoreCase(run.spec.name, name)) {
                cyclesTask_ = &run;
                break;
            }
        if (!cyclesTask_) throw std::invalid_argument("--task: no task named '" + name + "'");
    }
    stack_.reserve(tasks_.size() + 1);
    if (profile_.systemVariables == SystemVariables::Modicon)
        system_ = std::make_unique<SystemArea>(machine_.image, profile_);
}

Scheduler::~Scheduler() = default;

void Scheduler::requestStop() {
    stopRequested_.store(true);
    // Lock-free atomics only: this runs inside a signal handler.
    if (Machine* machine = runningMachine_.load()) machine->requestAttentionFromOtherThread();
}

// ---------------------------------------------------------------- the run

PlcState Scheduler::run() {
    // The stop flag is cleared when a run ends, not here: a Ctrl-C that comes
    // between installing the handler and this call still stops the run.
    runningMachine_.store(&machine_);
    machine_.handler = options_.front ? options_.front : this;
    for (const ImageArea* area : {&machine_.image.inputs, &machine_.image.outputs, &machine_.image.memory})
        machine_.memory.add(area->data(), area->size());
    machine_.setTime(0);
    machine_.setDeadline(kNever);
    // PLC time ends at kPlcTimeLimit (about 146 years) even without --for:
    // with --stmt-cost at most kMaxStmtCost, Machine::tick can then never
    // overflow the clock (docs/limits.md).
    forEnd_ = std::min(options_.duration.value_or(kNever), kPlcTimeLimit);
    if (options_.virtualClock) {
        machine_.setStmtCost(std::max<PlcTime>(options_.stmtCost, 1));
        calendarBase_ = options_.startCalendarNanos;
    } else {
        machine_.setStmtCost(0);
        // --realtime: lock memory and switch to SCHED_FIFO *before* PLC time
        // starts. mlockall faults in every mapped page (the reserved frame
        // stacks, the heap's top pad): about 10 ms that, counted as PLC
        // time, made the first releases late and showed as start-up latency
        // and overruns (issue 29, docs/realtime.md).
        // The timer thread's 8 MiB stack is locked page by page when it is
        // created under mlockall(MCL_FUTURE) (2-3 ms): it too is started
        // before PLC time 0.
        std::vector<std::string> notes;
        if (options_.realtime) notes = enableRealtimeForThisThread(kPlcThreadPriority);
        timer_ = std::make_unique<AttentionTimer>(machine_, monotonicNanos());
        if (options_.realtime) {
            if (std::string note = enableRealtimeForThread(timer_->thread(), kTimerThreadPriority); !note.empty())
                notes.push_back(note);
            std::ostream& out = options_.warnings ? *options_.warnings : std::cerr;
            for (const std::string& note : notes) out << "strun: warning: --realtime: " << note << '\n';
        }
        calendarBase_ = realtimeNanos();
        monotonicOrigin_ = monotonicNanos();
        timer_->setOrigin(monotonicOrigin_);
    }
    if (options_.realtime && options_.virtualClock) {
        std::ostream& out = options_.warnings ? *options_.warnings : std::cerr;
        out << "strun: warning: --realtime has no effect on the virtual clock\n";
    }

    for (TaskRun& task : tasks_) {
        // Event tasks react to rising edges after RUN: a BOOL already TRUE at RUN is no edge.
        if (task.spec.kind == TaskKind::Event) task.lastTrigger = task.spec.trigger.byte && task.spec.trigger.read();
        if (task.spec.kind == TaskKind::External)
            task.lastTrigger = (machine_.image.physicalInputs[task.spec.inputByte] >> task.spec.inputBit) & 1;
        // Time events follow the calendar from RUN on; one due during the startup task waits for its end.
        if (task.spec.kind == TaskKind::TimeEvent) {
            task.nextOccurrence = nextTimeEventOccurrence(task.spec.atCalendarNanos, task.spec.repeat, calendarBase_);
            task.nextRelease = calendarToPlc(task.nextOccurrence);
        }
    }
    if (system_) {
        std::array<PlcTime, SystemArea::kSlots> periods{};
        for (const TaskRun& task : tasks_)
            if (task.spec.systemSlot >= 0 && task.spec.systemSlot < SystemArea::kSlots)
                periods[size_t(task.spec.systemSlot)] = task.spec.interval;
        system_->start(periods, master_ ? master_->spec.watchdog : 0);
    }
    masterOnlyPhase_ = profile_.firstCycle == FirstCyclePolicy::MasterOnly && master_;
    // The stimulus tells the scheduler about input changes only when an EXTERNAL task listens.
    bool hasExternal = std::any_of(tasks_.begin(), tasks_.end(), [](const TaskRun& t) { return t.spec.kind == TaskKind::External; });
    if (options_.stimulus && hasExternal)
        options_.stimulus->setInputListener([this](const StimulusWrite&, PlcTime at) { physicalInputsChanged(at); });
    recomputeEarliestRelease();
    if (startup_) release(*startup_, 0, false);
    else startRegularTasks();
    if (options_.cycles && *options_.cycles == 0) ending_ = true;

    if (options_.live) options_.live->runStarting(*this);
    mainLoop();
    if (state_ == PlcState::Run && machine_.time() >= kPlcTimeLimit && (!options_.duration || *options_.duration > kPlcTimeLimit))
        (options_.warnings ? *options_.warnings : std::cerr)
            << "strun: warning: PLC time reached its limit of " << formatDuration(kPlcTimeLimit) << "; the run ends\n";

    // A fault stop ends the run at the fault, not at the statement boundary where the task unwound.
    endTime_ = state_ == PlcState::Run ? machine_.time() : stopTime_;
    if (options_.observer) options_.observer->runEnded(std::max(endTime_, machine_.time()));
    timer_.reset();
    runningMachine_.store(nullptr);
    stopRequested_.store(false);
    machine_.setDeadline(kNever);
    return state_;
}

void Scheduler::mainLoop() {
    for (;;) {
        refreshNow();
        if (stopRequested_.load()) ending_ = true;
        if (ending_) return;
        if (machine_.time() >= forEnd_) return;
        if (options_.live) [[unlikely]] {
            if (!liveHold()) return;
        }
        processDue();
        if (TaskRun* next = pickReady(nullptr)) {
            noteBusy(next);
            runActivation(*next);
            checkSystemWatchdog();
            continue;
        }
        noteBusy(nullptr);
        idle();
    }
}

// Nothing is ready: wait for the next moment anything can happen.
void Scheduler::idle() {
    PlcTime next = std::min(earliestRelease_, forEnd_);
    if (sampleOnTicks()) next = std::min(next, nextSample_);
    if (options_.virtualClock && earliestRelease_ == kNever && !options_.duration) {
        // No task runs and none is due at any time: only task code could raise
        // an event or status trigger, so nothing can ever run again. End here
        // instead of sampling (or sleeping) forever (docs/limits.md).
        std::ostream& out = options_.warnings ? *options_.warnings : std::cerr;
        out << "strun: warning: no task can ever run again; the run ends at " << formatDuration(machine_.time());
        if (cyclesTask_) out << " (" << cyclesTask_->spec.name << " completed " << cyclesTask_->cycles << " of " << *options_.cycles << " cycles)";
        out << '\n';
        ending_ = true;
        return;
    }
    if (options_.virtualClock) {
        if (next != kNever) {
            machine_.setTime(std::max(machine_.time(), next));
            return;
        }
        // Nothing can ever happen again: wait (without spinning) to be stopped.
        while (!stopRequested_.load()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        return;
    }
    timer_->arm(kNever);
    PlcTime wake = std::min(next, machine_.time() + kMaxIdleSleep);
    sleepUntilMonotonic(monotonicOrigin_ + wake);
}

void Scheduler::refreshNow() {
    if (!options_.virtualClock) machine_.setTime(monotonicNanos() - monotonicOrigin_);
}

// ---------------------------------------------------------------- releases

// STOP -> RUN is over (no startup task, or it has ended): the other tasks
// begin, cyclic grids and the first samples counting from this moment.
// Under the M340 first-cycle policy only the master task begins here; the
// others begin when its first cycle ends (onMasterEnd).
void Scheduler::startRegularTasks() {
    regularStarted_ = true;
    PlcTime now = machine_.time();
    for (TaskRun& task : tasks_)
        if (!masterOnlyPhase_ || &task == master_) startTask(task, now);
    if (sampleOnTicks()) nextSample_ = (now / profile_.schedulerTick + 1) * profile_.schedulerTick;
    recomputeEarliestRelease();
}

// The end of a MAST cycle: the activation bits %S30..%S35 are tested; after
// the first one, the other tasks begin.
void Scheduler::onMasterEnd() {
    if (system_)
        for (TaskRun& task : tasks_)
            if (task.spec.systemSlot >= 0) task.inhibited = !system_->taskActive(task.spec.systemSlot);
    if (!masterOnlyPhase_) return;
    masterOnlyPhase_ = false;
    PlcTime now = machine_.time();
    for (TaskRun& task : tasks_)
        if (&task != master_) startTask(task, now);
    if (sampleOnTicks()) nextSample_ = (now / profile_.schedulerTick + 1) * profile_.schedulerTick;
    recomputeEarliestRelease();
}

void Scheduler::startTask(TaskRun& task, PlcTime now) {
        switch (task.spec.kind) {
        case TaskKind::Cyclic:
            release(task, now, true);
            task.nextRelease = task.period > 0 ? now + task.period : kNever;
            break;
        case TaskKind::Freewheeling: release(task, now, false); break;
        case TaskKind::Event: {
            // The reference was sampled at RUN: an edge made by the startup task counts.
            hasTriggers_ = true;
            bool value = task.spec.trigger.byte && task.spec.trigger.read();
            if (value && !task.lastTrigger) release(task, now, true);
            task.lastTrigger = value;
            break;
        }
        case TaskKind::Status:
            hasTriggers_ = true;
            if (task.spec.trigger.byte && task.spec.trigger.read()) release(task, now, false);
            break;
        case TaskKind::TimeEvent:  // scheduled at RUN (run()): they follow the calendar
        case TaskKind::External:   // released by physicalInputsChanged()
        case TaskKind::Startup:
        case TaskKind::ProgramError:
        case TaskKind::ExecTimeout: break;
        }
}

PlcTime Scheduler::calendarToPlc(int64_t calendar) const {
    if (calendar == kNever) return kNever;
    // Checked: an AT of LDT#1700-01-01 is far before any base; one past the end never comes.
    PlcTime plc = 0;
    if (__builtin_sub_overflow(calendar, calendarBase_, &plc)) return calendar < calendarBase_ ? machine_.time() : kNever;
    return std::max<PlcTime>(plc, machine_.time());
}

// Releases everything whose moment has come, in time order (ties: declaration order).
void Scheduler::processDue() {
    PlcTime now = machine_.time();
    if (earliestRelease_ <= now) {
        if (options_.stimulus) options_.stimulus->applyInputsDue(now, options_.trace);
        for (;;) {
            TaskRun* due = nullptr;
            for (TaskRun& task : tasks_)
                if (task.nextRelease <= now && (!due || task.nextRelease < due->nextRelease)) due = &task;
            if (!due) break;
            PlcTime nominal = due->nextRelease;
            scheduleNext(*due);
            release(*due, nominal, true);
        }
        recomputeEarliestRelease();
    }
    if (sampleOnTicks() && nextSample_ <= now) {
        // Missed ticks are not caught up: sampling twice at one moment sees the same values.
        nextSample_ = (now / profile_.schedulerTick + 1) * profile_.schedulerTick;
        sampleTriggers();
    }
}

void Scheduler::scheduleNext(TaskRun& task) {
    if (task.spec.kind == TaskKind::Cyclic) {
        task.nextRelease += task.period;  // the grid, whatever happened to this activation
    } else if (task.spec.kind == TaskKind::TimeEvent) {
        task.nextOccurrence = nextTimeEventOccurrence(task.spec.atCalendarNanos, task.spec.repeat, task.nextOccurrence + 1);
        task.nextRelease = calendarToPlc(task.nextOccurrence);
    } else {
        task.nextRelease = kNever;
    }
}

void Scheduler::recomputeEarliestRelease() {
    earliestRelease_ = kNever;
    for (const TaskRun& task : tasks_) earliestRelease_ = std::min(earliestRelease_, task.nextRelease);
    // A stimulus on a physical input is a moment to wake up for, like a release.
    if (options_.stimulus) earliestRelease_ = std::min(earliestRelease_, options_.stimulus->nextInputAt());
}

// Makes the task ready. A task already ready or running drops the new
// activation; for the kinds that have a release of their own (cyclic,
// event, time event) that is an OVERRUN.
bool Scheduler::release(TaskRun& task, PlcTime nominal, bool reportOverrun) {
    if (task.phase != Phase::Idle) {
        if (reportOverrun) {
            // M241: a cyclic task whose period is too short starts again right after its outputs.
            bool restart = profile_.overrun == OverrunPolicy::RestartAtEnd && task.spec.kind == TaskKind::Cyclic &&
                           task.phase == Phase::Active;
            ++task.overruns;
            if (system_) system_->setOverrun(task.spec.systemSlot);
            trace(&task, "overrun");
            record(DiagCode::Overrun, &task, "", 0,
                   "task '" + task.spec.name + "' released at " + formatDuration(nominal) + " while its previous activation is still " +
                       (task.phase == Phase::Ready ? "waiting" : "running") +
                       (restart ? "; it restarts right after writing its outputs" : "; the activation is dropped"));
            if (restart && !task.restartPending) {
                task.restartPending = true;
                task.restartNominal = nominal;
            }
        }
        return false;
    }
    task.phase = Phase::Ready;
    task.releasedAt = nominal;
    trace(&task, "release");
    return true;
}

// Event tasks: one release per rising edge between two samples. Status
// tasks: a release whenever the BOOL is TRUE and the task is idle.
void Scheduler::sampleTriggers() {
    if (!regularStarted_) return;
    PlcTime now = machine_.time();
    for (TaskRun& task : tasks_) {
        if (task.spec.kind != TaskKind::Event && task.spec.kind != TaskKind::Status) continue;
        bool value = task.spec.trigger.byte && task.spec.trigger.read();
        if (task.spec.kind == TaskKind::Event) {
            if (value && !task.lastTrigger) release(task, now, true);
            task.lastTrigger = value;
        } else if (value && task.phase == Phase::Idle) {
            release(task, now, false);
        }
    }
}

// ---------------------------------------------------------------- dispatch

// The ready task that should run now: highest priority, then the longest
// waiting, then the start-up order. With `running`, only one allowed to
// preempt it (strictly higher priority; the startup task yields only to the
// program-error and execution-timeout tasks, but to those whatever their priority).
Scheduler::TaskRun* Scheduler::pickReady(const TaskRun* running) const {
    TaskRun* best = nullptr;
    for (const TaskRun& candidate : tasks_) {
        if (candidate.phase != Phase::Ready) continue;
        // Until the startup task has ended, only it and the fault tasks may run.
        if (!regularStarted_ && !candidate.isFaultTask && &candidate != startup_) continue;
        if (best) {
            const TaskSpec& a = candidate.spec;
            const TaskSpec& b = best->spec;
            if (a.priority != b.priority) {
                if (a.priority > b.priority) continue;
            } else if (candidate.releasedAt != best->releasedAt) {
                if (candidate.releasedAt > best->releasedAt) continue;
            } else if (candidate.tieRank > best->tieRank) {
                continue;
            }
        }
        best = const_cast<TaskRun*>(&candidate);
    }
    if (!best || !running) return best;
    if (best->spec.priority < running->spec.priority) return best;
    if (running == startup_ && best->isFaultTask) return best;
    return nullptr;
}

void Scheduler::runActivation(TaskRun& task) {
    // Compiled twice: without a control plane (the common case) the body is
    // exactly the one a run without live options had, and the only cost of
    // the live hooks is the one null test below, once per activation.
    auto activation = [&]<bool Live>() {
        // Only an observer needs the task's index: not computed otherwise.
        auto index = [&] { return size_t(&task - tasks_.data()); };
        // A task switch for the --vcd observer (and the live timeline).
        auto observe = [&](bool running) {
            if constexpr (Live) observeRunning(task, running);
            else if (options_.observer) options_.observer->taskRunning(index(), running, machine_.time());
        };
        refreshNow();
        PlcTime start = machine_.time();
        task.phase = Phase::Active;
        task.startedAt = start;
        task.watchdogAt = task.spec.watchdog > 0 ? start + task.spec.watchdog : kNever;
        PlcTime latency = start - task.releasedAt;
        task.minLatency = std::min(task.minLatency, latency);
        task.maxLatency = std::max(task.maxLatency, latency);
        ++task.started;
        ++activations_;
        stack_.push_back(&task);
        trace(&task, task.inhibited ? "inhibited" : "start");
        observe(true);
        int slot = task.spec.systemSlot;
        if (system_) system_->enter(slot);

        // --set variable writes due by now, live writes and forces, then the input phase.
        if (options_.stimulus) options_.stimulus->applyVariablesDue(start, options_.trace);
        if constexpr (Live) liveEvent(LiveEvent::Starting, task);
        ProcessImage& image = machine_.image;
        if (!system_ || !system_->inputsInhibited(slot))
            std::memcpy(image.inputs.data(), image.physicalInputs.data(), std::min(image.inputExtent, ProcessImage::kSize));
        if constexpr (Live) liveEvent(LiveEvent::InputsLatched, task);
        armNextAttention();

        bool completed = task.inhibited || !task.body ? true : task.body->runActivation();
        if constexpr (Live) liveEvent(LiveEvent::Ending, task);

        // An activation costs at least one statement, even an empty one, so a
        // freewheeling task can never spin at a standstill on the virtual clock.
        if (options_.virtualClock && machine_.time() == start) machine_.setTime(start + machine_.stmtCost);
        refreshNow();
        if (options_.observer) {
            options_.observer->activationEnded(index(), machine_.time());
            observe(false);
        } else if constexpr (Live) {
            observe(false);
        }
        stack_.pop_back();
        // No activation left running: host memory of blocks __DELETE released may go (runtime/heap.h).
        if (stack_.empty()) machine_.heap.trim();
        task.phase = Phase::Idle;
        task.watchdogAt = kNever;
        if (system_) system_->leave(task.spec.systemSlot);
        finishActivation(task, completed);
        if constexpr (Live) liveEvent(completed ? LiveEvent::EndedCompleted : LiveEvent::EndedAborted, task);
    };
    if (options_.live) [[unlikely]] activation.template operator()<true>();
    else activation.template operator()<false>();
}

// The live hooks (runtime/live_hooks.h), out of line and cold: a run without
// a control plane pays only the null tests at their call sites, and the
// scheduler's hot functions keep the inlining they had without them.
bool Scheduler::liveHold() {
    // Paused between two activations. PLC time stands still meanwhile, on the
    // real clock too: the time spent paused is taken out of it, so a pause
    // causes no overruns (decision 0171).
    const int64_t holdStart = options_.virtualClock ? 0 : monotonicNanos();
    if (options_.live->holdWhilePaused() && !options_.virtualClock) {
        const int64_t paused = monotonicNanos() - holdStart;
        monotonicOrigin_ += paused;
        timer_->shiftOrigin(paused);
    }
    refreshNow();
    if (stopRequested_.load()) ending_ = true;
    return !ending_ && machine_.time() < forEnd_;
}

void Scheduler::liveEvent(LiveEvent event, const TaskRun& task) {
    const size_t index = size_t(&task - tasks_.data());
    switch (event) {
    case LiveEvent::Starting: options_.live->activationStarting(index); break;
    case LiveEvent::InputsLatched: options_.live->inputsLatched(index); break;
    case LiveEvent::Ending: options_.live->activationEnding(index); break;
    case LiveEvent::EndedCompleted:
    case LiveEvent::EndedAborted: options_.live->activationEnded(index, event == LiveEvent::EndedCompleted, stack_.empty()); break;
    case LiveEvent::Running:
    case LiveEvent::Stopped: options_.live->taskRunning(index, event == LiveEvent::Running, machine_.time()); break;
    }
}

void Scheduler::finishActivation(TaskRun& task, bool completed) {
    PlcTime now = machine_.time();
    if (task.abortRequested) {
        task.abortRequested = false;
        if (!ending_) trace(&task, "abort");  // after a STOP the "stop" line says it all
    } else if (completed) {
        int slot = task.spec.systemSlot;
        ProcessImage& image = machine_.image;
        // M241: an external task that switches a fast output needs 15 ms between triggers.
        if (profile_.fastOutputMask && task.spec.kind == TaskKind::External &&
            ((image.physicalOutputs[0] ^ image.outputs[0]) & profile_.fastOutputMask))
            task.drivesFastOutputs = true;
        // An inhibited M340 task still writes its outputs (seed 002).
        if (!system_ || !system_->outputsInhibited(slot)) {
            std::memcpy(image.physicalOutputs.data(), image.outputs.data(), std::min(image.outputExtent, ProcessImage::kSize));
            if (options_.observer) options_.observer->outputsWritten(now);  // --vcd's physical outputs
        }
        if (!task.inhibited) {
            PlcTime exec = now - task.startedAt;
            ++task.cycles;
            task.lastExec = exec;
            task.minExec = std::min(task.minExec, exec);
            task.maxExec = std::max(task.maxExec, exec);
            task.sumExec += exec;
            if (system_) system_->recordExecution(slot, exec);
            trace(&task, "end");
            if (&task == cyclesTask_ && task.cycles >= *options_.cycles) ending_ = true;
        }
    }
    if (ending_) return;
    if (&task == startup_ && !regularStarted_) startRegularTasks();
    if (&task == master_) onMasterEnd();
    if (system_) {
        if (master_) switchMasterMode(*master_, system_->requestedMasterPeriod(master_->period));
        for (TaskRun& other : tasks_)
            if (other.spec.kind == TaskKind::Cyclic) setPeriod(other, system_->requestedPeriod(other.spec.systemSlot, other.period));
    }
    if (task.restartPending) {
        task.restartPending = false;
        release(task, task.restartNominal, false);
    }
    if (task.spec.kind == TaskKind::Freewheeling) {
        if (profile_.freewheelingGap > 0) {
            task.nextRelease = now + profile_.freewheelingGap;  // system processing before the next scan
            recomputeEarliestRelease();
        } else {
            release(task, now, false);
        }
    }
    if (hasTriggers_ && (!scanSampling_ || task.spec.isScanProgram)) sampleTriggers();
}

// ---------------------------------------------------------------- periods and external inputs

PlcTime Scheduler::currentTaskInterval() {
    if (stack_.empty() || stack_.back()->spec.kind != TaskKind::Cyclic) return 0;
    return stack_.back()->period;
}

bool Scheduler::setCurrentTaskInterval(PlcTime period) {
    if (stack_.empty()) return false;
    TaskRun& task = *stack_.back();
    if (task.spec.kind != TaskKind::Cyclic || period < profile_.minInterval || period > profile_.maxInterval ||
        period % profile_.intervalStep != 0)
        return false;
    setPeriod(task, period);
    return true;
}

// M340: %SW0 = 0 makes MAST cyclic (freewheeling: released again at each
// end), 1..255 periodic with that period, at run time (decision 0117). A
// cyclic MAST excludes AUX tasks, so with AUX tasks configured 0 is ignored.
void Scheduler::switchMasterMode(TaskRun& mast, PlcTime period) {
    const bool cyclicNow = mast.spec.kind == TaskKind::Freewheeling;
    if (period == 0 && !cyclicNow) {
        for (const TaskRun& t : tasks_)
            if (t.spec.systemSlot >= 0 && size_t(t.spec.systemSlot) < profile_.fixedTasks.size() &&
                profile_.fixedTasks[size_t(t.spec.systemSlot)].needsPeriodicMaster)
                return;
        mast.spec.kind = TaskKind::Freewheeling;
        mast.period = 0;
        mast.nextRelease = kNever;
        trace(&mast, "mode", "cyclic");
        // Idle until its next grid point: it runs again at once instead.
        if (mast.phase == Phase::Idle && &mast != (stack_.empty() ? nullptr : stack_.back())) release(mast, machine_.time(), false);
        recomputeEarliestRelease();
    } else if (period > 0 && cyclicNow) {
        mast.spec.kind = TaskKind::Cyclic;
        mast.period = period;
        // The grid starts from the release of its current (or last) scan.
        mast.nextRelease = std::max(mast.releasedAt + period, machine_.time());
        trace(&mast, "mode", "periodic");
        recomputeEarliestRelease();
    }
}

// The grid restarts from the current (or last) activation's release.
void Scheduler::setPeriod(TaskRun& task, PlcTime period) {
    if (period == task.period || period <= 0) return;
    task.period = period;
    if (task.nextRelease != kNever) task.nextRelease = task.releasedAt + period;
    recomputeEarliestRelease();
    if (!stack_.empty()) armNextAttention();
}

void Scheduler::physicalInputsChanged(PlcTime now) {
    bool planned = false;
    for (TaskRun& task : tasks_) {
        if (task.spec.kind != TaskKind::External) continue;
        bool value = (machine_.image.physicalInputs[task.spec.inputByte] >> task.spec.inputBit) & 1;
        if (value == task.lastTrigger) continue;
        task.lastTrigger = value;
        if (!(task.spec.edges & (value ? kEdgeRising : kEdgeFalling))) continue;
        if (task.nextRelease != kNever) {
            ++task.overruns;
            trace(&task, "overrun");
            record(DiagCode::Overrun, &task, "", 0,
                   "external task '" + task.spec.name + "' triggered at " + formatDuration(now) +
                       " while its previous trigger still waits for its release; the trigger is dropped");
            continue;
        }
        PlcTime at = now + profile_.externalDetectionDelay + task.spec.inputDelay;
        const PlcTime spacing = task.drivesFastOutputs ? profile_.externalMinSpacingFastOutputs : profile_.externalMinSpacing;
        if (task.hasExternalRelease) at = std::max(at, task.lastExternalRelease + spacing);
        task.nextRelease = at;
        task.lastExternalRelease = at;
        task.hasExternalRelease = true;
        planned = true;
    }
    if (!planned) return;
    recomputeEarliestRelease();
    if (!stack_.empty()) armNextAttention();
}

bool Scheduler::onAttention() {
    if (options_.virtualClock) {
        machine_.deadline.store(kNever, std::memory_order_relaxed);
    } else {
        // Raise the deadline BEFORE reading the clock: a timer poke that lands
        // after this exchange calls us again, one before it is covered below.
        machine_.deadline.exchange(kNever, std::memory_order_acq_rel);
        refreshNow();
    }
    if (stack_.empty()) return ending_;  // not from a task body: nothing to decide
    TaskRun& current = *stack_.back();
    bool preempted = false;
    for (;;) {
        if (stopRequested_.load()) ending_ = true;
        if (machine_.time() >= forEnd_) ending_ = true;
        if (ending_) {
            requestOwnAttention();  // every level below unwinds too
            return true;
        }
        processDue();
        checkWatchdogs();
        checkSystemWatchdog();
        if (ending_) continue;
        if (current.abortRequested) {
            armNextAttention();
            return true;
        }
        TaskRun* next = pickReady(&current);
        if (!next) break;
        if (!preempted) {
            trace(&current, "preempt");
            observeRunning(current, false);
            if (system_) system_->leave(current.spec.systemSlot);
        }
        preempted = true;
        runActivation(*next);
    }
    if (preempted) {
        trace(&current, "resume");
        observeRunning(current, true);
        if (system_) system_->enter(current.spec.systemSlot);
    }
    armNextAttention();
    return false;
}

// ---------------------------------------------------------------- watchdog and faults

// Execution time counts from the activation's start, preemptions included.
void Scheduler::checkWatchdogs() {
    for (TaskRun* task : stack_)
        if (machine_.time() >= task->watchdogAt) tripWatchdog(*task);
}

// The processor passes from the base level to `next` (nullptr: idle). A task
// above the system watchdog's priorities, or a pause, ends the busy stretch.
void Scheduler::noteBusy(const TaskRun* next) {
    if (profile_.systemWatchdogBusy <= 0) return;
    if (!next || next->spec.priority > profile_.systemWatchdogMaxPriority) highBusySince_ = kNever;
    else if (highBusySince_ == kNever) highBusySince_ = machine_.time();
}

void Scheduler::checkSystemWatchdog() {
    if (highBusySince_ == kNever || ending_ || machine_.time() - highBusySince_ <= profile_.systemWatchdogBusy) return;
    const TaskRun* current = stack_.empty() ? nullptr : stack_.back();
    // Reported where the running task was, like a task watchdog.
    std::string pou;
    int line = 0, file = -1, col = 0;
    if (current && current->body) {
        current->body->currentPosition(pou, line);
        current->body->currentFileAndColumn(file, col);
    }
    record(DiagCode::SystemWatchdog, current, pou, line,
           "tasks of priority 0.." + std::to_string(profile_.systemWatchdogMaxPriority) + " held the processor without a pause for more than " +
               formatDuration(profile_.systemWatchdogBusy) + " (since " + formatDuration(highBusySince_) +
               "); application error: the controller stops",
           file, col);
    highBusySince_ = kNever;
    faultStop(current, DiagCode::SystemWatchdog, PlcState::Stop);
}

std::string Scheduler::virtualCostNote(PlcTime elapsed) const {
    // On the virtual clock all running time is the modelled statement cost:
    // say so, or the user looks for a slow statement that does not exist.
    if (!options_.virtualClock || machine_.stmtCost <= 0) return {};
    return " (virtual clock: " + std::to_string(elapsed / machine_.stmtCost) + " statements at --stmt-cost " +
           formatDuration(machine_.stmtCost) + " each: a loop that does not end, or more statements than the watchdog allows at that --stmt-cost)";
}

void Scheduler::tripWatchdog(TaskRun& task) {
    task.watchdogAt = kNever;
    bool timeoutTaskTripped = &task == timeoutTask_;
    // Baosky's startup task is interrupted by the timeout task, not aborted (decision 0297).
    const bool goesOn = profile_.startupInterruptedOnWatchdog && &task == startup_ && timeoutTask_ && !timeoutTaskTripped;
    task.abortRequested = !goesOn;
    ++task.watchdogTrips;
    trace(&task, "watchdog");
    if (system_) system_->setWatchdogOverflow();
    std::string pou;
    int line = 0, file = -1, col = 0;
    if (task.body) {
        task.body->currentPosition(pou, line);
        task.body->currentFileAndColumn(file, col);
    }
    record(DiagCode::Watchdog, &task, pou, line,
           std::string(timeoutTaskTripped ? "the execution-timeout task '" : "task '") + task.spec.name +
               "' reached its watchdog of " + formatDuration(task.spec.watchdog) + " (running for " +
               formatDuration(machine_.time() - task.startedAt) + ", preemptions included); " +
               (goesOn ? "the execution-timeout task interrupts it and it goes on" : "the activation is aborted") +
               virtualCostNote(machine_.time() - task.startedAt),
           file, col);
    PlcState reaction = profile_.watchdogReaction == WatchdogReaction::Halt ? PlcState::Halt : PlcState::Stop;
    if (timeoutTaskTripped || !timeoutTask_) faultStop(&task, DiagCode::Watchdog, reaction);
    else release(*timeoutTask_, machine_.time(), false);
}

void Scheduler::faultStop(const TaskRun* task, DiagCode code, PlcState state) {
    // The entry just recorded is the fault that stops the PLC.
    if (!diagnostics_.entries().empty()) stopFaults_.push_back(diagnostics_.entries().back());
    if (state_ == PlcState::Run) {
        state_ = state;
        stopTime_ = machine_.time();
    }
    ending_ = true;
    // STOP ends every activation in progress, also one whose fault came in
    // its last statement: none of them completes a cycle or writes outputs.
    for (TaskRun* running : stack_) running->abortRequested = true;
    trace(task, state == PlcState::Halt ? "halt" : "stop", diagCodeName(code));
    requestOwnAttention();
}

void Scheduler::onFault(DiagCode code, std::string_view pou, int line, std::string message, int file, int col) {
    refreshNow();
    TaskRun* current = stack_.empty() ? nullptr : stack_.back();
    trace(current, "error", diagCodeName(code));
    record(code, current, pou, line, std::move(message), file, col);
    switch (code) {
    case DiagCode::DivByZero:
    case DiagCode::Overrun:
    case DiagCode::Watchdog:
    case DiagCode::IoFault: return;  // recorded; execution goes on
    case DiagCode::ArrayBounds:
    case DiagCode::NullPointer:
        // A program error inside the program-error task itself stops the PLC,
        // as a watchdog trip of the execution-timeout task does.
        if (errorTask_ && current != errorTask_) {
            release(*errorTask_, machine_.time(), false);
            requestOwnAttention();  // it may preempt at the next statement boundary
            return;
        }
        faultStop(current, code, PlcState::Stop);
        return;
    case DiagCode::CallDepth:
    case DiagCode::TaskError:
    case DiagCode::SystemWatchdog: faultStop(current, code, PlcState::Stop); return;
    case DiagCode::Log: return;
    }
}

void Scheduler::recordOutsideFault(DiagCode code, std::string message) {
    trace(nullptr, "error", diagCodeName(code));
    record(code, nullptr, "", 0, std::move(message));
}

void Scheduler::onLog(std::string_view pou, int line, std::string message, int file, int col) {
    refreshNow();
    record(DiagCode::Log, stack_.empty() ? nullptr : stack_.back(), pou, line, std::move(message), file, col);
}

void Scheduler::record(DiagCode code, const TaskRun* task, std::string_view pou, int line, std::string message, int file, int col) {
    if (file >= 0 && options_.originalPosition) std::tie(line, col) = options_.originalPosition(file, line, col);
    diagnostics_.add({machine_.time(), code, task ? task->spec.name : std::string(), std::string(pou), line, std::move(message), file, col});
}

// ---------------------------------------------------------------- attention

// The next moment onAttention must run: the earliest release, sampling tick,
// end of --for, or watchdog expiry of an active activation.
void Scheduler::armNextAttention() {
    PlcTime at = std::min(earliestRelease_, forEnd_);
    if (sampleOnTicks()) at = std::min(at, nextSample_);
    for (const TaskRun* task : stack_) at = std::min(at, task->watchdogAt);
    if (highBusySince_ != kNever) at = std::min(at, highBusySince_ + profile_.systemWatchdogBusy + 1);
    if (options_.virtualClock) {
        machine_.setDeadline(at);
        // requestStop() may have lowered the deadline just before the store above.
        if (stopRequested_.load() || ending_) machine_.requestAttention();
    } else {
        timer_->arm(at);
    }
    if (options_.front) {
        ownDeadline_.store(ending_ ? std::numeric_limits<PlcTime>::min() : at, std::memory_order_relaxed);
        // strun debug sees every statement boundary while it watches (decision 0271).
        if (frontEveryStatement_.load()) machine_.requestAttention();
    }
}

void Scheduler::requestOwnAttention() {
    ownDeadline_.store(std::numeric_limits<PlcTime>::min(), std::memory_order_relaxed);
    machine_.requestAttention();
}

void Scheduler::excludeFromWatchdogs(PlcTime stopped) {
    if (stopped <= 0) return;
    for (TaskRun* task : stack_)
        if (task->watchdogAt != kNever) task->watchdogAt += stopped;
    if (highBusySince_ != kNever) highBusySince_ = std::min(highBusySince_ + stopped, machine_.time());
    if (!stack_.empty()) armNextAttention();
}

PlcTime Scheduler::currentTime() {
    refreshNow();
    return machine_.time();
}

int64_t Scheduler::calendarNanos() {
    if (options_.virtualClock) return calendarBase_ + machine_.time();
    return realtimeNanos();
}

int64_t Scheduler::taskStartCalendarNanos() {
    PlcTime now = currentTime();
    PlcTime start = stack_.empty() ? now : stack_.back()->releasedAt;
    return calendarNanos() - (now - start);
}

void Scheduler::observeRunning(const TaskRun& task, bool running) {
    if (options_.observer) options_.observer->taskRunning(size_t(&task - tasks_.data()), running, machine_.time());
    if (options_.live) [[unlikely]] liveEvent(running ? LiveEvent::Running : LiveEvent::Stopped, task);
}

std::string Scheduler::currentTaskName() const { return stack_.empty() ? std::string() : stack_.back()->spec.name; }
int Scheduler::currentTaskIndex() const { return stack_.empty() ? 0 : static_cast<int>(stack_.back() - tasks_.data()) + 1; }

bool Scheduler::taskInfo(int index, TaskInfo& out) const {
    if (index < 1 || static_cast<size_t>(index) > tasks_.size()) return false;
    const TaskRun& t = tasks_[static_cast<size_t>(index) - 1];
    out.name = t.spec.name;
    out.priority = t.spec.priority;
    out.interval = t.period;
    out.started = t.started;
    out.lastExec = t.lastExec;
    out.overrun = t.overruns != 0;
    return true;
}

// ---------------------------------------------------------------- output

// One line per event: "<PLC time> <task> <event>[ <detail>]" (decision 0011).
void Scheduler::trace(const TaskRun* task, const char* event, const char* detail) {
    if (!options_.trace) return;
    traceLine_.clear();
    appendDuration(traceLine_, machine_.time());
    traceLine_ += ' ';
    traceLine_ += task ? task->spec.name : std::string("-");
    traceLine_ += ' ';
    traceLine_ += event;
    if (detail) {
        traceLine_ += ' ';
        traceLine_ += detail;
    }
    traceLine_ += '\n';
    options_.trace->write(traceLine_.data(), std::streamsize(traceLine_.size()));
}

TaskStats Scheduler::statsOf(const TaskRun& task) const {
    TaskStats s;
    s.kind = task.spec.kind;
    s.cycles = task.cycles;
    s.overruns = task.overruns;
    s.watchdogTrips = task.watchdogTrips;
    s.started = task.started;
    s.lastExec = task.lastExec;
    s.minExec = task.minExec;
    s.maxExec = task.maxExec;
    s.sumExec = task.sumExec;
    s.minLatency = task.minLatency;
    s.maxLatency = task.maxLatency;
    return s;
}

void Scheduler::copyTaskStats(std::vector<TaskStats>& out) const {
    out.resize(tasks_.size());
    for (size_t i = 0; i < tasks_.size(); ++i) out[i] = statsOf(tasks_[i]);
}

nlohmann::ordered_json taskStatsJson(const std::vector<TaskSpec>& specs, const std::vector<TaskStats>& stats) {
    nlohmann::ordered_json array = nlohmann::ordered_json::array();
    for (size_t i = 0; i < specs.size() && i < stats.size(); ++i) {
        const TaskStats& task = stats[i];
        bool ran = task.cycles > 0;
        bool started = task.started > 0;
        array.push_back(nlohmann::ordered_json{
            {"name", specs[i].name},
            {"kind", taskKindName(task.kind)},
            {"priority", specs[i].priority},
            {"cycles", task.cycles},
            {"overruns", task.overruns},
            {"watchdog_trips", task.watchdogTrips},
            {"last_exec_us", micros(task.lastExec)},
            {"min_exec_us", micros(ran ? task.minExec : 0)},
            {"max_exec_us", micros(task.maxExec)},
            {"avg_exec_us", micros(ran ? task.sumExec / PlcTime(task.cycles) : 0)},
            {"min_latency_us", micros(started ? task.minLatency : 0)},
            {"max_latency_us", micros(task.maxLatency)},
        });
    }
    return array;
}

nlohmann::ordered_json Scheduler::tasksJson() const {
    std::vector<TaskSpec> specs;
    std::vector<TaskStats> stats;
    for (const TaskRun& task : tasks_) {
        specs.push_back(task.spec);
        stats.push_back(statsOf(task));
    }
    return taskStatsJson(specs, stats);
}

nlohmann::ordered_json diagnosticsJson(const std::vector<DiagEntry>& entries, const std::vector<std::string>& files) {
    nlohmann::ordered_json array = nlohmann::ordered_json::array();
    for (const DiagEntry& entry : entries) {
        bool known = entry.file >= 0 && size_t(entry.file) < files.size();
        array.push_back(nlohmann::ordered_json{
            {"time", formatDuration(entry.time)},
            {"code", diagCodeName(entry.code)},
            {"task", entry.task},
            {"pou", entry.pou},
            {"file", known ? files[size_t(entry.file)] : std::string()},
            {"line", entry.line},
            {"col", entry.col},
            {"message", entry.message},
        });
    }
    return array;
}

nlohmann::ordered_json Scheduler::diagnosticsJson() const { return rt::diagnosticsJson(diagnostics_.entries(), options_.sourceFiles); }

}  // namespace strun::rt
