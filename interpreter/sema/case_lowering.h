// Lowering of a checked CASE to its node (interpreter/exec/case_nodes.h):
// the selector read inside the node when it is a plain INT/enumeration or
// DINT variable of the instance or frame and the labels fit a table
// (decision 0352).
#pragma once

#include "interpreter/exec/case_nodes.h"

namespace strun::sema {

// Builds the CASE node for `selector` and the filled `arms` (entries,
// blocks, ELSE) and finishes its branch table in place.
exec::Stmt* makeCaseNode(exec::NodePool& pool, exec::Expr* selector, exec::CaseArms&& arms);

}  // namespace strun::sema
