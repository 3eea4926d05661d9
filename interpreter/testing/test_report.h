// The results of a `strun test` run as the contract prints them on stdout
// (PASS / FAIL lines, the summary) and as a JUnit XML report for CI, and the
// --list of the tests the suites declare.
#pragma once

#include <ostream>
#include <string>

#include "interpreter/source/source_set.h"
#include "runtime/machine.h"

namespace strun::testing {

class TestRegistry;

struct TestCounts {
    int passed = 0, failed = 0, skipped = 0;
};

// One line per test that ran, "PASS Suite.Test" or "FAIL Suite.Test: WHY",
// then "N passed, M failed" (unless `summary` is false: a slice of a -j run,
// whose summary the parent prints). `color`: PASS green and FAIL red, as
// diagnostics are coloured on a terminal.
TestCounts printResults(const TestRegistry& reg, const SourceSet& sources, std::ostream& out, bool summary = true, bool color = false);

// The FAIL reason of a failure: "FILE:LINE: EXP: e, ACT: a, MSG: m", a fault, or "timeout".
std::string failureText(const struct Failure& f, const SourceSet& sources);

// testsuites / testsuite / testcase / failure (message, file, line), times in
// seconds of PLC time. False (with `error`) when the file cannot be written.
bool writeJUnit(const TestRegistry& reg, const SourceSet& sources, rt::PlcTime totalTime, const std::string& path, std::string& error);

// --list: "Suite.Test" for every TEST('name') with a constant name in the
// suites' blocks (and the blocks they extend), without running anything.
void printTestList(const TestRegistry& reg, std::ostream& out);

}  // namespace strun::testing
