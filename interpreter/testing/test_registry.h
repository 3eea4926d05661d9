// The state of a `strun test` run that the TcUnit API nodes share: the suites
// RUN() calls, the tests each suite registered with TEST(), their failures,
// and the fault capture that turns a runtime fault inside a test into a
// failure of that test instead of a PLC STOP. One per compiled project
// (owned by the ProgramModel); the nodes hold a plain pointer to it.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "interpreter/testing/axunit_fixtures.h"
#include "runtime/machine.h"

namespace strun::exec { struct PouCode; struct Ctx; }

namespace strun::testing {

// One failed assertion, or the fault / timeout that ended a test.
struct Failure {
    int file = -1;  // SourceSet index of the assertion (or faulting statement); -1 unknown
    int line = 0;
    std::string filePath;  // file < 0: the path as text (AxUnit's {CallerFilePath}), "" unknown
    std::string expected, actual, message;
    std::string fault;  // non-empty: "ARRAY_BOUNDS: subscript 11 outside 1..10" (no EXP/ACT)
};

struct TestCase {
    std::string name;         // as given to TEST(), trimmed, without the DISABLED_ prefix
    bool skipped = false;     // DISABLED_ or not selected by --filter: neither run nor counted
    bool finished = false;
    int order = 0;            // TEST_ORDERED: 1, 2, ... in the order first seen; 0 = unordered
    rt::PlcTime startedAt = 0, finishedAt = 0;
    uint64_t lastCycle = 0;   // the suite cycle that last called TEST() for it (duplicate check)
    bool duplicateReported = false;  // TcUnit reports a duplicate name once
    rt::PlcTime awaitStart = -1;     // AWAIT_ASSERTIONS: when the test first awaited; -1 never
    std::vector<Failure> failures;
};

struct Suite {
    std::string name;         // the instance's name as declared
    std::string path;         // Program.member path ("PRG_TEST.fbSuite")
    std::string typeName;     // the FUNCTION_BLOCK
    bool axUnit = false;      // an AxUnit fixture (decision 0365): TcUnit's test limit does not apply
    std::vector<std::string> blocks;  // it and the blocks it extends, upper case
    uint8_t* instance = nullptr;
    exec::PouCode* body = nullptr;
    std::vector<TestCase> tests;
    int orderedCount = 0;
    uint64_t cycles = 0;      // how many times RUN() called it
    // TcUnit's assertion records (MaxNumberOfAssertsForEachTestSuite): each
    // distinct assertion (test, place, message, values) once, the same one
    // again only when it comes more often in one cycle than in any before.
    std::unordered_map<uint64_t, uint32_t> assertRecords, assertsThisCycle;
    uint64_t assertCycle = 0;
    int64_t assertCount = 0;
    bool assertOverflowReported = false;
    bool pastSuiteLimit = false;  // past MaxNumberOfTestSuites: never run, its tests fail
    bool finished() const;    // called at least once and every test finished or skipped (or past the limit)
};

class TestRegistry;

// Installed as Machine::handler while RUN() calls a suite: a fault inside a
// test fails that test (and the PLC keeps running); the suite call gets a
// watchdog budget of its own. Everything else goes to the scheduler.
class FaultCapture final : public rt::AttentionHandler {
public:
    explicit FaultCapture(TestRegistry& r) : registry_(r) {}
    bool onAttention() override;
    void onFault(rt::DiagCode code, std::string_view pou, int line, std::string message, int file = -1, int col = 0) override;
    // What the suite's code asks of its task (the task's start time, name,
    // index, period, a log line) is the scheduler's answer, as outside a suite.
    rt::PlcTime currentTime() override { return inner->currentTime(); }
    int64_t calendarNanos() override { return inner->calendarNanos(); }
    int64_t taskStartCalendarNanos() override { return inner->taskStartCalendarNanos(); }
    rt::PlcTime currentTaskInterval() override { return inner->currentTaskInterval(); }
    bool setCurrentTaskInterval(rt::PlcTime period) override { return inner->setCurrentTaskInterval(period); }
    void onLog(std::string_view pou, int line, std::string message, int file, int col) override {
        inner->onLog(pou, line, std::move(message), file, col);
    }
    std::string currentTaskName() const override { return inner->currentTaskName(); }
    int currentTaskIndex() const override { return inner->currentTaskIndex(); }
    bool taskInfo(int index, TaskInfo& out) const override { return inner->taskInfo(index, out); }

    rt::AttentionHandler* inner = nullptr;
    rt::Machine* machine = nullptr;
    exec::Ctx* ctx = nullptr;  // the task context running the suite (the position of a WATCHDOG; CALL_DEPTH lets it go on)
    rt::PlcTime budgetEnd = rt::kNever;
    bool abortedByTest = false;  // the abort unwinding now was caused by a test fault

private:
    TestRegistry& registry_;
};

class TestRegistry {
public:
    TestRegistry() : capture(*this) {}
    TestRegistry(const TestRegistry&) = delete;
    TestRegistry& operator=(const TestRegistry&) = delete;

    // ---- filled at compile time
    int runCalls = 0;  // RUN() / RUN_IN_SEQUENCE() calls the checker saw
    // TEST('name') calls with a constant name: the POU code name that makes
    // the call ("FB_X" or "FB_X.Method"), the name, and where it is written.
    struct StaticTest {
        std::string pou, name;
        int file = 0, line = 0;
    };
    std::vector<StaticTest> staticTests;
    std::map<std::string, int> pouFiles;  // POU code name -> source file (fault locations)
    std::vector<std::string> suiteBlocks;  // FUNCTION_BLOCKs extending FB_TestSuite, not ABSTRACT
    std::vector<AxFixture> axFixtures;     // AxUnit {TestFixture} classes and {Test} functions (decision 0365)

    // ---- set up by the runner
    std::vector<Suite> suites;
    std::string filter;               // --filter: glob over "Suite.Test"; empty = all
    rt::PlcTime watchdog = 0;         // budget of one suite call (the task's watchdog); 0 = none
    rt::PlcTime testTimeout = 0;      // TIMEOUT_FOR_EACH_TEST; 0 = none
    // GVL_Param_TcUnit as compiled (readTcUnitLimits; TcUnit's defaults).
    int64_t maxTests = 100;           // MaxNumberOfTestsForEachTestSuite
    int64_t maxAsserts = 1000;        // MaxNumberOfAssertsForEachTestSuite
    int64_t maxSuites = 1000;         // MaxNumberOfTestSuites
    bool logExtendedResults = true;   // FALSE: TCUNIT_ADSLOGSTR prints only ADSLOG_MSGTYPE_ERROR
    rt::PlcTime timeBetweenSuites = 0;  // TimeBetweenTestSuitesExecution: RUN_IN_SEQUENCE()'s pause

    // ---- the API (called by the nodes)
    // TEST / TEST_ORDERED: makes `name` the current test; for TEST_ORDERED
    // returns whether it is its turn. `hint` (per call site and suite) caches
    // the test's index so that the usual call finds it without a search.
    bool beginTest(std::string_view name, bool ordered, rt::PlcTime now, int* hint = nullptr);
    bool finishCurrent(rt::PlcTime now);
    bool finishNamed(std::string_view name, rt::PlcTime now);
    bool isFinished(std::string_view name) const;
    // AWAIT_ASSERTIONS(AwaitTime): until AwaitTime has passed since the
    // current test first called it, its assertions and TEST_FINISHED are held.
    void awaitAssertions(rt::PlcTime awaitTime, rt::PlcTime now);
    // TIMEOUT_FOR_EACH_TEST(Timeout): a test still running Timeout after it
    // started fails with a timeout and is finished (0: no limit).
    void setTestTimeout(rt::PlcTime timeout) { testTimeout = timeout; }
    // FB_TestSuite's query methods: the suite whose instance is at `instance`
    // (null when it is not one RUN() calls).
    const Suite* suiteAt(const uint8_t* instance) const;
    // Whether an assertion now counts (a test is current, running, not skipped).
    bool assertionsActive() const { return currentSuite >= 0 && currentTest >= 0 && !ignoreCurrent; }
    void recordFailure(Failure f);  // into the current test (duplicates of an earlier one are dropped)
    // Every evaluated assertion of the current test, by a hash of what TcUnit
    // compares (place, message, expected, actual): past the suite's
    // MaxNumberOfAssertsForEachTestSuite records TcUnit logs its error once.
    void noteAssertion(uint64_t hash);
    // RUN(): calls the suites (all, or in sequence) on the task's context.
    // RUN_IN_SEQUENCE waits `pause` of PLC time between one suite finishing
    // and the next one starting (TcUnit's TimeBetweenTestSuitesExecution).
    void runSuites(exec::Ctx& c, bool inSequence, rt::PlcTime pause = 0);
    rt::PlcTime nextSuiteAt = 0;  // RUN_IN_SEQUENCE: the next suite starts no sooner

    bool allFinished() const;
    // TEST_FINISHED_NAMED with a name the suite does not have: TcUnit logs
    // "Failed to find test 'X'" (three times at most, then one last warning)
    // and aborts the run; the tests still running then fail with `abortReason`.
    bool aborted = false;
    std::string abortReason;
    int failedLookups = 0;
    // After the run: unfinished tests fail with `why` ("timeout").
    void failUnfinished(const std::string& why);
    // The tests a suite declares (constant names given to TEST / TEST_ORDERED
    // in its blocks, in the order written, DISABLED_ and --filter applied):
    // what --list prints.
    std::vector<std::string> declaredTests(const Suite& s) const;
    // After the run: every declared test that never called TEST() (a test
    // before it looped, the run stopped) is added and fails with `not run`,
    // so that the report lists every test --list shows.
    void addNotRun();
    // Before the run: TcUnit registers at most MaxNumberOfTestSuites suites;
    // those past it (in declaration order) are marked and never run.
    void markSuitesPastLimit();
    // After the run: a suite with more tests than MaxNumberOfTestsForEachTestSuite
    // fails the tests past the limit and logs TcUnit's error (its text); every
    // test of a suite past MaxNumberOfTestSuites fails as not run, with one error.
    void applyTestLimit();

    int currentSuite = -1;
    int currentTest = -1;
    bool ignoreCurrent = false;
    FaultCapture capture;

private:
    bool selected(const Suite& s, const std::string& test) const;
};

// Glob match with '*' (any run) and '?' (one character), case-insensitive.
bool globMatch(std::string_view pattern, std::string_view text);

}  // namespace strun::testing
