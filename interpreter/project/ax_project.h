// SIMATIC AX projects: a folder with an `apax.yml` (AX's package file) holds
// one. Where AX and TwinCAT/CODESYS read the same ST text differently, strun
// follows AX for such a project (decision 0394).
#pragma once

#include <string>
#include <vector>

namespace strun::project {

// True when one of the source files `paths` lies in a folder that has an
// apax.yml, or below one. `<stdin>` and paths that do not exist count for nothing.
bool isAxProject(const std::vector<std::string>& paths);

}  // namespace strun::project
