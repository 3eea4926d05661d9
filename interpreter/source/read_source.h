// Reading the source files named on the command line, within the input
// limits of docs/limits.md. One function, so that the rule "a directory is
// an error" can later become "a directory means every source under it".
#pragma once

#include <cstddef>
#include <string>

#include "interpreter/source/source_set.h"

namespace strun {

inline constexpr std::size_t kMaxSourceFileBytes = std::size_t{4} << 20;     // one file
inline constexpr std::size_t kMaxProjectSourceBytes = std::size_t{8} << 20;  // all files of a project together

// Adds `path` to `sources` (its index in `index`); false with `error` set when
// it cannot be read, is not a file, or would pass a size limit.
bool readSourceFile(const std::string& path, SourceSet& sources, int& index, std::string& error);

}  // namespace strun
