#include "runtime/output_files.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace strun::rt {

int openRegularInput(const std::string& path, std::string& error) {
    int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        error = "cannot open '" + path + "': " + std::strerror(errno);
        return -1;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        error = "'" + path + "' is not a regular file";
        return -1;
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    return fd;
}

std::FILE* openRegularOutput(const std::string& path, std::string& error) {
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_NONBLOCK | O_CLOEXEC | O_NOCTTY, 0644);
    if (fd < 0) {
        error = "cannot write '" + path + "': " + std::strerror(errno);
        return nullptr;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        error = "'" + path + "' is not a regular file";
        return nullptr;
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    std::FILE* file = ::ftruncate(fd, 0) == 0 ? ::fdopen(fd, "wb") : nullptr;
    if (!file) {
        error = "cannot write '" + path + "': " + std::strerror(errno);
        ::close(fd);
    }
    return file;
}

bool sameFile(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    const bool hasA = ::stat(a.c_str(), &sa) == 0, hasB = ::stat(b.c_str(), &sb) == 0;
    if (hasA && hasB) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    if (hasA || hasB) return false;
    // Neither exists yet (two outputs of one run): the same path once `.`, `..` and links are resolved.
    std::error_code ea, eb;
    const auto pa = std::filesystem::weakly_canonical(a, ea), pb = std::filesystem::weakly_canonical(b, eb);
    return !ea && !eb && pa == pb;
}

std::string outputPathProblem(const std::string& option, const std::string& path, const std::vector<std::string>& inputs) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        // A new file (a missing directory shows when it is created), unless another output of the run is it.
        if (errno != ENOENT) return option + ": cannot use '" + path + "': " + std::strerror(errno);
    } else if (!S_ISREG(st.st_mode))
        return option + ": '" + path + "' exists and is not a regular file (" +
               (S_ISDIR(st.st_mode) ? "a directory" : S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISSOCK(st.st_mode) ? "a socket" : "a device") +
               "); strun writes only regular files";
    for (const std::string& in : inputs)
        if (sameFile(path, in)) return option + ": '" + path + "' is an input of this run ('" + in + "'); strun never writes over its inputs";
    return {};
}

}  // namespace strun::rt
