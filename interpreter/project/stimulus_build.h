// --set / --stimulus entries (name and literal as text) resolved against the
// checked model into the runtime's Stimulus (byte writes at PLC times).
#pragma once

#include <string>
#include <vector>

#include "interpreter/sema/program_model.h"
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
bool buildStimulus(sema::ProgramModel& model, const std::vector<StimulusEntry>& entries, rt::Stimulus& out, std::string& error);

}  // namespace strun::project
