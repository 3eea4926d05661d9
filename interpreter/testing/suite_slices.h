// Splitting a project's test suites into deterministic slices: `strun test
// --shard K/N` (one slice per CI machine) and `-j N` (one slice per process).
// A suite is the unit (its tests share the suite's body and state); slice K
// of N holds a contiguous run of suites in declaration order, so that the
// slices' outputs, put one after the other, are in declaration order too.
#pragma once

#include <cstddef>

namespace strun::testing {

class TestRegistry;

// Whether suite `index` of `count` belongs to slice `k` (0-based) of `n`:
// suite i is in slice floor(i * n / count). Every suite is in exactly one slice.
bool inSlice(size_t index, size_t count, size_t k, size_t n);

// Keeps only slice `k` (0-based) of `n` of the registry's suites; the others
// are neither run nor reported.
void keepSlice(TestRegistry& reg, size_t k, size_t n);

}  // namespace strun::testing
