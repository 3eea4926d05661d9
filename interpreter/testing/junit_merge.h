// Merging the JUnit XML reports strun writes (the processes of `strun test
// -j N`, or the files of `--shard K/N` runs on several machines): one
// <testsuites> holding every <testsuite> in the order of the inputs, the
// counts summed, the ids renumbered.
#pragma once

#include <string>
#include <vector>

namespace strun::testing {

// False (with `error`) when an input cannot be read or is not a report strun
// wrote, or the output cannot be written.
bool mergeJUnit(const std::vector<std::string>& inputs, const std::string& output, std::string& error);

}  // namespace strun::testing
