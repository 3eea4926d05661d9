// What differs between PLC families, as one data table (--target NAME). The
// task rules (task_rules.h) check a configuration against a profile, the
// checker takes its defaults, names and system variables from it, and the
// scheduler consults it for what happens at a watchdog trip, how often it
// samples event/status BOOLs and the few behaviours that are genuinely
// different (the named policies below). A family's whole personality is its
// row in plc_profile.cpp; docs/targets.md lists every rule with its test.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "runtime/machine.h"
#include "runtime/task_spec.h"

namespace strun::rt {

constexpr PlcTime kMicrosecond = 1'000;
constexpr PlcTime kMillisecond = 1'000'000;
constexpr PlcTime kSecond = 1'000'000'000;

constexpr size_t kTaskKindCount = 9;  // the enumerators of TaskKind
constexpr size_t kindIndex(TaskKind kind) { return static_cast<size_t>(kind); }
constexpr uint32_t kindBit(TaskKind kind) { return 1u << kindIndex(kind); }

// What a profile allows for one task kind.
struct KindLimits {
    int maxCount = 0;        // 0: the kind is not available on this PLC
    int minPriority = 0;     // numerically; 0 is the highest priority
    int maxPriority = 31;
    bool watchdogAllowed = true;
    int defaultPriority = 30;     // when PRIORITY is omitted
    PlcTime defaultWatchdog = 0;  // when WATCHDOG is omitted (0: none)
};

// A limit on several kinds together (XGI: event + status tasks are the
// "internal interrupt" tasks, 8 of them).
struct GroupLimit {
    uint32_t kinds = 0;  // kindBit()s
    int maxCount = 0;
    std::string_view words;  // "internal interrupt" for messages
};

// A family whose tasks have fixed names and roles (Modicon M340: MAST, FAST,
// AUX0..AUX3), each with its own priority, period and watchdog ranges.
struct FixedTask {
    std::string_view name;
    int priority = 0;
    PlcTime minInterval = 0, maxInterval = 0, intervalStep = 1;
    PlcTime defaultInterval = 0;  // when INTERVAL is omitted; 0: freewheeling ("cyclic" mode)
    bool freewheelingAllowed = false;  // MAST only
    bool needsPeriodicMaster = false;  // AUXi: excluded when the master task is freewheeling
    PlcTime minWatchdog = 0, maxWatchdog = 0, defaultWatchdog = 0;
    int periodUnitMs = 1;  // unit of its period word (%SW0..%SW5): 1 ms or 10 ms
};

// A name of a physical input bit (M241 fast inputs FI0, FI1).
struct InputAlias {
    std::string_view name;
    uint32_t byte = 0;
    int bit = 0;
};

enum class WatchdogReaction {
    Stop,  // the PLC goes to STOP (CODESYS family, Baosky, XGI)
    Halt,  // the application is declared in error: HALT (Modicon)
};

// Named policies: the behaviours that differ between families.
enum class FirstCyclePolicy {
    AllTasks,    // every task is released at RUN (after a startup task)
    MasterOnly,  // M340: only the first fixed task (MAST) runs its first cycle; the others start at its end
};
enum class OverrunPolicy {
    Drop,            // a release while the task is busy is dropped (OVERRUN)
    RestartAtEnd,    // M241: the task restarts right after writing its outputs (OVERRUN counted, not dropped)
};
enum class TriggerSampling {
    TickAndTaskEnd,  // event/status BOOLs sampled at every scheduler tick and task end
    EndOfScan,       // XGI: sampled when the scan program finishes a scan
};
enum class SystemVariables {
    None,
    Modicon,  // %S / %SW system bits and words (runtime/system_area.h)
};

struct PlcProfile {
    std::string_view id;           // --target value, e.g. "generic"
    std::string_view description;  // for messages: "generic (CODESYS-like)"
    int maxTasks = 100;            // all kinds together
    std::array<KindLimits, kTaskKindCount> kinds{};
    std::span<const GroupLimit> groupLimits;
    int maxOnceTimeEvents = 0;     // Baosky: 6 once + 6 repeat (0: only the kind limit)
    int maxRepeatTimeEvents = 0;
    int maxProgramsPerTask = 0;    // 0: no limit
    bool startupPriorityFixed = false;  // Baosky: PRIORITY on the startup task is an error
    // Baosky: the startup task "can only be interrupted by user program error
    // tasks and execution timeout tasks": its watchdog releases the timeout
    // task, which interrupts it, and it goes on (not aborted; decision 0297).
    bool startupInterruptedOnWatchdog = false;
    std::span<const FixedTask> fixedTasks;  // non-empty: only these task names
    PlcTime minInterval = 0;  // cyclic INTERVAL range
    PlcTime maxInterval = 0;
    PlcTime intervalStep = 1;  // INTERVAL must be a multiple of this (M241: 4 ms)
    // `INTERVAL := TRUE`: a cyclic task with the cycle time the IDE gives a new
    // one (Baosky: 20 ms; decision 0297); 0: the target has none to give.
    PlcTime defaultCyclicInterval = 0;
    PlcTime minWatchdog = 0;   // WATCHDOG range when one is given
    PlcTime maxWatchdog = 0;
    bool watchdogAtLeastInterval = false;  // Baosky: a cyclic task's watchdog >= its period
    bool freewheelingBelowCyclic = false;  // Baosky: the continuous task has a lower priority than every cyclic one
    PlcTime defaultMainWatchdog = 200 * kMillisecond;  // the default MainTask
    int defaultMainPriority = 30;
    // Programs configured without a task: the task they run in, below every other one.
    std::string_view unassignedTaskName = "DefaultTask";
    int unassignedTaskPriority = 31;
    WatchdogReaction watchdogReaction = WatchdogReaction::Stop;
    // How often the scheduler samples the BOOLs of event and status tasks
    // besides at every task end (CODESYS: the scheduler tick, 1 ms).
    PlcTime schedulerTick = 1 * kMillisecond;
    FirstCyclePolicy firstCycle = FirstCyclePolicy::AllTasks;
    OverrunPolicy overrun = OverrunPolicy::Drop;
    TriggerSampling triggerSampling = TriggerSampling::TickAndTaskEnd;
    PlcTime freewheelingGap = 0;  // M241: system processing between two freewheeling scans
    // EXTERNAL tasks: released at the input change + detectionDelay, never
    // sooner than minTriggerSpacing after the previous release.
    uint8_t externalEdges = kEdgeBoth;  // the EDGE values allowed
    PlcTime externalDetectionDelay = 0;
    PlcTime externalMinSpacing = 0;
    // M241: an EXTERNAL task that has switched a fast output (bits of
    // %QB0 in fastOutputMask) keeps this longer minimum between triggers.
    uint8_t fastOutputMask = 0;
    PlcTime externalMinSpacingFastOutputs = 0;
    PlcTime maxExternalInputDelay = kNever;  // INPUT_DELAY range 0..this (XGI: 2 ms, the seed's 3 ms in all)
    std::span<const InputAlias> inputAliases;
    SystemVariables systemVariables = SystemVariables::None;
    bool taskCycleFunctions = false;  // M241: GetCurrentTaskCycle / SetCurrentTaskCycle
    // M241 system watchdog: tasks of priority 0..systemWatchdogMaxPriority
    // holding the processor without a pause for longer than systemWatchdogBusy
    // (0: no such watchdog) stop the controller with SYSTEM_WATCHDOG.
    PlcTime systemWatchdogBusy = 0;
    int systemWatchdogMaxPriority = 0;

    const KindLimits& limits(TaskKind kind) const { return kinds[kindIndex(kind)]; }
    const FixedTask* fixedTask(std::string_view name) const;  // case-insensitive; nullptr: not one
    int fixedTaskIndex(std::string_view name) const;          // -1: not one
};

// The generic CODESYS-like profile used when none is chosen.
const PlcProfile& defaultProfile();
// Every profile of the table; the first is the default.
std::span<const PlcProfile> allProfiles();
// Case-insensitive lookup by id; nullptr when unknown.
const PlcProfile* findProfile(std::string_view id);
// "generic, baosky, ax3, m340, m241, xgi" (for the usage message).
std::string profileIds();
// The profile that has system variables of this kind, for "only on ..." messages.
const PlcProfile* profileWithSystemVariables();
const PlcProfile* profileWithTaskCycleFunctions();

// A target's name for a physical input bit, case-insensitive.
std::optional<InputAlias> findInputAlias(const PlcProfile& profile, std::string_view name);

}  // namespace strun::rt
