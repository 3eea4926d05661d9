// The limits that differ between PLC families, as one data table. The task
// rules (task_rules.h) check a configuration against a profile, the scheduler
// takes from it what happens at a watchdog trip and how often it samples
// event/status BOOLs. Adding a PLC family means adding a row to the table in
// plc_profile.cpp, nothing else.
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "runtime/machine.h"
#include "runtime/task_spec.h"

namespace strun::rt {

constexpr PlcTime kMicrosecond = 1'000;
constexpr PlcTime kMillisecond = 1'000'000;
constexpr PlcTime kSecond = 1'000'000'000;

constexpr size_t kTaskKindCount = 8;  // the enumerators of TaskKind
constexpr size_t kindIndex(TaskKind kind) { return static_cast<size_t>(kind); }

// What a profile allows for one task kind.
struct KindLimits {
    int maxCount = 0;        // 0: the kind is not available on this PLC
    int minPriority = 0;     // numerically; 0 is the highest priority
    int maxPriority = 31;
    bool watchdogAllowed = true;
};

enum class WatchdogReaction {
    Stop,  // the PLC goes to STOP (CODESYS family, Baosky)
    Halt,  // the application is declared in error: HALT (Modicon)
};

struct PlcProfile {
    std::string_view id;           // --profile value, e.g. "generic"
    std::string_view description;  // for messages: "generic (CODESYS-like)"
    int maxTasks = 100;            // all kinds together
    std::array<KindLimits, kTaskKindCount> kinds{};
    PlcTime minInterval = 0;  // cyclic INTERVAL range
    PlcTime maxInterval = 0;
    PlcTime intervalStep = 1;  // INTERVAL must be a multiple of this (M241: 4 ms)
    PlcTime minWatchdog = 0;   // WATCHDOG range when one is given
    PlcTime maxWatchdog = 0;
    bool watchdogAtLeastInterval = false;  // Baosky: a cyclic task's watchdog >= its period
    bool freewheelingBelowCyclic = false;  // Baosky: the continuous task has a lower priority than every cyclic one
    PlcTime defaultMainWatchdog = 200 * kMillisecond;  // the default MainTask
    int defaultMainPriority = 30;
    WatchdogReaction watchdogReaction = WatchdogReaction::Stop;
    // How often the scheduler samples the BOOLs of event and status tasks
    // besides at every task end (CODESYS: the scheduler tick, 1 ms).
    PlcTime schedulerTick = 1 * kMillisecond;

    const KindLimits& limits(TaskKind kind) const { return kinds[kindIndex(kind)]; }
};

// The generic CODESYS-like profile used when none is chosen.
const PlcProfile& defaultProfile();
// Every profile of the table; the first is the default.
std::span<const PlcProfile> allProfiles();
// Case-insensitive lookup by id; nullptr when unknown.
const PlcProfile* findProfile(std::string_view id);

}  // namespace strun::rt
