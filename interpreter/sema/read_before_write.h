// W0017: a FUNCTION's or METHOD's local variable read before it is ever
// written. The rule (decision 0162) is deliberately conservative, so a
// warning is always a real read of the initial value:
//   - candidates: VAR / VAR_TEMP of an elementary type with no initial value;
//   - statements are followed in order; a write inside one IF/CASE branch is
//     seen by the rest of that branch, and after the statement the variable
//     counts as (maybe) written; a loop body starts with everything the loop
//     writes as written (a later iteration may read it);
//   - a variable passed to a call as a bare argument may be written by the
//     callee (VAR_IN_OUT, ADR) and counts as written, not read;
//   - a POU with a label (JMP) is not analysed.
#pragma once

#include "interpreter/sema/symbols.h"
#include "interpreter/source/source_set.h"

namespace strun::sema {

void warnReadBeforeWrite(const PouInfo& pou, CompileLog& log);

}  // namespace strun::sema
