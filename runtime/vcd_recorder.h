// --vcd: a Value Change Dump (IEEE 1364) of a run, PLC time in ns. One 1-bit
// signal per task, 1 while it executes (0 while preempted or idle), and the
// recorded variables, each sampled at the end of every activation of the
// task that owns it (globals: of any task) and written only when it changed.
// The file is complete after runEnded(), whatever ended the run.
//
// The runtime sees storage only: interpreter/project/vcd_signals.h turns
// the checked variables into VcdSignals (decision 0081 for the encodings).
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "runtime/run_observer.h"

namespace strun::rt {

struct VcdSignal {
    // EnumName / Text (--vcd-text): string signals GTKWave shows as text: an
    // enumeration's value name, a STRING's characters.
    enum class Kind : uint8_t { Bit, Vector, Real32, Real64, EnumName, Text };
    std::shared_ptr<const std::vector<std::string>> scopes;  // enclosing scopes, outermost first ("Main", "valve"); shared by the elements of an array
    std::string name;                 // the leaf ("cmd", "levels(3)")
    Kind kind = Kind::Vector;
    const uint8_t* addr = nullptr;
    int bit = -1;            // Bit: this bit of *addr; -1: *addr != 0
    uint32_t size = 1;       // bytes read (Vector: 1, 2, 4 or 8)
    int width = 8;           // Vector: bits written
    bool isSigned = false;   // Vector: sign-extend before scaling
    int64_t scale = 1;       // Vector: written value = stored value * scale (TIME ms -> ns)
    std::vector<std::pair<int64_t, std::string>> names;  // EnumName: value -> name (size, isSigned as Vector)
    int task = -1;           // owning task index; -1: sampled at the end of every task's activations; -2: never (no task runs it);
                             // kAfterOutputPhase: a physical output, sampled when an output phase wrote them
    static constexpr int kAfterOutputPhase = -3;
};

class VcdRecorder final : public RunObserver {
public:
    // Writes the header and the initial values ($dumpvars at #0) to `out`
    // (owned by the caller, which closes it after runEnded()).
    // `taskWaveforms[i]` false: task i's running/idle signal is left out (its
    // activations still sample the variables); empty: every task has one.
    VcdRecorder(std::FILE* out, const std::vector<std::string>& taskNames, std::vector<VcdSignal> signals, const std::string& version,
                const std::vector<bool>& taskWaveforms = {});

    void taskRunning(size_t task, bool running, PlcTime now) override;
    void activationEnded(size_t task, PlcTime now) override;
    void outputsWritten(PlcTime now) override;
    void runEnded(PlcTime end) override;

    size_t signalCount() const { return signals_.size(); }

private:
    uint64_t read(const VcdSignal& s) const;  // the value's bits (Vector: scaled)
    void writeValue(const VcdSignal& s, uint64_t value, const std::string& id);
    void stampTime(PlcTime now);
    void sample(const std::vector<size_t>& which, PlcTime now);
    void flushIfLarge();

    std::FILE* out_;
    std::vector<VcdSignal> signals_;
    std::vector<std::string> signalIds_, taskIds_;  // a task without a waveform has an empty id
    std::vector<uint64_t> last_;
    std::vector<std::vector<size_t>> byTask_;  // signals each task samples (globals included)
    std::vector<size_t> physicalOutputs_;      // signals sampled after an output phase
    std::vector<uint8_t> taskState_;
    PlcTime stamped_ = -1;
    std::string buffer_;
};

}  // namespace strun::rt
