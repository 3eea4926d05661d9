// The PLC's diagnostic buffer: a bounded ring of entries. When it is full the
// oldest entry gives way and is counted, so a fault raised every cycle costs
// constant memory however long the PLC runs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/machine.h"

namespace strun::rt {

struct DiagEntry {
    PlcTime time = 0;
    DiagCode code = DiagCode::TaskError;
    std::string task;  // the task running when it happened ("" when none)
    std::string pou;   // "" for scheduler events (OVERRUN, WATCHDOG)
    int line = 0;      // 0 when unknown
    std::string message;
    int file = -1;     // source index (RunOptions::sourceFiles), -1 when unknown
    int col = 0;       // 0 when unknown
};

class DiagBuffer {
public:
    explicit DiagBuffer(size_t capacity) : capacity_(capacity) {}

    void add(DiagEntry entry);
    // Oldest first.
    const std::vector<DiagEntry>& entries() const;
    // Entries given way to newer ones.
    uint64_t dropped() const { return dropped_; }
    size_t capacity() const { return capacity_; }

private:
    size_t capacity_;
    std::vector<DiagEntry> ring_;
    size_t oldest_ = 0;  // index in ring_ of the oldest entry once the ring is full
    uint64_t dropped_ = 0;
    mutable std::vector<DiagEntry> ordered_;  // entries() when the ring has wrapped
};

}  // namespace strun::rt
