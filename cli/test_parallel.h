// `strun test -j N`: runs slices of the test suites in child processes
// (fork after compiling, so the project is compiled once) and prints what
// each printed in slice order, so the output reads as one serial run.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace strun::cli {

struct ChildSlice {
    int exitCode = 1;        // the child's exit status (1 when it crashed)
    std::string dir;         // a private directory the child may write files to
};

// Runs `body(k, dir)` in `n` child processes at once (k = 0..n-1; `dir` is a
// fresh directory for its files), each with its stdout and stderr captured,
// waits for all of them, then copies each child's stdout and stderr to ours
// in the order of k. The caller removes the directories with removeSliceDirs.
// Empty when the processes cannot be started (the caller runs serially).
std::vector<ChildSlice> runInChildren(size_t n, const std::function<int(size_t k, const std::string& dir)>& body);

void removeSliceDirs(const std::vector<ChildSlice>& slices);

// The number of processors online (at least 1): the value of `-j 0`.
size_t processorCount();

}  // namespace strun::cli
