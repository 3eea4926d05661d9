// --set / --stimulus entries (name and literal as text) resolved against the
// checked model into the runtime's Stimulus (byte writes at PLC times).
#pragma once

#include <string>
#include <vector>

#include "interpreter/sema/program_model.h"
#include "runtime/plc_profile.h"
#include "runtime/stimulus.h"

namespace strun::project {

struct StimulusEntry {
    rt::PlcTime at = 0;
    std::string name;    // a variable path (variable_path.h) or a direct input address %IX0.3, %IB2, %IW4, %ID1, %IL0
    std::string value;   // an ST literal of the variable's type
    std::string origin;  // for messages: "--set Main.x=5" or "levels.csv:7"
};

// Appends one write per entry, in the given order. False with a one-line
// `error` ("ORIGIN: ...") for an unknown name, a CONSTANT, or a value that
// does not parse or fit.
//
// A variable located in the input image (AT %I...) is set as its physical
// input: the program's copy is overwritten by every input phase, so a
// variable write there would be lost (decision 0080).
// A target's input alias (`FI0` under --target m241, runtime/plc_profile.h)
// stands for its physical input bit.
bool buildStimulus(sema::ProgramModel& model, const std::vector<StimulusEntry>& entries, rt::Stimulus& out, std::string& error,
                   const rt::PlcProfile& profile = rt::defaultProfile());

// Who writes: --set and --stimulus may set inputs only; the live interfaces
// (live writes and forces, docs/live.md) may also set outputs and memory
// (%QX0.1, %QW3, %MW7, %MD2 and variables located there).
enum class WriteScope { Inputs, Anywhere };

// What resolveWrite() found besides the write itself.
struct ResolvedWrite {
    rt::StimulusWrite write;          // dest/bit/bytes/kind/inputOffset/text as buildStimulus makes them
    const sema::Type* type = nullptr;  // the value's type (BOOL for a bit address)
    std::string name;                  // the variable's path as declared, or the address in upper case
};

// One NAME=VALUE (entry.at is copied), the resolver buildStimulus uses for
// each entry. False with `error` ("ORIGIN: why"; just "why" when
// entry.origin is empty) for an unknown name, a CONSTANT, or a bad value.
bool resolveWrite(sema::ProgramModel& model, const StimulusEntry& entry, ResolvedWrite& out, std::string& error,
                  const rt::PlcProfile& profile = rt::defaultProfile(), WriteScope scope = WriteScope::Inputs);

}  // namespace strun::project
