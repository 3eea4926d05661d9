// The Modicon system bits and words (seed 002) the scheduler maintains under
// --target m340. A task's "slot" is its place among the fixed tasks (0 MAST,
// 1 FAST, 2..5 AUX0..AUX3). What each address means and when it is read or
// written is pinned in docs/targets.md (M340 table):
//   %S11          watchdog overflow (set before the HALT)
//   %S19          period overrun, one bit per task: the running task sees its own
//   %S30..%S35    task active; read at the end of every MAST cycle
//   %SW0..%SW5    task periods (MAST, FAST in ms; AUXi in 10 ms); writable
//   %SW8, %SW9    bit i: inhibit the input reading / output writing of slot i
//   %SW11         MAST watchdog in ms (read-only: rewritten at every task start)
//   %SW30..%SW47  current, max, min execution time per slot in ms
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "runtime/machine.h"
#include "runtime/plc_profile.h"

namespace strun::rt {

class SystemArea {
public:
    static constexpr int kSlots = 6;

    SystemArea(ProcessImage& image, const PlcProfile& profile) : image_(image), profile_(profile) {}

    // The words a warm start keeps: each task's maximum and minimum cycle
    // time (seed 002: "taken from the times measured since the last cold restart").
    static std::vector<int> wordsKeptOverWarmStart();
    // At RUN: the period words from the configured periods, %SW11, every task
    // active; maximum and minimum cycle times go on from what the words hold
    // (zero after a cold start, the kept values after a warm one).
    void start(const std::array<PlcTime, kSlots>& periods, PlcTime masterWatchdog);
    // The running task changes (start/resume: enter; end/preemption: leave):
    // %S19 is the running task's own bit.
    void enter(int slot);
    void leave(int slot);
    void setOverrun(int slot);
    void setWatchdogOverflow() { setBit(11, true); }
    // An activation of `slot` ended after `exec` (preemptions included).
    void recordExecution(int slot, PlcTime exec);
    bool taskActive(int slot) const { return bit(30 + slot); }
    bool inputsInhibited(int slot) const { return (word(8) >> slot) & 1; }
    bool outputsInhibited(int slot) const { return (word(9) >> slot) & 1; }
    // The period %SW<slot> asks for, in ns; `current` when the word holds a
    // value outside the task's range (such a write is not taken into account).
    PlcTime requestedPeriod(int slot, PlcTime current) const;
    // The mode %SW0 asks of the master task: 0 cyclic (freewheeling), else its
    // period in ns; `current` when the word holds a value outside 0..255 ms.
    PlcTime requestedMasterPeriod(PlcTime current) const;

private:
    bool bit(int n) const { return (image_.systemBits[size_t(n) / 8] >> (n % 8)) & 1; }
    void setBit(int n, bool value);
    uint16_t word(int n) const;
    void setWord(int n, uint16_t value);

    ProcessImage& image_;
    const PlcProfile& profile_;
    std::array<bool, kSlots> overrun_{};  // each task's own %S19
    std::array<uint16_t, kSlots> minMs_{};
    std::array<bool, kSlots> measured_{};
    uint16_t masterWatchdogMs_ = 0;
    int running_ = -1;  // the slot whose %S19 is in the bit now
};

}  // namespace strun::rt
