#include "cli/huge_page_restart.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <system_error>

#include <unistd.h>

#include "interpreter/source/project_inputs.h"

namespace strun::cli {

namespace {

namespace fs = std::filesystem;

// A directory walk stops after this many entries: the count is an estimate,
// and a huge tree must not delay every start.
constexpr int kWalkEntries = 20000;

std::uintmax_t folderBytes(const fs::path& dir, std::uintmax_t enough) {
    std::uintmax_t total = 0;
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
    int entries = 0;
    for (; !ec && it != fs::recursive_directory_iterator() && entries < kWalkEntries && total < enough; it.increment(ec), ++entries) {
        std::error_code fileEc;
        if (it->is_regular_file(fileEc) && source::isProjectSource(it->path().string())) {
            const std::uintmax_t size = it->file_size(fileEc);
            if (!fileEc) total += size;
        }
    }
    return total;
}

// The process runs under valgrind (its preload library is in the
// environment): valgrind would run the restarted image natively, outside
// the tool, so a profile of a large compile would measure nothing.
bool underValgrind() {
    const char* preload = std::getenv("LD_PRELOAD");
    return preload && std::strstr(preload, "vgpreload") != nullptr;
}

// The bytes of the regular files among `paths` and of the sources a
// directory among them contributes (source::isProjectSource); stops counting
// once `enough` is reached. Other arguments (options, their values) count nothing.
std::uintmax_t inputBytes(int count, char** paths, std::uintmax_t enough) {
    std::uintmax_t total = 0;
    for (int i = 0; i < count && total < enough; ++i) {
        std::error_code ec;
        const fs::path path(paths[i]);
        const fs::file_status status = fs::status(path, ec);
        if (ec) continue;  // an option, an option's value or a missing file
        if (fs::is_regular_file(status)) {
            const std::uintmax_t size = fs::file_size(path, ec);
            if (!ec) total += size;
        } else if (fs::is_directory(status)) {
            total += folderBytes(path, enough - total);
        }
    }
    return total;
}

}  // namespace

bool wantsHugePageRestart(int argc, char** argv) {
    if (argc < 3) return false;
    const std::string_view command = argv[1];
    if (command != "run" && command != "check" && command != "test") return false;
    if (std::getenv("GLIBC_TUNABLES") != nullptr || underValgrind()) return false;
    return inputBytes(argc - 2, argv + 2, kHugePageInputBytes) >= kHugePageInputBytes;
}

void restartWithHugePagesForLargeInputs(int argc, char** argv) {
#ifndef STRUN_SANITIZED  // the sanitizers' allocator is not glibc's
    if (!wantsHugePageRestart(argc, argv)) return;
    if (setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1) != 0) return;
    execv("/proc/self/exe", argv);
    unsetenv("GLIBC_TUNABLES");  // the restart failed (no /proc): go on as we are
#else
    (void)argc;
    (void)argv;
#endif
}

}  // namespace strun::cli
