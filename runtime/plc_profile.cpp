#include "runtime/plc_profile.h"

#include <cctype>

namespace strun::rt {

namespace {

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
    p.kinds[kindIndex(TaskKind::Startup)] = kOne0to31;
    p.kinds[kindIndex(TaskKind::ProgramError)] = kOne0to31;
    p.kinds[kindIndex(TaskKind::ExecTimeout)] = kOne0to31;
    p.minInterval = 1 * kMicrosecond;
    p.maxInterval = 24 * 3600 * kSecond;
    p.minWatchdog = 1 * kMicrosecond;
    p.maxWatchdog = 24 * 3600 * kSecond;
    return p;
}

// Seed 000: 25 tasks (9 cyclic, 1 continuous, 15 event-triggered: 1 startup,
// 6 + 6 time events, 1 program error, 1 execution timeout); cyclic priorities
// 5..25, event-triggered 5..29; periods 1 ms..60 s; watchdogs 10 ms..60 s,
// a cyclic task's never below its period; no watchdog on the timeout task.
constexpr PlcProfile makeBaosky() {
    PlcProfile p;
    p.id = "baosky-t3";
    p.description = "Baosky T3/T4";
    p.maxTasks = 25;
    p.kinds[kindIndex(TaskKind::Cyclic)] = {9, 5, 25, true};
    p.kinds[kindIndex(TaskKind::Freewheeling)] = {1, 0, 31, true};
    p.kinds[kindIndex(TaskKind::Event)] = {0, 0, 31, true};
    p.kinds[kindIndex(TaskKind::Status)] = {0, 0, 31, true};
    p.kinds[kindIndex(TaskKind::TimeEvent)] = {12, 5, 29, true};
    p.kinds[kindIndex(TaskKind::Startup)] = {1, 0, 31, true};
    p.kinds[kindIndex(TaskKind::ProgramError)] = {1, 5, 29, true};
    p.kinds[kindIndex(TaskKind::ExecTimeout)] = {1, 5, 29, false};
    p.minInterval = 1 * kMillisecond;
    p.maxInterval = 60'000 * kMillisecond;
    p.minWatchdog = 10 * kMillisecond;
    p.maxWatchdog = 60'000 * kMillisecond;
    p.watchdogAtLeastInterval = true;
    p.freewheelingBelowCyclic = true;
    return p;
}

constexpr PlcProfile kProfiles[] = {makeGeneric(), makeBaosky()};

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

}  // namespace

const PlcProfile& defaultProfile() { return kProfiles[0]; }

std::span<const PlcProfile> allProfiles() { return kProfiles; }

const PlcProfile* findProfile(std::string_view id) {
    for (const PlcProfile& profile : kProfiles)
        if (equalsIgnoreCase(profile.id, id)) return &profile;
    return nullptr;
}

}  // namespace strun::rt
