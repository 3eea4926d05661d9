// A compile of a large project runs with its heap in transparent huge pages
// (decision 0494): strun restarts itself, once, with glibc's tunable
// glibc.malloc.hugetlb=1 when the files named on its command line add up to
// kHugePageInputBytes or more.
#pragma once

#include <cstdint>

namespace strun::cli {

// 256 KiB of sources (about 13 000 lines of ST): below it the compile is too
// short for the restart (about a millisecond) and a huge page's first touch
// (2 MiB zeroed) to pay.
inline constexpr std::uintmax_t kHugePageInputBytes = 256 * 1024;

// Whether this command line restarts: a command that compiles sources (run,
// check, test) whose inputs reach kHugePageInputBytes, GLIBC_TUNABLES not
// set (by the user, who then decides, or by the restart itself, which so
// happens once) and no valgrind (it would run the restarted image outside
// its tool).
bool wantsHugePageRestart(int argc, char** argv);

// Returns only when strun goes on as it is: !wantsHugePageRestart, or the
// restart failed (no /proc). Otherwise the process image is replaced (same
// pid, arguments and open files; nothing has been read or written yet).
void restartWithHugePagesForLargeInputs(int argc, char** argv);

}  // namespace strun::cli
