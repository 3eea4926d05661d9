// Putting translated ST into an ST file in place of what it translates
// (textual SFC: st_textual_sfc.cpp, textual IL: st_textual_il.cpp): the
// translated spans are blanked, and every line of the result keeps its
// origin in the file, as for XML files.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "interpreter/source/plcopen_graphical.h"
#include "interpreter/source/xml_inputs.h"

namespace strun::source {

// Lines to put in at byte `at` of the file: a VAR section of the
// `declarations` (when there are any), then the `body`.
struct StSplice {
    size_t at = 0;
    std::vector<plcopen::StLine> declarations;
    std::vector<plcopen::StLine> body;
};

// `src` with the byte ranges `blanked` replaced by blanks (line breaks
// kept) and the splices put in at their places (in order of place; at one
// place, in the order given), into `result.text` and `result.origins`.
void spliceSt(const std::string& src, const std::vector<std::pair<size_t, size_t>>& blanked, std::vector<StSplice> splices,
              Converted& result);

}  // namespace strun::source
