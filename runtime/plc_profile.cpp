#include "runtime/plc_profile.h"

#include <string>

#include "stdlib/number_scan.h"

namespace strun::rt {

namespace {

constexpr PlcTime kDay = 24 * 3600 * kSecond;

constexpr KindLimits kOne0to31{1, 0, 31, true};
constexpr KindLimits kMany0to31{100, 0, 31, true};

constexpr PlcProfile makeGeneric() {
    PlcProfile p;
    p.id = "generic";
    p.description = "generic (CODESYS-like)";
    p.maxTasks = 100;
    p.kinds[kindIndex(TaskKind::Cyclic)] = kMany0to31;
    p.kinds[kindIndex(TaskKind::Freewheeling)] = kMany0to31;
    p.kinds[kindIndex(TaskKind::Event)] = kMany0to31;
    p.kinds[kindIndex(TaskKind::Status)] = kMany0to31;
    p.kinds[kindIndex(TaskKind::TimeEvent)] = kMany0to31;
    p.kinds[kindIndex(TaskKind::External)] = kMany0to31;
    p.kinds[kindIndex(TaskKind::Startup)] = kOne0to31;
    p.kinds[kindIndex(TaskKind::ProgramError)] = kOne0to31;
    p.kinds[kindIndex(TaskKind::ExecTimeout)] = kOne0to31;
    p.minInterval = 1 * kMicrosecond;
    p.maxInterval = kDay;
    p.minWatchdog = 1 * kMicrosecond;
    p.maxWatchdog = kDay;
    return p;
}

// Seed 000: 25 tasks (9 cyclic, 1 continuous, 15 event-triggered: 1 startup,
// 6 once + 6 repeat time events, 1 program error, 1 execution timeout); 99
// programs per task; cyclic priorities 5..25 (11 when omitted), event-triggered
// 5..29; the continuous task 30 with a 200 ms watchdog, below every cyclic
// one; periods 1 ms..60 s; watchdogs 10 ms..60 s, a cyclic task's never below
// its period; no watchdog on the timeout task; the startup priority is fixed.
constexpr PlcProfile makeBaosky() {
    PlcProfile p;
    p.id = "baosky";
    p.description = "Baosky T3/T4";
    p.maxTasks = 25;
    p.kinds[kindIndex(TaskKind::Cyclic)] = {9, 5, 25, true, 11, 0};
    p.kinds[kindIndex(TaskKind::Freewheeling)] = {1, 0, 31, true, 30, 200 * kMillisecond};
    p.kinds[kindIndex(TaskKind::TimeEvent)] = {12, 5, 29, true, 29, 0};
    p.kinds[kindIndex(TaskKind::Startup)] = {1, 0, 31, true, 0, 0};
    p.kinds[kindIndex(TaskKind::ProgramError)] = {1, 5, 29, true, 29, 0};
    p.kinds[kindIndex(TaskKind::ExecTimeout)] = {1, 5, 29, false, 29, 0};
    p.maxOnceTimeEvents = 6;
    p.maxRepeatTimeEvents = 6;
    p.maxProgramsPerTask = 99;
    p.startupPriorityFixed = true;
    p.startupInterruptedOnWatchdog = true;
    p.minInterval = 1 * kMillisecond;
    p.maxInterval = 60'000 * kMillisecond;
    p.defaultCyclicInterval = 20 * kMillisecond;  // "the default cycle time of the first established periodic cyclic task is 20ms"
    p.minWatchdog = 10 * kMillisecond;
    p.maxWatchdog = 60'000 * kMillisecond;
    p.watchdogAtLeastInterval = true;
    p.freewheelingBelowCyclic = true;
    return p;
}

// Seed 001: priorities 0..31; cyclic, event (rising edge), freewheeling,
// status (while TRUE) and external-event tasks; nothing else.
constexpr PlcProfile makeAx3() {
    PlcProfile p = makeGeneric();
    p.id = "ax3";
    p.description = "AX-3";
    p.kinds[kindIndex(TaskKind::TimeEvent)] = {};
    p.kinds[kindIndex(TaskKind::Startup)] = {};
    p.kinds[kindIndex(TaskKind::ProgramError)] = {};
    p.kinds[kindIndex(TaskKind::ExecTimeout)] = {};
    return p;
}

// Seed 002: the six tasks of a Modicon M340/Premium with their fixed
// priorities (FAST above MAST above AUX0..AUX3), periods and watchdogs.
constexpr FixedTask kM340Tasks[] = {
    {"MAST", 1, 1 * kMillisecond, 255 * kMillisecond, kMillisecond, 0, true, false, 10 * kMillisecond,
     1500 * kMillisecond, 250 * kMillisecond, 1},
    {"FAST", 0, 1 * kMillisecond, 255 * kMillisecond, kMillisecond, 5 * kMillisecond, false, false,
     10 * kMillisecond, 500 * kMillisecond, 100 * kMillisecond, 1},
    {"AUX0", 2, 10 * kMillisecond, 2550 * kMillisecond, 10 * kMillisecond, 100 * kMillisecond, false, true,
     100 * kMillisecond, 5000 * kMillisecond, 2000 * kMillisecond, 10},
    {"AUX1", 3, 10 * kMillisecond, 2550 * kMillisecond, 10 * kMillisecond, 200 * kMillisecond, false, true,
     100 * kMillisecond, 5000 * kMillisecond, 2000 * kMillisecond, 10},
    {"AUX2", 4, 10 * kMillisecond, 2550 * kMillisecond, 10 * kMillisecond, 300 * kMillisecond, false, true,
     100 * kMillisecond, 5000 * kMillisecond, 2000 * kMillisecond, 10},
    {"AUX3", 5, 10 * kMillisecond, 2550 * kMillisecond, 10 * kMillisecond, 400 * kMillisecond, false, true,
     100 * kMillisecond, 5000 * kMillisecond, 2000 * kMillisecond, 10},
};

constexpr PlcProfile makeM340() {
    PlcProfile p;
    p.id = "m340";
    p.description = "Modicon M340";
    p.maxTasks = 6;
    p.kinds[kindIndex(TaskKind::Cyclic)] = {6, 0, 5, true};
    p.kinds[kindIndex(TaskKind::Freewheeling)] = {1, 0, 5, true};
    p.fixedTasks = kM340Tasks;
    p.minInterval = 1 * kMillisecond;
    p.maxInterval = 2550 * kMillisecond;
    p.minWatchdog = 10 * kMillisecond;
    p.maxWatchdog = 5000 * kMillisecond;
    p.watchdogReaction = WatchdogReaction::Halt;
    p.firstCycle = FirstCyclePolicy::MasterOnly;
    p.systemVariables = SystemVariables::Modicon;
    return p;
}

// Seed 003: CODESYS-based; cyclic (>= 4 ms, a multiple of 4 ms; a too short
// period restarts the task right after its outputs), freewheeling (a short
// system-processing gap between scans), event (rising edge) and external
// event tasks on the fast inputs FI0/FI1 and the HSC thresholds (1.5 ms
// minimum between triggers, 15 ms for a task that switches the fast outputs
// FQ0/FQ1). HSC0_THn is the bit "HSC0's value >= threshold n", driven by the
// stimulus: it rises when the counter passes the threshold counting up and
// falls when it passes it counting down (decision 0119).
constexpr InputAlias kM241Inputs[] = {{"FI0", 0, 0}, {"FI1", 0, 1}, {"HSC0_TH0", 10, 0}, {"HSC0_TH1", 10, 1}};

constexpr PlcProfile makeM241() {
    PlcProfile p = makeGeneric();
    p.id = "m241";
    p.description = "Modicon M241";
    p.kinds[kindIndex(TaskKind::Status)] = {};
    p.kinds[kindIndex(TaskKind::TimeEvent)] = {};
    p.kinds[kindIndex(TaskKind::Startup)] = {};
    p.kinds[kindIndex(TaskKind::ProgramError)] = {};
    p.kinds[kindIndex(TaskKind::ExecTimeout)] = {};
    p.minInterval = 4 * kMillisecond;
    p.intervalStep = 4 * kMillisecond;
    p.overrun = OverrunPolicy::RestartAtEnd;
    p.freewheelingGap = 1 * kMillisecond;
    p.externalMinSpacing = 1500 * kMicrosecond;
    p.fastOutputMask = 0x03;  // FQ0 %QX0.0, FQ1 %QX0.1
    p.externalMinSpacingFastOutputs = 15 * kMillisecond;
    p.inputAliases = kM241Inputs;
    p.taskCycleFunctions = true;
    // "If the total execution time of the tasks with priorities between 0 and
    // 24 reaches 100% of processor resources for more than 1 second, an
    // application error is detected" (Schneider's M241 programming guide,
    // the system watchdog seed 003 names; decision 0120).
    p.systemWatchdogBusy = 1000 * kMillisecond;
    p.systemWatchdogMaxPriority = 24;
    return p;
}

// Seed 004: 8 time-driven (10 ms units), 8 external-interrupt (rising edge,
// 1 ms detection) and 8 internal-interrupt tasks (rising edge or ON state of a
// BOOL, seen when the scan program ends); priorities 0..7; programs without a
// task form the scan program, below every task.
constexpr GroupLimit kXgiGroups[] = {{kindBit(TaskKind::Event) | kindBit(TaskKind::Status), 8, "internal interrupt"}};

constexpr PlcProfile makeXgi() {
    PlcProfile p;
    p.id = "xgi";
    p.description = "LS XGI";
    p.maxTasks = 8;  // "Up to 8 task programs are available": all kinds together (decision 0243)
    p.kinds[kindIndex(TaskKind::Cyclic)] = {8, 0, 7, true, 7, 0};
    p.kinds[kindIndex(TaskKind::External)] = {8, 0, 7, true, 7, 0};
    p.kinds[kindIndex(TaskKind::Event)] = {8, 0, 7, true, 7, 0};
    p.kinds[kindIndex(TaskKind::Status)] = {8, 0, 7, true, 7, 0};
    p.groupLimits = kXgiGroups;
    p.minInterval = 10 * kMillisecond;
    p.maxInterval = 4'294'967'290 * kMillisecond;
    p.intervalStep = 10 * kMillisecond;
    p.minWatchdog = 1 * kMillisecond;
    p.maxWatchdog = kDay;
    p.unassignedTaskName = "Scan";
    p.unassignedTaskPriority = 8;
    p.triggerSampling = TriggerSampling::EndOfScan;
    p.externalEdges = kEdgeRising;
    p.externalDetectionDelay = 1 * kMillisecond;
    p.maxExternalInputDelay = 2 * kMillisecond;
    return p;
}

constexpr PlcProfile kProfiles[] = {makeGeneric(), makeBaosky(), makeAx3(), makeM340(), makeM241(), makeXgi()};

}  // namespace

const FixedTask* PlcProfile::fixedTask(std::string_view name) const {
    int index = fixedTaskIndex(name);
    return index < 0 ? nullptr : &fixedTasks[size_t(index)];
}

int PlcProfile::fixedTaskIndex(std::string_view name) const {
    for (size_t i = 0; i < fixedTasks.size(); ++i)
        if (stdlib::equalsIgnoreCase(fixedTasks[i].name, name)) return int(i);
    return -1;
}

const PlcProfile& defaultProfile() { return kProfiles[0]; }

std::span<const PlcProfile> allProfiles() { return kProfiles; }

const PlcProfile* findProfile(std::string_view id) {
    for (const PlcProfile& profile : kProfiles)
        if (stdlib::equalsIgnoreCase(profile.id, id)) return &profile;
    return nullptr;
}

std::string profileIds() {
    std::string ids;
    for (const PlcProfile& profile : kProfiles) {
        if (!ids.empty()) ids += ", ";
        ids += profile.id;
    }
    return ids;
}

const PlcProfile* profileWithSystemVariables() {
    for (const PlcProfile& profile : kProfiles)
        if (profile.systemVariables != SystemVariables::None) return &profile;
    return nullptr;
}

const PlcProfile* profileWithTaskCycleFunctions() {
    for (const PlcProfile& profile : kProfiles)
        if (profile.taskCycleFunctions) return &profile;
    return nullptr;
}

std::optional<InputAlias> findInputAlias(const PlcProfile& profile, std::string_view name) {
    for (const InputAlias& alias : profile.inputAliases)
        if (stdlib::equalsIgnoreCase(alias.name, name)) return alias;
    return std::nullopt;
}

}  // namespace strun::rt
