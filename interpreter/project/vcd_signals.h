// The variables --vcd records, as the runtime's VcdSignals: every elementary
// variable of every program instance and global (no --watch), or those whose
// path matches a --watch pattern (`*` matches any run of characters,
// case-insensitive: `Main.*`, `*.level`). Strings are not recorded
// (decision 0081).
#pragma once

#include <string>
#include <vector>

#include "interpreter/sema/program_model.h"
#include "runtime/vcd_recorder.h"

namespace strun::project {

// At most this many variables are recorded (docs/limits.md): past it the
// rest is left out with a warning, and --watch picks what to record.
inline constexpr size_t kMaxVcdSignals = 100000;

// `unmatched` gets the patterns that match no recordable variable;
// `truncated` is set when more than kMaxVcdSignals would be recorded. `text`
// (--vcd-text): STRING variables are recorded as text and enumerations by
// their value names, as VCD string signals (decision 0241).
std::vector<rt::VcdSignal> vcdSignals(const sema::ProgramModel& model, const std::vector<std::string>& patterns,
                                      std::vector<std::string>& unmatched, bool& truncated, bool text = false);

// Which tasks get a running/idle waveform: every task (the contract's
// timeline), or, when a --watch is `task:PATTERN`, only the tasks such
// patterns name; `!task:PATTERN` leaves tasks out (`!task:*`: no timeline, a
// small file for a freewheeling program). The other patterns go to
// `variablePatterns`; a task pattern naming no task to `unmatched`.
std::vector<bool> vcdTaskSelection(const std::vector<std::string>& taskNames, const std::vector<std::string>& patterns,
                                   std::vector<std::string>& variablePatterns, std::vector<std::string>& unmatched);

// `*`-glob match, case-insensitive.
bool matchesPattern(std::string_view pattern, std::string_view text);

}  // namespace strun::project
