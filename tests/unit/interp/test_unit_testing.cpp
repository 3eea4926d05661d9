// `strun test` below the command line: the TcUnit API run through
// testing::compileForTests / runTests, the JUnit report, the --filter glob,
// TCUNIT_ADSLOGSTR and the value texts of failed assertions.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "interpreter/testing/assert_text.h"
#include "interpreter/testing/test_registry.h"
#include "interpreter/testing/test_report.h"
#include "interpreter/testing/test_session.h"

using namespace strun;

namespace {

struct TestRun {
    SourceSet sources;
    CompileLog log;
    std::unique_ptr<sema::ProgramModel> model;
    testing::TestRunResult result;
    std::string stdoutText;
    testing::TestCounts counts;
};

std::unique_ptr<TestRun> runSuites(const std::string& source, const std::string& filter = "", rt::PlcTime timeout = 10'000'000'000LL) {
    auto r = std::make_unique<TestRun>();
    int file = r->sources.add("suite.st", source);
    r->model = testing::compileForTests(r->sources, {file}, r->log);
    if (!r->model) return r;
    rt::RunOptions options;
    options.duration = timeout;
    r->result = testing::runTests(*r->model, options, filter);
    std::ostringstream out;
    r->counts = testing::printResults(*r->model->tests, r->sources, out);
    r->stdoutText = out.str();
    return r;
}

std::string printed(const TestRun& r) {
    std::ostringstream out;
    r.log.print(out, r.sources);
    return out.str();
}

const char* const kSuite = R"(
FUNCTION_BLOCK FB_Suite EXTENDS FB_TestSuite
VAR n : INT; END_VAR
TEST('Passes'); AssertEquals_INT(Expected := 1, Actual := 1, Message := 'one'); TEST_FINISHED();
TEST('Fails <twice>');
AssertEquals_INT(Expected := 1, Actual := 2, Message := 'a & b');
AssertTrue(Condition := FALSE, Message := 'second');
TEST_FINISHED();
TEST('DISABLED_Off'); TEST_FINISHED();
TEST('Slow'); n := n + 1; IF n = 3 THEN TEST_FINISHED(); END_IF
END_FUNCTION_BLOCK
)";

}  // namespace

TEST_CASE("a suite runs and its verdicts are printed as the contract says", "[testing]") {
    auto r = runSuites(kSuite);
    INFO(printed(*r));
    REQUIRE(r->model);
    CHECK(r->stdoutText ==
          "PASS FB_Suite.Passes\n"
          "FAIL FB_Suite.Fails <twice>: suite.st:6: EXP: 1, ACT: 2, MSG: a & b\n"
          "PASS FB_Suite.Slow\n"
          "2 passed, 1 failed\n");
    CHECK(r->counts.skipped == 1);
    // The run stops as soon as every test finished: three cycles of the slow test.
    CHECK(r->result.endTime < 1'000'000'000LL);
}

TEST_CASE("the JUnit report has one testsuite per suite, one testcase per test, a failure per failed assertion", "[testing]") {
    auto r = runSuites(kSuite);
    REQUIRE(r->model);
    std::string path = (std::filesystem::temp_directory_path() / ("strun_junit_" + std::to_string(::getpid()) + ".xml")).string();
    std::string error;
    REQUIRE(testing::writeJUnit(*r->model->tests, r->sources, r->result.endTime, path, error));
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    std::remove(path.c_str());
    std::string xml = ss.str();
    INFO(xml);
    CHECK(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites ", 0) == 0);
    CHECK(xml.find("tests=\"4\" failures=\"1\" disabled=\"1\"") != std::string::npos);
    CHECK(xml.find("<testsuite id=\"0\" name=\"FB_Suite\" tests=\"4\" failures=\"1\" skipped=\"1\"") != std::string::npos);
    CHECK(xml.find("<testcase name=\"Passes\" classname=\"FB_Suite\"") != std::string::npos);
    // Names and messages are escaped; every failed assertion is listed with its file and line.
    CHECK(xml.find("<testcase name=\"Fails &lt;twice&gt;\"") != std::string::npos);
    CHECK(xml.find("<failure message=\"EXP: 1, ACT: 2, MSG: a &amp; b\" type=\"ASSERT\" file=\"suite.st\" line=\"6\">") != std::string::npos);
    CHECK(xml.find("<failure message=\"EXP: TRUE, ACT: FALSE, MSG: second\" type=\"ASSERT\" file=\"suite.st\" line=\"7\">") != std::string::npos);
    CHECK(xml.find("<testcase name=\"Off\"") != std::string::npos);
    CHECK(xml.find("<skipped/>") != std::string::npos);
    CHECK(xml.find("</testsuites>\n") != std::string::npos);
    CHECK_FALSE(testing::writeJUnit(*r->model->tests, r->sources, 0, "/nonexistent-dir/x.xml", error));
    CHECK(error.find("cannot write") != std::string::npos);
}

TEST_CASE("--filter selects tests by a case-insensitive glob over Suite.Test", "[testing]") {
    CHECK(testing::globMatch("*", "S.T"));
    CHECK(testing::globMatch("s.*", "S.Test"));
    CHECK(testing::globMatch("*.fa?ls*", "FB_Suite.Fails <twice>"));
    CHECK_FALSE(testing::globMatch("*.Pass", "FB_Suite.Passes"));
    CHECK(testing::globMatch("a*b*c", "aXbYbZc"));
    CHECK_FALSE(testing::globMatch("a*b*c", "aXbYbZ"));
    auto r = runSuites(kSuite, "*.pass*");
    REQUIRE(r->model);
    CHECK(r->stdoutText == "PASS FB_Suite.Passes\n1 passed, 0 failed\n");
}

TEST_CASE("an unfinished test fails with timeout when the timeout passed", "[testing]") {
    auto r = runSuites("FUNCTION_BLOCK FB_T EXTENDS FB_TestSuite\nTEST('Never');\nEND_FUNCTION_BLOCK\n", "", 50'000'000);
    REQUIRE(r->model);
    CHECK(r->stdoutText == "FAIL FB_T.Never: timeout\n0 passed, 1 failed\n");
    CHECK(r->result.endTime >= 50'000'000);
}

TEST_CASE("TCUNIT_ADSLOGSTR writes its message with %s replaced to stderr", "[testing]") {
    std::ostringstream captured;
    auto* saved = std::cerr.rdbuf(captured.rdbuf());
    auto r = runSuites("FUNCTION_BLOCK FB_L EXTENDS FB_TestSuite\nTEST('Log');\n"
                       "TCUNIT_ADSLOGSTR(msgCtrlMask := 1, msgFmtStr := 'value %s seen', strArg := 'x1');\n"
                       "TEST_FINISHED();\nEND_FUNCTION_BLOCK\n");
    std::cerr.rdbuf(saved);
    REQUIRE(r->model);
    CHECK(captured.str() == "value x1 seen\n");
}

TEST_CASE("a project without test suites runs nothing and passes", "[testing]") {
    auto r = runSuites("PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM\n");
    REQUIRE(r->model);
    CHECK(r->stdoutText == "0 passed, 0 failed\n");
}

TEST_CASE("assertion value texts follow TcUnit", "[testing]") {
    sema::TypeTable types;
    auto text = [&](sema::TK k, uint64_t bits) {
        uint8_t buf[8];
        std::memcpy(buf, &bits, 8);
        return testing::assertText(types.elementary(k), buf);
    };
    CHECK(text(sema::TK::Bool, 1) == "TRUE");
    CHECK(text(sema::TK::Byte, 0xAB) == "0xAB");
    CHECK(text(sema::TK::Word, 0x1) == "0x0001");
    CHECK(text(sema::TK::DWord, 0x90ABCDEF) == "0x90ABCDEF");
    CHECK(text(sema::TK::LWord, 0x0123656789ABCBECULL) == "0x0123656789ABCBEC");
    CHECK(text(sema::TK::SInt, 0x80) == "-128");
    CHECK(text(sema::TK::Time, 45255010) == "T#12h34m15s10ms");
    CHECK(text(sema::TK::Tod, 22871492) == "TOD#06:21:11.492");
    CHECK(testing::hexBytes(reinterpret_cast<const uint8_t*>("\x01\xff"), 2) == "0x01FF");
    CHECK(testing::typeClassName(types.elementary(sema::TK::Dt)) == "DATEANDTIME");
}
