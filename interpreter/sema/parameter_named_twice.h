// A parameter named twice in one call (`fb(Execute := FALSE, Execute := TRUE)`,
// `LIMIT(MN := 0, MN := 1, IN := x, MX := 9)`): what TwinCAT compiles, so a
// warning W0044 by default and an error with --strict, the same for user POUs
// and standard functions (decisions 0350, 0426).
#pragma once

#include <string>

#include "interpreter/sema/checker.h"

namespace strun::sema {

// Reports `twice` ("parameter 'X' given twice") as W0044; false when --strict
// made it an error.
bool acceptNamedTwice(Checker& ck, const ast::Loc& loc, const std::string& twice);

// For the bindings of standard functions, whose inputs are values in one slot
// each: reports `formal` of the call given again at `loc` and puts `later` in
// `slot`. An earlier value that calls something is kept in `call.replaced`, to
// be evaluated before the function (sequenceReplaced). False when it was an error.
bool rebindNamedTwice(Checker& ck, CallArgs& call, const ast::Loc& loc, const std::string& formal, Checked& slot,
                      const Checked& later, const std::string& callee = "");

// The standard function's result `r`, evaluated after the earlier values in
// `call.replaced` (in the order written), so their calls still run, as a user
// POU's arguments named twice all do.
void sequenceReplaced(Checker& ck, const CallArgs& call, Checked& r);

}  // namespace strun::sema
