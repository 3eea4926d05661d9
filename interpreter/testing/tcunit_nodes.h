// The resolved-tree nodes of the TcUnit API: TEST / TEST_ORDERED /
// TEST_FINISHED / TEST_FINISHED_NAMED / IS_TEST_FINISHED / RUN /
// RUN_IN_SEQUENCE / TCUNIT_ADSLOGSTR and the assertions. They act on the
// project's TestRegistry. A passing assertion reads its operands and compares
// them, nothing more: no allocation unless it fails.
#pragma once

#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/exec/node.h"
#include "interpreter/testing/test_registry.h"

namespace strun::testing {

using exec::Ctx;
using exec::Expr;

// A STRING / WSTRING operand seen as characters (WSTRING: its UTF-8 text, built on demand).
std::string_view stringArg(Expr* e, const sema::Type* t, Ctx& c, std::string& scratch);

struct BeginTestNode final : Expr {
    TestRegistry* reg = nullptr;
    Expr* name = nullptr;
    const sema::Type* nameType = nullptr;
    bool ordered = false;
    std::string scratch;
    std::vector<int> hints;  // per suite: the index of the test this call registered (sized at the first call)
    int64_t i(Ctx& c) override {
        int* hint = nullptr;
        if (reg->currentSuite >= 0) {
            if (hints.size() != reg->suites.size()) hints.assign(reg->suites.size(), -1);
            hint = &hints[static_cast<size_t>(reg->currentSuite)];
        }
        return reg->beginTest(stringArg(name, nameType, c, scratch), ordered, c.m->time(), hint);
    }
};

struct FinishTestNode final : Expr {
    TestRegistry* reg = nullptr;
    int64_t i(Ctx& c) override { return reg->finishCurrent(c.m->time()); }
};

struct FinishNamedTestNode final : Expr {
    TestRegistry* reg = nullptr;
    Expr* name = nullptr;
    const sema::Type* nameType = nullptr;
    std::string scratch;
    int64_t i(Ctx& c) override { return reg->finishNamed(stringArg(name, nameType, c, scratch), c.m->time()); }
};

struct IsTestFinishedNode final : Expr {
    TestRegistry* reg = nullptr;
    Expr* name = nullptr;
    const sema::Type* nameType = nullptr;
    std::string scratch;
    int64_t i(Ctx& c) override { return reg->isFinished(stringArg(name, nameType, c, scratch)); }
};

struct RunSuitesNode final : Expr {
    TestRegistry* reg = nullptr;
    bool inSequence = false;
    Expr* pause = nullptr;  // RUN_IN_SEQUENCE(TimeBetweenTestSuitesExecution); null: none
    int64_t scale = 1;      // to nanoseconds
    int64_t i(Ctx& c) override {
        // RUN_IN_SEQUENCE() pauses GVL_Param_TcUnit.TimeBetweenTestSuitesExecution.
        reg->runSuites(c, inSequence, pause ? pause->i(c) * scale : reg->timeBetweenSuites);
        return 0;
    }
};

// AWAIT_ASSERTIONS(AwaitTime) and TIMEOUT_FOR_EACH_TEST(Timeout): a TIME
// (milliseconds) or LTIME (nanoseconds) operand.
struct AwaitAssertionsNode final : Expr {
    TestRegistry* reg = nullptr;
    Expr* duration = nullptr;
    int64_t scale = 1;  // to nanoseconds
    int64_t i(Ctx& c) override {
        reg->awaitAssertions(duration->i(c) * scale, c.m->time());
        return 0;
    }
};

struct TestTimeoutNode final : Expr {
    TestRegistry* reg = nullptr;
    Expr* duration = nullptr;
    int64_t scale = 1;
    int64_t i(Ctx& c) override {
        int64_t t = duration->i(c) * scale;
        reg->setTestTimeout(t > 0 ? t : 0);
        return 0;
    }
};

// FB_TestSuite's query methods (stdlib/st/tcunit.st) ask about the suite at
// THIS: how many tests it has, failed, skipped, successful; whether all (or
// one named) finished.
struct SuiteQueryNode final : Expr {
    enum class What { Tests, Failed, Skipped, Successful, AllFinished, TestFinished };
    TestRegistry* reg = nullptr;
    Expr* self = nullptr;  // POINTER TO the suite instance
    What what = What::Tests;
    Expr* name = nullptr;  // TestFinished
    const sema::Type* nameType = nullptr;
    std::string scratch;
    int64_t i(Ctx& c) override;
};

// TCUNIT_ADSLOGSTR(msgCtrlMask, msgFmtStr, strArg): the message, %s replaced by strArg, on stderr.
struct AdsLogNode final : Expr {
    TestRegistry* reg = nullptr;  // GVL_Param_TcUnit.LogExtendedResults
    Expr* mask = nullptr;         // msgCtrlMask; null: 0
    Expr* format = nullptr;
    const sema::Type* formatType = nullptr;
    Expr* arg = nullptr;
    const sema::Type* argType = nullptr;
    int64_t i(Ctx& c) override;
};

// What every assertion knows: where it is written and its message.
struct AssertBase : Expr {
    TestRegistry* reg = nullptr;
    int file = -1;
    int line = 0;
    Expr* message = nullptr;  // null: ''
    const sema::Type* messageType = nullptr;
    void fail(Ctx& c, std::string expected, std::string actual, const char* messageSuffix = "");
    // Counts this evaluation among the suite's assertion records (GVL_Param_TcUnit.
    // MaxNumberOfAssertsForEachTestSuite); `values` hashes what it compared.
    void note(Ctx& c, uint64_t values);
};

// FNV-1a over `n` bytes, continuing `h`: what an assertion compared, for note().
uint64_t hashBytes(uint64_t h, const void* p, size_t n);

// AssertTrue / AssertFalse.
struct AssertConditionNode final : AssertBase {
    Expr* condition = nullptr;
    bool expected = true;
    int64_t i(Ctx& c) override;
};

// One operand of an assertion: its value as the bytes of its type.
struct Operand {
    Expr* e = nullptr;
    const sema::Type* t = nullptr;
    // Scalars are stored into `buf` as their type stores them; aggregates are read in place.
    const uint8_t* load(Ctx& c, uint8_t* buf) const;
};

// AssertEquals_<TYPE> (Delta for REAL/LREAL) and the generic AssertEquals.
struct AssertEqualsNode final : AssertBase {
    Operand expected, actual;
    Expr* delta = nullptr;  // REAL/LREAL: maximum |Expected - Actual|; null: exact
    bool generic = false;   // AssertEquals(ANY): type class and size are compared first
    int64_t i(Ctx& c) override;
};

// AssertArrayEquals_<TYPE>, AssertArray2dEquals_<TYPE>, AssertArray3dEquals_<TYPE>.
struct ArrayOperand {
    Expr* place = nullptr;    // the array (fixed bounds), or
    Expr* desc = nullptr;     // an ARRAY[*] parameter's descriptor { address, lo0, hi0, ... }
    std::vector<int64_t> lo, hi;  // fixed bounds
    // Base address and bounds now; false when the dimension count differs.
    uint8_t* resolve(Ctx& c, size_t dims, int64_t* los, int64_t* his) const;
};

struct AssertArrayNode final : AssertBase {
    ArrayOperand expected, actual;
    const sema::Type* elem = nullptr;
    size_t dims = 1;
    Expr* delta = nullptr;
    int64_t i(Ctx& c) override;
};

}  // namespace strun::testing
