// IEC duration text for PLC times ("T#1s500ms", "T#0s", "T#-250ms",
// "T#1ms250us"), used by --trace and the --dump diagnostics. Kept inside the
// runtime so it does not depend on the stdlib's value formatter; the output
// follows the same rules as the contract's TIME encoding (largest unit d,
// zero components left out, ns precision when needed).
#pragma once

#include <string>

#include "runtime/machine.h"

namespace strun::rt {

std::string formatDuration(PlcTime nanos);
// Appends the same text to `out` (the trace builds whole lines this way).
void appendDuration(std::string& out, PlcTime nanos);

}  // namespace strun::rt
