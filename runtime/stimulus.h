// Writes from outside the program at given PLC times (--set, --stimulus):
// a time-ordered list the scheduler applies. The runtime sees only storage
// (a byte pointer, a bit, the bytes to write); interpreter/project resolves
// names and literals into these (stimulus_build.h).
//
// Timing (docs/decisions/0080-stimulus-timing.md):
//  - a Variable write is applied when the first task activation at or after
//    its time starts, before that activation's input phase: never in the
//    middle of a running cycle (Scheduler::runActivation calls
//    applyVariablesDue).
//  - a PhysicalInput write changes ProcessImage::physicalInputs at its time
//    exactly: nextInputAt() is one of the moments the scheduler wakes up for
//    (like a release), and a task sees the new value at its next input phase.
//    After a write that changed the image, the listener (if any) is told, so
//    a task triggered by an input (an EXTERNAL task) can be released at that
//    time plus the target's detection delay.
// Writes due at the same moment apply in the order they were added.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "runtime/machine.h"

namespace strun::rt {

struct StimulusWrite {
    enum class Kind : uint8_t { Variable, PhysicalInput };
    PlcTime at = 0;
    Kind kind = Kind::Variable;
    uint8_t* dest = nullptr;     // first byte written
    int bit = -1;                // >= 0: only this bit of *dest, from bytes[0] != 0
    std::vector<uint8_t> bytes;  // the value's storage image (native byte order)
    size_t inputOffset = 0;      // PhysicalInput: byte offset of dest in physicalInputs
    std::string text;            // for --trace: "Main.start := TRUE"
};

class Stimulus {
public:
    // Called after a PhysicalInput write that changed the image:
    // (the write, the PLC time it took effect).
    using InputListener = std::function<void(const StimulusWrite&, PlcTime)>;

    void add(StimulusWrite write);  // any order; sorted stably by time on first use
    bool empty() const { return writes_.empty(); }
    size_t size() const { return writes_.size(); }

    // The time of the next pending PhysicalInput write, kNever when none.
    PlcTime nextInputAt();
    // Applies every pending write of `kind` due at or before `now`, in order;
    // one trace line each ("T#2s set Main.start := TRUE") when `trace`.
    void applyVariablesDue(PlcTime now, std::ostream* trace);
    void applyInputsDue(PlcTime now, std::ostream* trace);
    void setInputListener(InputListener listener) { listener_ = std::move(listener); }

private:
    void sortOnce();
    void applyDue(StimulusWrite::Kind kind, std::vector<size_t>& queue, size_t& next, PlcTime now, std::ostream* trace);
    std::vector<StimulusWrite> writes_;
    std::vector<size_t> variables_, inputs_;  // indices into writes_, time order
    size_t nextVariable_ = 0, nextInput_ = 0;
    bool sorted_ = false;
    InputListener listener_;
    std::string line_;
};

}  // namespace strun::rt
