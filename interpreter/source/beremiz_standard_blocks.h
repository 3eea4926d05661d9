// The blocks of matiec's standard library (Beremiz, OpenPLC) that share a
// name with a CODESYS Util block of strun's library but not its interface:
// PID, INTEGRAL, DERIVATIVE, RAMP, HYSTERESIS as IEC 61131-3 (2nd edition)
// defines them, which matiec provides (decision 0360). A Beremiz project
// (decision 0356) gets them as a source of its own, so that its
// `pid1(TRUE, sp, pv, 0.0, kp, tr, td, cycle, out)` calls the block it was
// written for; other projects keep CODESYS' blocks.
#pragma once

#include <string>

namespace strun::source {

// The path diagnostics name the source by.
inline constexpr const char* kBeremizStandardBlocksPath = "<matiec standard blocks>";

// ST declaring those of the blocks that `plcXml` (a PLCopen project) uses as
// a type (`<derived name="PID"/>`) and does not declare itself, with the
// blocks they use; "" when it uses none.
std::string beremizStandardBlocks(const std::string& plcXml);

}  // namespace strun::source
