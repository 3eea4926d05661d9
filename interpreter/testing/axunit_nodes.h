// The resolved-tree nodes of AxUnit (SIMATIC AX's unit-test library, decision
// 0364): the comparisons behind AxUnit.Assert.Equal / NotEqual / LessThan /
// GreaterThan (stdlib/libraries/AxUnit), axunit_Fail and axunit_Succeed. The
// place of a failure is the file path and line the assertion received through
// its {CallerFilePath} / {CallerLineNumber} inputs, read when it fails.
#pragma once

#include <string>

#include "interpreter/testing/tcunit_nodes.h"

namespace strun::testing {

// Where an AxUnit failure is written: a STRING/WSTRING path and an integer line.
struct CallerPlace {
    Expr* file = nullptr;
    const sema::Type* fileType = nullptr;
    Expr* line = nullptr;
    void fill(Ctx& c, Failure& f) const;
};

struct AxCompareNode final : Expr {
    enum class Kind { Equal, NotEqual, Less, Greater };
    TestRegistry* reg = nullptr;
    Kind kind = Kind::Equal;
    Operand a, b;  // expected/actual, or left/right
    CallerPlace place;
    int64_t i(Ctx& c) override;
};

// axunit_Fail(message, file, line): the current test fails there.
struct AxFailNode final : Expr {
    TestRegistry* reg = nullptr;
    Expr* message = nullptr;
    const sema::Type* messageType = nullptr;
    CallerPlace place;
    int64_t i(Ctx& c) override;
};

}  // namespace strun::testing
