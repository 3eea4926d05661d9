// IEC 61131-3's edge-detecting inputs, `x : BOOL R_EDGE;` / `F_EDGE`, and
// names in real code such as `R_Edge : R_TRIG;`: the scanner reads R_EDGE
// and F_EDGE as names; this step makes one the keyword token only after a
// declaration's `: TYPE` and before its `;` or `:=` (decision 0339), so every
// other use stays a name.
#pragma once

#include <string_view>
#include <vector>

#include "interpreter/ast/st_scanner.h"

namespace strun::ast {

void resolveEdgeKeyword(std::string_view text, std::vector<ScannedToken>& tokens);

}  // namespace strun::ast
