// IEC 61131-3's edge-detecting inputs (decision 0339): a function block or
// program input declared `x : BOOL R_EDGE;` (or F_EDGE) is TRUE in the body
// only on the call at which the value passed in rose (fell), "as if" the
// block held an R_TRIG (F_TRIG) on it. The input itself keeps the value the
// caller passed (an unconnected input keeps it from call to call, so it
// cannot be overwritten with the edge); the body reads the edge instead.
#pragma once

#include <string>

#include "interpreter/ast/ast.h"

namespace strun::sema {

// The hidden R_TRIG/F_TRIG instance that detects the edges of input `input`:
// a name no source can write.
std::string edgeTriggerName(const std::string& input);

// For each BOOL R_EDGE / F_EDGE input of `pou` (a FUNCTION_BLOCK or PROGRAM;
// declarations elsewhere are the checker's error): declares the hidden
// trigger, calls it with the input first thing in the body, and makes the
// body's reads of the input read the trigger's Q. Methods and actions see
// the input as passed. Done once per parse (idempotent).
void lowerEdgeInputs(ast::Pou& pou);

}  // namespace strun::sema
