// Exit status of every strun command (the fixed interface).
#pragma once

namespace strun::cli {

constexpr int kExitOk = 0;
constexpr int kExitCompile = 1;   // does not compile (or, for `test`, a test failed)
constexpr int kExitUsage = 2;     // bad command line
constexpr int kExitStopped = 3;   // `run`: the PLC went to STOP/HALT because of a fault

}  // namespace strun::cli
