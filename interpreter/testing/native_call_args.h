// What the test libraries' natives (TcUnit, AxUnit) share when the checker
// binds a call of one: its arguments by position or name and its result.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "interpreter/sema/checker.h"

namespace strun::testing::native_call {

struct Param {
    const char* name;  // as the library spells it; matched in any case
    bool required;
};

// The function's name as written in the call (CallArgs::name is upper case).
std::string written(const sema::CallArgs& call);

// Binds the arguments positional in order or by name (any case); a
// parameter a call leaves out keeps its default unless it is required.
// `out[k].ok` is false for a parameter not given. Errors are reported.
bool bindArgs(sema::Checker& ck, sema::CallArgs& call, std::initializer_list<Param> params, std::vector<sema::Checked>& out);

// The call's result: `node`, of the elementary type `kind`.
sema::Checked result(sema::Checker& ck, exec::Expr* node, sema::TK kind, const sema::CallArgs& call);

}  // namespace strun::testing::native_call
