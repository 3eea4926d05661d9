// Reads the FILEs of a command line into one SourceSet.
#pragma once

#include <string>
#include <vector>

#include "interpreter/source/source_set.h"

namespace strun::cli {

// False (with `error` set) when a file cannot be read.
bool readSourceFiles(const std::vector<std::string>& paths, SourceSet& sources, std::vector<int>& indices, std::string& error);

}  // namespace strun::cli
