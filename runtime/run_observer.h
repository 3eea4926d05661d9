// What the scheduler tells an observer of the run (the --vcd recorder):
// task execution switches and activation ends. Called only at activation
// granularity, never per statement, and only when RunOptions::observer is
// set, so a run without one pays nothing.
#pragma once

#include <cstddef>

#include "runtime/machine.h"

namespace strun::rt {

class RunObserver {
public:
    virtual ~RunObserver() = default;
    // `task` (index into the scheduler's task list) starts or resumes
    // executing (running) or is preempted or ends (not running), at `now`.
    virtual void taskRunning(size_t task, bool running, PlcTime now) = 0;
    // An activation of `task` ended (completed or aborted): sample values.
    virtual void activationEnded(size_t task, PlcTime now) = 0;
    // An output phase copied the program's %Q image to the physical outputs
    // (after activationEnded of the same activation).
    virtual void outputsWritten(PlcTime) {}
    // The run is over at `end` (any reason): flush.
    virtual void runEnded(PlcTime end) = 0;
};

}  // namespace strun::rt
