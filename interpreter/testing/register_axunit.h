// Binds AxUnit's natives into the checker (decision 0364): axunit_Fail,
// axunit_Succeed, and the comparisons __AXUNIT_EQUAL / __AXUNIT_NOT_EQUAL /
// __AXUNIT_LESS / __AXUNIT_GREATER that the ST assertions of
// stdlib/libraries/AxUnit call. The assertions themselves are ST, overloaded
// by type (decision 0362), with {CallerFilePath} / {CallerLineNumber} inputs.
#pragma once

namespace strun::sema { class Checker; }

namespace strun::testing {

class TestRegistry;

void registerAxUnit(sema::Checker& checker, TestRegistry& registry);

}  // namespace strun::testing
