// The text forms of stimulus: `--set NAME=VALUE[@TIME]` and the CSV file
// of `--stimulus FILE` (`time,name,value` lines, a header and `#` comments
// allowed). Names and values are checked later against the compiled
// project (interpreter/project/stimulus_build.h).
#pragma once

#include <string>
#include <vector>

#include "cli/command_line.h"
#include "interpreter/project/stimulus_build.h"
#include "runtime/plc_profile.h"

namespace strun::cli {

// False with `error` when the text has no `=` or a bad @TIME.
bool parseSetOption(const std::string& text, project::StimulusEntry& entry, std::string& error);
// Appends the file's entries in file order; false with `error` = "FILE:LINE: ...".
bool readStimulusFile(const std::string& path, std::vector<project::StimulusEntry>& entries, std::string& error);
// The --set and --stimulus of a command line (run, test) as the scheduler's
// writes, every name and value checked against the project before anything
// runs; `profile` gives the target's input aliases (FI0). False with `error`.
bool buildCommandLineStimulus(const CommandLine& line, sema::ProgramModel& model, const rt::PlcProfile& profile,
                              rt::Stimulus& stimulus, std::string& error);

}  // namespace strun::cli
