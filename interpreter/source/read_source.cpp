#include "interpreter/source/read_source.h"

#include <algorithm>
#include <cstdio>
#include <memory>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace strun {

bool readSourceText(const std::string& path, std::size_t projectBytes, std::string& text, std::string& error) {
    // "-" is standard input (not closed here). Any other path is opened without
    // blocking and checked to be a regular file (decision 0250): a FIFO put where
    // a source was (after the command line was checked) is refused, never waited on.
    const bool standardInput = path == "-";
    const int fd = standardInput ? -1 : ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    struct stat st {};
    if (fd >= 0 && (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))) {
        ::close(fd);
        error = "'" + path + "' is not a regular file";
        return false;
    }
    if (fd >= 0) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> owned(fd >= 0 ? ::fdopen(fd, "rb") : nullptr, &std::fclose);
    std::FILE* const file = standardInput ? stdin : owned.get();
    if (!file) {
        if (fd >= 0) ::close(fd);
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
