// Arithmetic on durations, times of day and dates, shared by the ADD/SUB/
// MUL/DIV functions and the named ADD_TIME ... DIV_LTIME functions.
#pragma once

#include "interpreter/builtins/bind_support.h"

namespace strun::stdlib::bind {

enum class TimeOp { Add, Sub, Mul, Div };

// a OP b for the combinations IEC 61131-3 defines (Table 30 and its L-forms):
//   TIME +- TIME -> TIME, TOD +- TIME -> TOD, DT +- TIME -> DT, DATE - DATE -> TIME,
//   TOD - TOD -> TIME, DT - DT -> TIME, TIME */ ANY_NUM -> TIME (and TIME + TOD/DT, ANY_NUM * TIME).
// A long operand makes the result long (LTIME, LTOD, LDT). Reports an error otherwise.
Checked timeArithmetic(Checker& ck, const CallArgs& call, TimeOp op, Checked a, Checked b);

}  // namespace strun::stdlib::bind
