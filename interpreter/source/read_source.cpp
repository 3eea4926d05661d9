#include "interpreter/source/read_source.h"

#include <algorithm>
#include <cstdio>
#include <memory>

#include <sys/stat.h>

namespace strun {

namespace {
std::size_t projectBytes(const SourceSet& sources) {
    std::size_t total = 0;
    for (int k = 0; k < sources.size(); ++k) total += sources.file(k).text.size();
    return total;
}
}  // namespace

bool readSourceFile(const std::string& path, SourceSet& sources, int& index, std::string& error) {
    struct stat info {};
    if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
        error = "'" + path + "' is a directory, not a source file";
        return false;
    }
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) {
        error = "cannot open '" + path + "'";
        return false;
    }
    // Read at most one byte past the limit: a huge file, a device like
    // /dev/zero or an endless pipe stops there instead of exhausting memory.
    const std::size_t already = projectBytes(sources);
    const std::size_t room = already >= kMaxProjectSourceBytes ? 0 : kMaxProjectSourceBytes - already;
    const std::size_t limit = std::min(kMaxSourceFileBytes, room);
    std::string text;
    char buffer[65536];
    while (text.size() <= limit) {
        std::size_t n = std::fread(buffer, 1, sizeof buffer, file.get());
        if (n == 0) break;
        text.append(buffer, n);
    }
    if (std::ferror(file.get())) {
        error = "cannot read '" + path + "'";
        return false;
    }
    if (text.size() > limit) {
        error = limit == kMaxSourceFileBytes
                    ? "'" + path + "' is larger than the limit of " + std::to_string(kMaxSourceFileBytes >> 20) + " MiB per source file"
                    : "the source files together are larger than the limit of " + std::to_string(kMaxProjectSourceBytes >> 20) + " MiB";
        return false;
    }
    index = sources.add(path, std::move(text));
    return true;
}

}  // namespace strun
