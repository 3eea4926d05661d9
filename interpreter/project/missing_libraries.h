// One message per library a TwinCAT project references and strun does not
// provide (decision 0279): "library Tc2_MC2 is not available: AXIS_REF,
// MC_Power are unknown", instead of one error per name the project takes from it.
#pragma once

#include <string>
#include <vector>

#include "interpreter/source/source_set.h"

namespace strun::project {

// Merges the checker's errors about names that come from one of `referenced`
// (the .plcproj's libraries) that strun does not provide into one error per
// library, at the first of them. Errors about other names are untouched.
void groupMissingLibraryNames(CompileLog& log, const std::vector<std::string>& referenced);

// Says, under an "unknown type" error about a global data type a .plcproj
// pins (`pinned`), where TwinCAT keeps it and what strun needs to read it
// (decision 0447).
void explainPinnedTypes(CompileLog& log, const std::vector<std::string>& pinned);

}  // namespace strun::project
