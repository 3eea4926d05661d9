// Reading one source file within the input limits of docs/limits.md: a
// huge file, a device like /dev/zero or an endless pipe stops at the limit
// instead of exhausting memory. project_inputs.cpp reads every file of a
// project (named or found under a directory) through it.
#pragma once

#include <cstddef>
#include <string>

namespace strun {

inline constexpr std::size_t kMaxSourceFileBytes = std::size_t{4} << 20;     // one file
inline constexpr std::size_t kMaxProjectSourceBytes = std::size_t{8} << 20;  // all files of a project together

// Reads `path` into `text`, given that the project's files read so far hold
// `projectBytes`; false with `error` set when it cannot be read or would pass
// a size limit.
bool readSourceText(const std::string& path, std::size_t projectBytes, std::string& text, std::string& error);

}  // namespace strun
