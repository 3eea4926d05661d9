#include "cli/test_parallel.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace strun::cli {

namespace {

std::string makeTempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/strun-test-XXXXXX";
    if (!::mkdtemp(pattern.data())) return {};
    return pattern;
}

void copyFile(const std::string& path, std::ostream& out) {
    std::ifstream in(path, std::ios::binary);
    // Inserting an empty buffer sets failbit on `out`: std::cerr would then
    // swallow every later message (the next slice's, --junit errors).
    if (in && in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();
    out.flush();
}

}  // namespace

size_t processorCount() {
    unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : n;
}

std::vector<ChildSlice> runInChildren(size_t n, const std::function<int(size_t, const std::string&)>& body) {
    std::vector<ChildSlice> slices(n);
    for (auto& s : slices) {
        s.dir = makeTempDir();
        if (s.dir.empty()) {
            removeSliceDirs(slices);
            return {};
        }
    }
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::vector<pid_t> pids;
    for (size_t k = 0; k < n; ++k) {
        pid_t pid = ::fork();
        if (pid < 0) {
            // Too few processes: wait for the ones started, and let the caller run serially.
            for (pid_t p : pids) ::waitpid(p, nullptr, 0);
            removeSliceDirs(slices);
            return {};
        }
        if (pid == 0) {
            int out = ::open((slices[k].dir + "/stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
            int err = ::open((slices[k].dir + "/stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
            if (out < 0 || err < 0) ::_exit(1);
            ::dup2(out, 1);
            ::dup2(err, 2);
            int code = body(k, slices[k].dir);
            std::cout.flush();
            std::cerr.flush();
            std::fflush(nullptr);
            ::_exit(code);
        }
        pids.push_back(pid);
    }
    for (size_t k = 0; k < n; ++k) {
        int status = 0;
        while (::waitpid(pids[k], &status, 0) < 0 && errno == EINTR) {
        }
        slices[k].exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
        if (WIFSIGNALED(status)) std::cerr << "strun: the test process of slice " << k + 1 << " ended by signal " << WTERMSIG(status) << "\n";
    }
    for (const auto& s : slices) {
        copyFile(s.dir + "/stdout", std::cout);
        copyFile(s.dir + "/stderr", std::cerr);
    }
    return slices;
}

void removeSliceDirs(const std::vector<ChildSlice>& slices) {
    std::error_code ec;
    for (const auto& s : slices)
        if (!s.dir.empty()) std::filesystem::remove_all(s.dir, ec);
}

}  // namespace strun::cli
