// AxUnit test discovery for `strun test` (decision 0365): the CLASSes marked
// {TestFixture} and their methods marked {Test} (or {Test(a := 1, ...)}, one
// test per pragma), {TestSetup} / {TestTearDown} run around each test,
// {FixtureSetup} / {FixtureTearDown} once around the fixture's tests; also
// FUNCTIONs marked {Test}, one fixture per namespace. Each fixture becomes a
// TcUnit-style suite block (ST the runner adds, like its test program), so
// AxUnit tests run, fail and report exactly as TcUnit suites do; the suite is
// shown under the fixture's qualified name, tests in AxUnit's order
// (alphabetical by qualified name).
#pragma once

#include <string>
#include <vector>

namespace strun::sema { struct ProgramModel; }

namespace strun::testing {

struct AxTest {
    std::string name;  // as reported: "Method" or "Method(a := 1)"
    std::string call;  // ST call text: "Method(a := 1)"
};

struct AxFixture {
    std::string displayName;  // "Ns.Class" (functions: the namespace)
    std::string typeName;     // qualified class name to declare the fixture with; "" for functions
    std::vector<AxTest> tests;
    std::string setup, teardown, fixtureSetup, fixtureTeardown;  // method names, "" when none
};

class TestRegistry;

// While the AST is alive (recordProject): every fixture, in AxUnit's order.
void recordAxFixtures(const sema::ProgramModel& model, TestRegistry& registry);

// ST of one suite block per fixture; their names are appended to `blocks`.
std::string axFixtureSuites(const std::vector<AxFixture>& fixtures, std::vector<std::string>& blocks);

// After collectSuites: the suites of those blocks take the fixtures' names.
void nameAxSuites(TestRegistry& registry);

}  // namespace strun::testing
