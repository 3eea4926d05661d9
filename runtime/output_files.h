// The file rules every command follows for the files strun reads and writes
// (docs/cli.md "Files strun reads and writes", decision 0250):
// - an input is read only when it is a regular file: a FIFO, device or
//   socket is refused at once instead of blocking or reading without end;
// - an output path that exists must be a regular file (nothing is ever
//   written into or renamed over a device, FIFO, socket or directory);
// - an output never names one of the run's inputs (like a compiler that
//   refuses to write its output over its source).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace strun::rt {

// Opens `path` for reading when it is a regular file; -1 with `error` set
// ("'P' is not a regular file", "cannot open 'P': ...") otherwise. The open
// itself never blocks (O_NONBLOCK, cleared again once it is known regular).
int openRegularInput(const std::string& path, std::string& error);

// Empty when `path` may be written by an option named `option` ("--vcd"):
// it does not exist yet or is a regular file, and it is none of `inputs`.
// Otherwise the one-line reason, starting with the option.
std::string outputPathProblem(const std::string& option, const std::string& path, const std::vector<std::string>& inputs);

// Creates or truncates `path` for writing, only when it is (or becomes) a
// regular file: nullptr with `error` set otherwise. Never blocks on a FIFO.
std::FILE* openRegularOutput(const std::string& path, std::string& error);

// True when both paths name the same existing file (device and inode), or
// neither exists and both resolve to the same path.
bool sameFile(const std::string& a, const std::string& b);

}  // namespace strun::rt
