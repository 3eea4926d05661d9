#include "interpreter/testing/test_registry.h"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <tuple>

#include <fmt/format.h>

#include "interpreter/exec/call_nodes.h"
#include "interpreter/sema/types.h"
#include "runtime/fnv1a.h"
#include "stdlib/value_format.h"

namespace strun::testing {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

bool startsWithNoCase(std::string_view s, std::string_view prefix) {
    if (s.size() < prefix.size()) return false;
    for (size_t k = 0; k < prefix.size(); ++k)
        if (std::tolower(static_cast<unsigned char>(s[k])) != std::tolower(static_cast<unsigned char>(prefix[k]))) return false;
    return true;
}

const std::string kRunPou = "RUN";

}  // namespace

bool globMatch(std::string_view p, std::string_view t) {
    // Iterative matcher with one backtrack point: linear in practice, no recursion.
    size_t pi = 0, ti = 0, star = std::string_view::npos, mark = 0;
    auto same = [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b)); };
    while (ti < t.size()) {
        if (pi < p.size() && (p[pi] == '?' || (p[pi] != '*' && same(p[pi], t[ti])))) {
            ++pi;
            ++ti;
        } else if (pi < p.size() && p[pi] == '*') {
            star = pi++;
            mark = ti;
        } else if (star != std::string_view::npos) {
            pi = star + 1;
            ti = ++mark;
        } else {
            return false;
        }
    }
    while (pi < p.size() && p[pi] == '*') ++pi;
    return pi == p.size();
}

bool Suite::finished() const {
    if (pastSuiteLimit) return true;
    if (cycles == 0) return false;
    for (const auto& t : tests)
        if (!t.finished && !t.skipped) return false;
    return true;
}

bool TestRegistry::selected(const Suite& s, const std::string& test) const {
    if (filter.empty()) return true;
    return globMatch(filter, s.name + "." + test) || globMatch(filter, s.path + "." + test);
}

bool TestRegistry::beginTest(std::string_view rawName, bool ordered, rt::PlcTime now, int* hint) {
    currentTest = -1;
    ignoreCurrent = true;
    if (currentSuite < 0) return false;
    Suite& s = suites[static_cast<size_t>(currentSuite)];
    std::string_view name = trim(rawName);
    bool disabled = startsWithNoCase(name, "disabled_");
    if (disabled) name.remove_prefix(9);
    int index = -1;
    if (hint && *hint >= 0 && static_cast<size_t>(*hint) < s.tests.size() && s.tests[static_cast<size_t>(*hint)].name == name) {
        index = *hint;  // the usual case: this TEST() call site registered it
    } else {
        for (size_t k = 0; k < s.tests.size(); ++k)
            if (s.tests[k].name == name) index = static_cast<int>(k);
    }
    if (index < 0) {
        TestCase t;
        t.name = std::string(name);
        t.skipped = disabled || !selected(s, t.name);
        t.startedAt = now;
        t.lastCycle = s.cycles;
        if (ordered) t.order = ++s.orderedCount;
        s.tests.push_back(std::move(t));
        index = static_cast<int>(s.tests.size()) - 1;
    } else if (s.tests[static_cast<size_t>(index)].lastCycle == s.cycles && s.cycles != 0) {
        // The same name twice in one cycle: TcUnit ignores the second one and
        // logs an error, once (its text, with the suite's instance path).
        TestCase& dup = s.tests[static_cast<size_t>(index)];
        if (!dup.duplicateReported) {
            dup.duplicateReported = true;
            std::cerr << "Test with name '" << dup.name << "' already exists in test suite '" << s.path << "'\n";
        }
        return false;
    }
    TestCase& t = s.tests[static_cast<size_t>(index)];
    t.lastCycle = s.cycles;
    currentTest = index;
    if (hint) *hint = index;
    if (t.skipped || t.finished) return false;
    if (testTimeout > 0 && now - t.startedAt > testTimeout) {
        // TIMEOUT_FOR_EACH_TEST: TcUnit stops the PLC; strun fails this test
        // and lets the others go on (decision 0142).
        Failure f;
        f.fault = fmt::format("timeout: not finished {} after it started (TIMEOUT_FOR_EACH_TEST)", stdlib::formatDuration(testTimeout));
        t.failures.push_back(std::move(f));
        t.finished = true;
        t.finishedAt = now;
        return false;
    }
    if (t.order > 0) {
        // TEST_ORDERED: its turn once every ordered test before it finished.
        for (const auto& other : s.tests)
            if (other.order > 0 && other.order < t.order && !other.finished && !other.skipped) return false;
    }
    ignoreCurrent = false;
    return true;
}

bool TestRegistry::finishCurrent(rt::PlcTime now) {
    if (currentSuite < 0 || currentTest < 0 || ignoreCurrent) return false;
    TestCase& t = suites[static_cast<size_t>(currentSuite)].tests[static_cast<size_t>(currentTest)];
    if (!t.finished) {
        t.finished = true;
        t.finishedAt = now;
    }
    ignoreCurrent = true;
    return true;
}

bool TestRegistry::finishNamed(std::string_view name, rt::PlcTime now) {
    if (currentSuite < 0) return false;
    name = trim(name);
    for (auto& t : suites[static_cast<size_t>(currentSuite)].tests) {
        if (t.name != name) continue;
        if (!t.finished && !t.skipped) {
            t.finished = true;
            t.finishedAt = now;
        }
        return true;
    }
    // TcUnit's messages (three, then one that suppresses the rest) and its abort.
    if (failedLookups < 3) std::cerr << "Failed to find test '" << name << "'\n";
    else if (failedLookups == 3) std::cerr << "Excess failed attempts to mark test finished, failed. Further warnings will be suppressed\n";
    ++failedLookups;
    if (!aborted) {
        aborted = true;
        abortReason = fmt::format("aborted: TEST_FINISHED_NAMED could not find test '{}'", name);
    }
    return false;
}

bool TestRegistry::isFinished(std::string_view name) const {
    if (currentSuite < 0) return false;
    name = trim(name);
    for (const auto& t : suites[static_cast<size_t>(currentSuite)].tests)
        if (t.name == name) return t.finished;
    return false;
}

void TestRegistry::awaitAssertions(rt::PlcTime awaitTime, rt::PlcTime now) {
    if (!assertionsActive()) return;
    TestCase& t = suites[static_cast<size_t>(currentSuite)].tests[static_cast<size_t>(currentTest)];
    if (t.awaitStart < 0) t.awaitStart = now;
    // Held: the rest of this cycle's assertions and TEST_FINISHED count for nothing.
    if (now - t.awaitStart < awaitTime) ignoreCurrent = true;
}

const Suite* TestRegistry::suiteAt(const uint8_t* instance) const {
    for (const auto& s : suites)
        if (s.instance == instance) return &s;
    return nullptr;
}

void TestRegistry::recordFailure(Failure f) {
    if (!assertionsActive()) return;
    TestCase& t = suites[static_cast<size_t>(currentSuite)].tests[static_cast<size_t>(currentTest)];
    // A multi-cycle test repeats its assertions every cycle: report each distinct failure once.
    for (const auto& old : t.failures)
        if (old.file == f.file && old.line == f.line && old.expected == f.expected && old.actual == f.actual &&
            old.message == f.message && old.fault == f.fault)
            return;
    t.failures.push_back(std::move(f));
}

void TestRegistry::runSuites(exec::Ctx& c, bool inSequence, rt::PlcTime pause) {
    exec::Site site{&kRunPou, 0};
    capture.machine = c.m;
    capture.ctx = &c;
    for (size_t k = 0; k < suites.size(); ++k) {
        Suite& s = suites[k];
        if (s.finished()) continue;
        if (inSequence && s.cycles == 0 && c.m->time() < nextSuiteAt) break;  // the pause between two suites
        currentSuite = static_cast<int>(k);
        currentTest = -1;
        ignoreCurrent = true;
        ++s.cycles;
        capture.inner = c.m->handler;
        capture.abortedByTest = false;
        capture.budgetEnd = watchdog > 0 ? c.m->time() + watchdog : rt::kNever;
        c.m->handler = &capture;
        if (capture.budgetEnd < c.m->deadline.load(std::memory_order_relaxed)) c.m->setDeadline(capture.budgetEnd);
        uint8_t* f = exec::pushFrame(c, *s.body, site);
        if (f) {
            exec::runBody(c, *s.body, s.instance, f);
            c.stackTop = f;
        }
        c.m->handler = capture.inner;
        // The budget deadline is ours: let the scheduler re-arm its own at the next look.
        if (capture.budgetEnd != rt::kNever) c.m->requestAttention();
        currentSuite = -1;
        currentTest = -1;
        if (c.aborting) {
            if (!capture.abortedByTest) return;  // the scheduler's abort (STOP, end of run): unwind
            c.aborting = false;                  // a test's fault: the other suites go on
        }
        if (inSequence && !s.finished()) break;
        if (inSequence) {
            nextSuiteAt = c.m->time() + pause;
            if (pause > 0) break;
        }
    }
}

bool TestRegistry::allFinished() const {
    for (const auto& s : suites)
        if (!s.finished()) return false;
    return true;
}

void TestRegistry::failUnfinished(const std::string& why) {
    for (auto& s : suites)
        for (auto& t : s.tests)
            if (!t.finished && !t.skipped && t.failures.empty()) {
                Failure f;
                f.fault = why;
                t.failures.push_back(std::move(f));
            }
}

std::vector<std::string> TestRegistry::declaredTests(const Suite& s) const {
    // In the order they are written (the checker visits methods by name).
    std::vector<StaticTest> calls = staticTests;
    std::stable_sort(calls.begin(), calls.end(), [](const auto& a, const auto& b) { return std::tie(a.file, a.line) < std::tie(b.file, b.line); });
    std::vector<std::string> names;
    for (const auto& call : calls) {
        // Code names are "Block" and "Block.Method": the call must be in the suite's block or one it extends.
        std::string block = sema::upper(call.pou.substr(0, call.pou.find('.')));
        if (std::find(s.blocks.begin(), s.blocks.end(), block) == s.blocks.end()) continue;
        std::string name(trim(call.name));
        if (startsWithNoCase(name, "disabled_")) continue;
        if (!selected(s, name)) continue;
        if (std::find(names.begin(), names.end(), name) != names.end()) continue;
        names.push_back(std::move(name));
    }
    return names;
}

void TestRegistry::noteAssertion(uint64_t hash) {
    Suite& s = suites[static_cast<size_t>(currentSuite)];
    hash = hash * rt::kFnv1aPrime ^ static_cast<uint64_t>(currentTest);
    if (s.assertCycle != s.cycles) {
        s.assertCycle = s.cycles;
        s.assertsThisCycle.clear();
    }
    uint32_t seen = ++s.assertsThisCycle[hash];
    uint32_t& stored = s.assertRecords[hash];
    if (seen <= stored) return;  // the same assertion as in an earlier cycle
    if (s.assertCount >= maxAsserts) {
        if (!s.assertOverflowReported) {
            s.assertOverflowReported = true;
            std::cerr << s.path << ". Max number of assertions exceeded. Check parameter MaxNumberOfAssertsForEachTestSuite.\n";
        }
        return;
    }
    ++stored;
    ++s.assertCount;
}

void TestRegistry::markSuitesPastLimit() {
    for (size_t k = 0; k < suites.size(); ++k) suites[k].pastSuiteLimit = maxSuites >= 0 && k >= static_cast<size_t>(maxSuites);
}

void TestRegistry::applyTestLimit() {
    bool suiteLimitReported = false;
    for (auto& s : suites) {
        if (!s.pastSuiteLimit) continue;
        // TcUnit has no slot for the suite (its FB_init would write past
        // TestSuiteAddresses): none of its tests ran, and none may pass silently.
        for (TestCase& t : s.tests) {
            if (t.skipped) continue;
            Failure f;
            f.fault = fmt::format("not run: the project has more test suites than GVL_Param_TcUnit.MaxNumberOfTestSuites ({})", maxSuites);
            t.failures.assign(1, std::move(f));
            t.finished = true;
        }
        if (!suiteLimitReported)
            std::cerr << "Test suite '" << s.path << "' and those after it were not run: the project has more test suites than "
                      << "defined in parameter 'GVL_Param_TcUnit.MaxNumberOfTestSuites' (" << maxSuites << "). Please increase this parameter.\n";
        suiteLimitReported = true;
    }
    for (auto& s : suites) {
        if (maxTests < 0 || s.tests.size() <= static_cast<size_t>(maxTests) || s.axUnit) continue;
        for (size_t k = static_cast<size_t>(maxTests); k < s.tests.size(); ++k) {
            TestCase& t = s.tests[k];
            if (t.skipped) continue;
            // TcUnit has no room for its results: it counts it as failed.
            Failure f;
            f.fault = fmt::format("not recorded: the suite has more tests than GVL_Param_TcUnit.MaxNumberOfTestsForEachTestSuite ({})",
                                  maxTests);
            t.failures.assign(1, std::move(f));
            t.finished = true;
        }
        std::cerr << "Tests failed because the number of tests (" << s.tests.size() << ") in the test suite '" << s.path
                  << "' are more than is defined in parameter 'GVL_Param_TcUnit.MaxNumberOfTestsForEachTestSuite' (" << maxTests
                  << "). Please increase this parameter.\n";
    }
}

void TestRegistry::addNotRun() {
    for (auto& s : suites) {
        size_t insertAt = 0;
        for (const std::string& name : declaredTests(s)) {
            auto it = std::find_if(s.tests.begin(), s.tests.end(), [&](const TestCase& t) { return t.name == name; });
            if (it != s.tests.end()) {
                insertAt = std::max(insertAt, size_t(it - s.tests.begin()) + 1);
                continue;
            }
            TestCase t;
            t.name = name;
            Failure f;
            f.fault = "not run";
            t.failures.push_back(std::move(f));
            s.tests.insert(s.tests.begin() + std::ptrdiff_t(insertAt), std::move(t));
            ++insertAt;
        }
    }
}

bool FaultCapture::onAttention() {
    if (machine && machine->time() >= budgetEnd) {
        TestRegistry& r = registry_;
        if (r.currentSuite >= 0 && r.currentTest >= 0) {
            Failure f;
            if (ctx && ctx->pouName) {
                auto file = r.pouFiles.find(*ctx->pouName);
                f.file = file == r.pouFiles.end() ? -1 : file->second;
                f.line = ctx->stmt ? ctx->stmt->line : 0;
            }
            f.fault = fmt::format("WATCHDOG: the test ran longer than the task watchdog ({}) in one cycle", stdlib::formatDuration(r.watchdog));
            r.ignoreCurrent = false;
            r.recordFailure(std::move(f));
            TestCase& t = r.suites[static_cast<size_t>(r.currentSuite)].tests[static_cast<size_t>(r.currentTest)];
            t.finished = true;
            t.finishedAt = machine->time();  // its JUnit time: never left at 0 (a negative duration)
        }
        abortedByTest = true;
        budgetEnd = rt::kNever;
        return true;
    }
    bool abort = inner->onAttention();
    if (budgetEnd < machine->deadline.load(std::memory_order_relaxed)) machine->setDeadline(budgetEnd);
    return abort;
}

void FaultCapture::onFault(rt::DiagCode code, std::string_view pou, int line, std::string message, int file, int col) {
    TestRegistry& r = registry_;
    if (r.currentSuite < 0 || r.currentTest < 0 || code == rt::DiagCode::Overrun) {
        inner->onFault(code, pou, line, std::move(message), file, col);
        return;
    }
    TestCase& t = r.suites[static_cast<size_t>(r.currentSuite)].tests[static_cast<size_t>(r.currentTest)];
    if (t.skipped) {
        // A disabled test's code still runs (as in TcUnit); its faults count for nothing,
        // and a refused call (CALL_DEPTH) gives 0 and lets the suite go on (decision 0253).
        if (code == rt::DiagCode::CallDepth && ctx) ctx->aborting = false;
        return;
    }
    Failure f;
    // The statement's own file when the evaluator knows it, else the POU's.
    auto pouFile = r.pouFiles.find(std::string(pou));
    f.file = file >= 0 ? file : pouFile == r.pouFiles.end() ? -1 : pouFile->second;
    f.line = line;
    f.fault = fmt::format("{}: {}", rt::diagCodeName(code), message);
    bool wasIgnored = r.ignoreCurrent;
    r.ignoreCurrent = false;  // a fault after TEST_FINISHED in the same cycle still belongs to the test
    r.recordFailure(std::move(f));
    r.ignoreCurrent = wasIgnored;
    // CALL_DEPTH fails and finishes the test. The activation is not cut
    // short: the refused call gives 0, the nesting unwinds call by call and
    // the suite's code goes on, so the tests after this one still run in
    // this and every later cycle (decision 0253; cutting the activation
    // short every cycle starved them).
    if (code == rt::DiagCode::CallDepth) {
        t.finished = true;
        t.finishedAt = machine ? machine->time() : t.startedAt;
        if (ctx) ctx->aborting = false;
        else abortedByTest = true;
    }
}

}  // namespace strun::testing
