#include "runtime/system_area.h"

#include <algorithm>

namespace strun::rt {

namespace {

constexpr int kOverrunBit = 19;
constexpr int kCycleTimeWords = 30;  // %SW30 + 3 * slot: current, max, min
constexpr int kMasterWatchdogWord = 11;

uint16_t clampMs(PlcTime nanos) { return uint16_t(std::clamp<PlcTime>(nanos / kMillisecond, 0, 0xFFFF)); }

}  // namespace

std::vector<int> SystemArea::wordsKeptOverWarmStart() {
    std::vector<int> words;
    for (int slot = 0; slot < kSlots; ++slot) {
        words.push_back(kCycleTimeWords + 3 * slot + 1);
        words.push_back(kCycleTimeWords + 3 * slot + 2);
    }
    return words;
}

void SystemArea::start(const std::array<PlcTime, kSlots>& periods, PlcTime masterWatchdog) {
    for (int slot = 0; slot < kSlots; ++slot) {
        // A warm start left a measured minimum (or maximum) in the words: go on from it.
        const int base = kCycleTimeWords + 3 * slot;
        measured_[size_t(slot)] = word(base + 1) != 0 || word(base + 2) != 0;
        minMs_[size_t(slot)] = word(base + 2);
        int unitMs = size_t(slot) < profile_.fixedTasks.size() ? profile_.fixedTasks[size_t(slot)].periodUnitMs : 1;
        setWord(slot, clampMs(periods[size_t(slot)] / unitMs));
        setBit(30 + slot, true);
    }
    masterWatchdogMs_ = clampMs(masterWatchdog);
    setWord(kMasterWatchdogWord, masterWatchdogMs_);
}

void SystemArea::enter(int slot) {
    running_ = slot;
    if (slot < 0 || slot >= kSlots) return;
    setBit(kOverrunBit, overrun_[size_t(slot)]);
    setWord(kMasterWatchdogWord, masterWatchdogMs_);  // not modifiable by the program
}

void SystemArea::leave(int slot) {
    running_ = -1;
    if (slot < 0 || slot >= kSlots) return;
    overrun_[size_t(slot)] = bit(kOverrunBit);  // the program may have reset it
}

void SystemArea::setOverrun(int slot) {
    if (slot < 0 || slot >= kSlots) return;
    overrun_[size_t(slot)] = true;
    if (slot == running_) setBit(kOverrunBit, true);  // the task sees it at once; leave() keeps it
}

void SystemArea::recordExecution(int slot, PlcTime exec) {
    if (slot < 0 || slot >= kSlots) return;
    uint16_t ms = clampMs(exec);
    int base = kCycleTimeWords + 3 * slot;
    setWord(base, ms);
    setWord(base + 1, std::max(word(base + 1), ms));
    minMs_[size_t(slot)] = measured_[size_t(slot)] ? std::min(minMs_[size_t(slot)], ms) : ms;
    measured_[size_t(slot)] = true;
    setWord(base + 2, minMs_[size_t(slot)]);
}

PlcTime SystemArea::requestedPeriod(int slot, PlcTime current) const {
    if (slot < 0 || size_t(slot) >= profile_.fixedTasks.size()) return current;
    const FixedTask& fixed = profile_.fixedTasks[size_t(slot)];
    PlcTime period = PlcTime(word(slot)) * fixed.periodUnitMs * kMillisecond;
    if (period < fixed.minInterval || period > fixed.maxInterval || period % fixed.intervalStep != 0) return current;
    return period;
}

PlcTime SystemArea::requestedMasterPeriod(PlcTime current) const {
    if (profile_.fixedTasks.empty() || !profile_.fixedTasks[0].freewheelingAllowed) return current;
    if (word(0) == 0) return 0;
    return requestedPeriod(0, current);
}

void SystemArea::setBit(int n, bool value) {
    uint8_t& byte = image_.systemBits[size_t(n) / 8];
    byte = uint8_t(value ? byte | (1u << (n % 8)) : byte & ~(1u << (n % 8)));
}

uint16_t SystemArea::word(int n) const {
    return uint16_t(image_.systemWords[size_t(n) * 2] | (image_.systemWords[size_t(n) * 2 + 1] << 8));
}

void SystemArea::setWord(int n, uint16_t value) {
    image_.systemWords[size_t(n) * 2] = uint8_t(value & 0xFF);
    image_.systemWords[size_t(n) * 2 + 1] = uint8_t(value >> 8);
}

}  // namespace strun::rt
