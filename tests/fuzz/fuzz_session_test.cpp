// The fuzz session reuses one parsed standard library across compiles: the
// reuse must not change results (same dump as a fresh compile, run after run)
// and must make an iteration cheap.
#include <catch2/catch.hpp>

#include <chrono>
#include <string>

#include "tests/fuzz/fuzz_session.h"

namespace {
std::string run(strun::fuzz::Session& s, const std::string& text) {
    return s.runOnce(reinterpret_cast<const uint8_t*>(text.data()), text.size());
}
const char* kProgram = R"(
FUNCTION_BLOCK Acc
VAR_INPUT x : INT; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
VAR total : DINT; t : TON; END_VAR
total := total + x;
t(IN := TRUE, PT := T#2ms);
q := t.Q;
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Acc; s : STRING := 'abc'; n : INT; done : BOOL; END_VAR
n := n + 1;
a(x := n);
s := CONCAT(s, 'x');
done := a.q;
END_PROGRAM
)";
}  // namespace

TEST_CASE("a reused standard library gives the same result every time") {
    strun::fuzz::Session session;
    const std::string first = run(session, kProgram);
    REQUIRE(first.find("\"state\":\"RUN\"") != std::string::npos);
    REQUIRE(first.find("\"done\":true") != std::string::npos);  // TON from the library ran 5 ms
    for (int k = 0; k < 3; ++k) CHECK(run(session, kProgram) == first);
    strun::fuzz::Session fresh;
    CHECK(run(fresh, kProgram) == first);
}

TEST_CASE("bad input between good ones leaves the library intact") {
    strun::fuzz::Session session;
    const std::string good = run(session, kProgram);
    CHECK(run(session, "PROGRAM Main VAR x : INT; END_VAR x := ; END_PROGRAM").empty());
    CHECK(run(session, "TYPE TON : INT; END_TYPE PROGRAM Main VAR t : TON; END_VAR END_PROGRAM").size() >= 0);
    CHECK(run(session, "FUNCTION_BLOCK A EXTENDS A END_FUNCTION_BLOCK").empty());
    CHECK(run(session, kProgram) == good);
}

TEST_CASE("a small program compiles and runs with the lent library; the cost of an iteration is reported") {
    strun::fuzz::Session session;
    const std::string small = "PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM";
    REQUIRE(run(session, small).find("\"state\":\"RUN\"") != std::string::npos);
    const int n = 20;
    auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < n; ++k) run(session, small);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / n;
    // A measurement, not a timed test (wall times on a shared machine are noise).
    WARN("one iteration: " << ms << " ms");
}
