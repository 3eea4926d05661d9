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

namespace {
std::string runXml(strun::fuzz::Session& s, const std::string& text) {
    return s.runXml(reinterpret_cast<const uint8_t*>(text.data()), text.size());
}
std::string runRetain(strun::fuzz::Session& s, const std::string& bytes) {
    return s.runRetain(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}
}  // namespace

TEST_CASE("the XML input of the fuzzer reaches both readers and the run") {
    strun::fuzz::Session session;
    const std::string tcpou = R"(<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1"><POU Name="Main" Id="{00000000-0000-0000-0000-000000000001}">
<Declaration><![CDATA[PROGRAM Main
VAR n : INT; END_VAR]]></Declaration>
<Implementation><ST><![CDATA[n := n + 2;]]></ST></Implementation></POU></TcPlcObject>)";
    const std::string dump = runXml(session, tcpou);
    REQUIRE(dump.find("\"state\":\"RUN\"") != std::string::npos);
    CHECK(dump.find("\"n\":") != std::string::npos);
    const std::string plcopen = R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-11-27T10:00:00"/>
<contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
<types><dataTypes/><pous><pou name="Main" pouType="program"><interface><localVars><variable name="k"><type><INT/></type></variable></localVars></interface>
<body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">k := k + 3;</xhtml></ST></body></pou></pous></types>
<instances><configurations/></instances></project>)";
    const std::string dump2 = runXml(session, plcopen);
    REQUIRE(dump2.find("\"state\":\"RUN\"") != std::string::npos);
    CHECK(dump2.find("\"k\":") != std::string::npos);
    CHECK(runXml(session, "<TcPlcObject><POU Name=\"x\"><Declaration><![CDATA[").empty());
    CHECK(runXml(session, tcpou) == dump);
}

TEST_CASE("the retain input of the fuzzer is restored into its program") {
    strun::fuzz::Session session;
    const std::string cold = runRetain(session, "");
    REQUIRE(cold.find("\"state\":\"RUN\"") != std::string::npos);
    const std::string file = session.validRetainFile();
    REQUIRE(!file.empty());
    // A warm start from the saved file continues the counts: differs from a cold start.
    const std::string warm = runRetain(session, file);
    REQUIRE(warm.find("\"state\":\"RUN\"") != std::string::npos);
    CHECK(warm != cold);
    // A damaged file is a cold start (with a warning), never a crash.
    std::string damaged = file;
    damaged[damaged.size() / 2] ^= 0x5a;
    CHECK(runRetain(session, damaged) == cold);
    // Bytes that are not a retain file at all are refused (never overwritten, decision 0251).
    CHECK(runRetain(session, std::string(300, '\xff')).empty());
    // "END FIX" gets the right checksum: the same warm start as the valid file.
    const std::string toFix = session.validRetainFile(true);
    REQUIRE(toFix.find("END FIX") != std::string::npos);
    CHECK(runRetain(session, toFix) == warm);
    // A value that is not valid for its type (BOOL byte 2) is dropped with a
    // warning, the rest restored: neither the cold nor the warm result.
    std::string badBool = toFix;
    const std::string goodLine = "gB\tBOOL (1 bytes)\t01";
    REQUIRE(badBool.find(goodLine) != std::string::npos);
    badBool.replace(badBool.find(goodLine), goodLine.size(), "gB\tBOOL (1 bytes)\t02");
    const std::string partly = runRetain(session, badBool);
    CHECK(partly.find("\"state\":\"RUN\"") != std::string::npos);
    CHECK(partly != cold);
}
