// What the scheduler offers a live front end (live/control_plane.h: the web
// monitor, the debugger, Modbus): the moments at which outside writes and
// forces are applied, values are published and the PLC may pause. The
// runtime knows only this interface; live/ implements it.
//
// Called at activation granularity only, and only when RunOptions::live is
// set: a run without a live option pays one null-pointer test per
// activation. Every call comes from the scheduler's thread; an
// implementation must never make it wait on a front end (no lock a reader
// may hold, no I/O), with one exception: holdWhilePaused() blocks for as
// long as the PLC is paused, which is its purpose.
#pragma once

#include <cstddef>

#include "runtime/machine.h"

namespace strun::rt {

class Scheduler;

class LiveHooks {
public:
    virtual ~LiveHooks() = default;
    // Scheduler::run() begins (before the first activation).
    virtual void runStarting(Scheduler& scheduler) = 0;
    // Between two activations, none in progress: returns false at once
    // unless the PLC is paused; then blocks until it is resumed or stepped or
    // the run is asked to stop, and returns true. PLC time stands still
    // meanwhile, on the real clock too (the scheduler takes the time spent
    // paused out of PLC time).
    virtual bool holdWhilePaused() = 0;
    // Activation of `task` (index into the scheduler's task list) starts:
    // before its input phase (queued writes, forces).
    virtual void activationStarting(size_t task) = 0;
    // Right after its input phase (forces on %I go into the input image).
    virtual void inputsLatched(size_t task) = 0;
    // Its code has run (completed or aborted), before the output phase (forces again).
    virtual void activationEnding(size_t task) = 0;
    // After the output phase. `outermost`: no other activation is in
    // progress underneath (none preempted), so memory is one consistent state.
    virtual void activationEnded(size_t task, bool completed, bool outermost) = 0;
    // `task` starts or resumes executing (running) or is preempted or ends.
    virtual void taskRunning(size_t task, bool running, PlcTime now) = 0;
};

}  // namespace strun::rt
