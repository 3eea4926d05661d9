#include "interpreter/source/read_source.h"

#include <algorithm>
#include <cstdio>
#include <memory>

namespace strun {

bool readSourceText(const std::string& path, std::size_t projectBytes, std::string& text, std::string& error) {
    // "-" is standard input (not closed here).
    const bool standardInput = path == "-";
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> owned(standardInput ? nullptr : std::fopen(path.c_str(), "rb"), &std::fclose);
    std::FILE* const file = standardInput ? stdin : owned.get();
    if (!file) {
        error = "cannot open '" + path + "'";
        return false;
    }
    // Read at most one byte past the limit.
    const std::size_t room = projectBytes >= kMaxProjectSourceBytes ? 0 : kMaxProjectSourceBytes - projectBytes;
    const std::size_t limit = std::min(kMaxSourceFileBytes, room);
    text.clear();
    char buffer[65536];
    while (text.size() <= limit) {
        std::size_t n = std::fread(buffer, 1, sizeof buffer, file);
        if (n == 0) break;
        text.append(buffer, n);
    }
    if (std::ferror(file)) {
        error = "cannot read '" + path + "'";
        return false;
    }
    if (text.size() > limit) {
        error = limit == kMaxSourceFileBytes
                    ? "'" + path + "' is larger than the limit of " + std::to_string(kMaxSourceFileBytes >> 20) + " MiB per source file"
                    : "the source files together are larger than the limit of " + std::to_string(kMaxProjectSourceBytes >> 20) + " MiB";
        return false;
    }
    return true;
}

}  // namespace strun
