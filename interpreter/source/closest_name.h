// "Did you mean ...?": the one edit-distance suggestion of strun, for a
// mistyped subcommand or option (cli/) and for names in diagnostics (sema/).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace strun {

// The candidate closest to `typed` by edit distance, or "" when none is
// close enough to be a plausible typo (at most a third of its length off).
std::string closestName(std::string_view typed, const std::vector<std::string>& candidates);

}  // namespace strun
