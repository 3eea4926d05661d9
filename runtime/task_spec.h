// What the checker hands the runtime about one configured task. The checker
// resolves a CONFIGURATION's TASK declarations (or builds the default
// MainTask) into these; the scheduler runs them.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "runtime/machine.h"
#include "runtime/source_location.h"

namespace strun::rt {

enum class TaskKind {
    Cyclic,        // INTERVAL := t (t > 0)
    Freewheeling,  // no trigger, or INTERVAL := T#0ms
    Event,         // SINGLE := boolVar: once per rising edge
    Status,        // STATUS := boolVar: repeatedly while TRUE
    Startup,       // EVENT := STARTUP: once at STOP -> RUN, before every other task
    ProgramError,  // EVENT := PROGRAM_ERROR: on an ARRAY_BOUNDS fault
    ExecTimeout,   // EVENT := EXEC_TIMEOUT: on a watchdog trip
    TimeEvent,     // AT := DT#..., REPEAT := ...
    External,      // EXTERNAL := FI0 | %IX0.0, EDGE := ...: on a change of a physical input
};
const char* taskKindName(TaskKind kind);  // "cyclic", "freewheeling", "event", "status", "startup", "program_error", "exec_timeout", "time_event", "external"

// Which changes of its physical input release an EXTERNAL task (bit mask).
enum EdgeMask : uint8_t { kEdgeRising = 1, kEdgeFalling = 2, kEdgeBoth = 3 };

enum class TimeRepeat { Once, Hourly, Daily, Weekly, Monthly, MonthEnd, Yearly };

// A BOOL in storage the scheduler samples (SINGLE / STATUS). bit < 0: the
// whole byte is the BOOL (0 / 1); else bit `bit` of the byte (AT %IX...).
struct BoolRef {
    const uint8_t* byte = nullptr;
    int bit = -1;
    bool read() const { return bit < 0 ? (*byte != 0) : ((*byte >> bit) & 1) != 0; }
};

struct TaskSpec {
    std::string name;
    SourceLoc loc;
    TaskKind kind = TaskKind::Freewheeling;
    int priority = 30;
    bool priorityGiven = false;  // PRIORITY was written (else the profile's default applies)
    bool watchdogGiven = false;  // WATCHDOG was written
    bool intervalGiven = false;  // INTERVAL was written
    PlcTime interval = 0;   // Cyclic: period in ns
    PlcTime watchdog = 0;   // 0 = no watchdog
    BoolRef trigger;        // Event / Status
    int64_t atCalendarNanos = 0;  // TimeEvent: first occurrence, ns since 1970-01-01 (UTC, no zone)
    TimeRepeat repeat = TimeRepeat::Once;
    // External: the physical input bit (ProcessImage::physicalInputs) and the edges.
    uint32_t inputByte = 0;
    int inputBit = 0;
    uint8_t edges = kEdgeRising;
    // INPUT_DELAY: the input module's filter time, added to the target's
    // detection delay (XGI: "1 ms + input module delay", decision 0118).
    PlcTime inputDelay = 0;
    bool inputDelayGiven = false;
    // The system-variable slot of the task on a target that has one
    // (M340: 0 MAST, 1 FAST, 2..5 AUX0..AUX3); -1: none.
    int systemSlot = -1;
    // The task strun made for programs configured without one (XGI: the scan program).
    bool isScanProgram = false;
};

// The code a task runs: all programs (and FB instances) bound to it, in order.
class TaskBody {
public:
    virtual ~TaskBody() = default;
    // Runs one activation. Returns false when the activation was aborted
    // (a tick returned true), true when it completed.
    virtual bool runActivation() = 0;
    // Where the activation is now (for the WATCHDOG diagnostic): the POU and
    // source line of the statement being executed. False when unknown.
    virtual bool currentPosition(std::string& pou, int& line) const { return false; }
    // The source file index and column of that statement (for the fault report).
    virtual bool currentFileAndColumn(int& file, int& col) const { return false; }
};

}  // namespace strun::rt
