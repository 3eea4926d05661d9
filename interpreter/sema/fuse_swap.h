// Swaps of two array elements through a temporary, fused into one node
// (interpreter/exec/swap_nodes.h, decision 0379).
#pragma once

#include "interpreter/exec/stmt_nodes.h"

namespace strun::sema {

// Replaces every run of three statements of `block`
//     t := a[i + k1]; a[i + k1] := a[i + k2]; a[i + k2] := t;
// (a, i, t variables of the instance or frame, i a DINT, t and the
// elements of one type) by one SwapElems that stands for the three. A block
// with labels is left alone (the labels index its statements).
void fuseSwaps(exec::NodePool& pool, exec::Block& block);

}  // namespace strun::sema
