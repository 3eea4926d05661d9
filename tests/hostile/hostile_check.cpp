// Hostile inputs too big to commit: each case generates its program in a
// temporary directory, runs strun on it, and checks the exit status, a
// stderr pattern, the wall time and the peak memory (docs/limits.md).
//   hostile_check STRUN CASE      one case (each is a ctest: hostile.CASE)
//   hostile_check --list          the case names
// STRUN_SLOW_FACTOR=N multiplies the time limits (sanitizer builds).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Case {
    std::string name;
    std::function<std::string()> program;  // empty result: no file (args name the input)
    std::vector<std::string> args;         // "@" is replaced by the generated file
    int exit;
    std::string stderrPattern;
    double maxSeconds;
    long maxMegabytes;
};

std::string chain(int n, const std::function<std::string(int)>& link, const std::string& tail) {
    std::string s;
    for (int i = 0; i < n; ++i) s += link(i);
    return s + tail;
}

const char* kDeep = "nested more than 1000 deep";

std::vector<Case> cases() {
    const std::string main = "PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM\n";
    return {
        {"struct_chain_10000",
         [] { return chain(10000, [](int i) { return "TYPE S" + std::to_string(i) + " : STRUCT a : INT; n : S" + std::to_string(i + 1) + "; END_STRUCT; END_TYPE\n"; },
                           "TYPE S10000 : STRUCT a : INT; END_STRUCT; END_TYPE\nPROGRAM Main VAR x : S0; END_VAR x.a := 1; END_PROGRAM\n"); },
         {"check", "@"}, 1, kDeep, 20, 1000},
        {"struct_chain_900_compiles",
         [] { return chain(900, [](int i) { return "TYPE S" + std::to_string(i) + " : STRUCT a : INT; n : S" + std::to_string(i + 1) + "; END_STRUCT; END_TYPE\n"; },
                           "TYPE S900 : STRUCT a : INT; END_STRUCT; END_TYPE\nPROGRAM Main VAR x : S0; END_VAR x.n.n.a := 1; END_PROGRAM\n"); },
         {"run", "--virtual", "--cycles", "1", "--dump", "@"}, 0, "", 20, 1000},
        {"alias_chain_10000",
         [] { return chain(10000, [](int i) { return "TYPE A" + std::to_string(i) + " : A" + std::to_string(i + 1) + "; END_TYPE\n"; },
                           "TYPE A10000 : INT; END_TYPE\nPROGRAM Main VAR x : A0; END_VAR x := 1; END_PROGRAM\n"); },
         {"check", "@"}, 1, kDeep, 20, 1000},
        {"array_chain_10000",
         [] { return chain(10000, [](int i) { return "TYPE A" + std::to_string(i) + " : ARRAY[0..0] OF A" + std::to_string(i + 1) + "; END_TYPE\n"; },
                           "TYPE A10000 : INT; END_TYPE\nPROGRAM Main VAR x : A0; END_VAR END_PROGRAM\n"); },
         {"check", "@"}, 1, kDeep, 20, 1000},
        {"fb_member_chain_10000",
         [] { return chain(10000, [](int i) { return "FUNCTION_BLOCK F" + std::to_string(i) + " VAR x : F" + std::to_string(i + 1) + "; END_VAR END_FUNCTION_BLOCK\n"; },
                           "FUNCTION_BLOCK F10000 END_FUNCTION_BLOCK\nPROGRAM Main VAR x : F0; END_VAR x(); END_PROGRAM\n"); },
         {"check", "@"}, 1, kDeep, 20, 1000},
        {"extends_chain_30000",
         [] { return chain(30000, [](int i) { return "FUNCTION_BLOCK F" + std::to_string(i) + " EXTENDS F" + std::to_string(i + 1) + " END_FUNCTION_BLOCK\n"; },
                           "FUNCTION_BLOCK F30000 END_FUNCTION_BLOCK\nPROGRAM Main VAR x : F0; END_VAR x(); END_PROGRAM\n"); },
         {"check", "@"}, 1, kDeep, 30, 1000},
        {"dump_100000_variables",
         [] { return "PROGRAM Main VAR\n" + chain(100000, [](int i) { return "v" + std::to_string(i) + " : INT;\n"; }, "END_VAR v1 := 1; END_PROGRAM\n"); },
         {"run", "--virtual", "--cycles", "1", "--dump", "@"}, 0, "", 20, 2000},
        {"tasks_20000",
         [] { return "CONFIGURATION C RESOURCE R ON PLC\n" +
                     chain(20000, [](int i) { return "TASK T" + std::to_string(i) + " (INTERVAL := T#1s, PRIORITY := 1);\n"; },
                           "PROGRAM P WITH T0 : Main;\nEND_RESOURCE END_CONFIGURATION\nPROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM\n"); },
         {"check", "@"}, 1, "at most 100 tasks", 10, 1000},
        {"file_over_size_limit",
         [main] { return main + std::string(5u << 20, ' '); },
         {"check", "@"}, 2, "larger than the limit of 4 MiB", 10, 500},
        {"too_many_tokens",
         [main] { return main + std::string(3000000, ';'); },
         {"check", "@"}, 1, "more than 2000000 tokens", 20, 1500},
        {"dev_zero_as_file", [] { return std::string(); }, {"check", "/dev/zero"}, 2, "is not a regular file", 10, 500},
        // A directory stands for every source under it (contract); one without any is exit 2.
        {"directory_as_file", [] { return std::string(); }, {"check", "/dev"}, 2, "contains no source files", 10, 500},
        {"fb_init_array_10_million",
         [] { return "FUNCTION_BLOCK F VAR v : INT; END_VAR\n"
                     "METHOD FB_init : BOOL VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR v := 1; END_METHOD\n"
                     "END_FUNCTION_BLOCK\nPROGRAM Main VAR a : ARRAY[0..10000000] OF F; END_VAR END_PROGRAM\n"; },
         {"run", "--virtual", "--cycles", "1", "@"}, 1, "instances of function blocks with FB_init", 20, 1500},
        {"never_called_function_with_huge_local",
         [] { return "FUNCTION Never : INT VAR big : ARRAY[0..50000000] OF WORD; END_VAR Never := 1; END_FUNCTION\n"
                     "PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM\n"; },
         {"run", "--virtual", "--cycles", "3", "@"}, 0, "", 10, 600},
    };
}

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

int runCase(const std::string& strun, const Case& c) {
    char dirTemplate[] = "/tmp/strun-hostile-XXXXXX";
    const char* dir = mkdtemp(dirTemplate);
    if (!dir) {
        std::cerr << "cannot create a temporary directory\n";
        return 2;
    }
    const std::string file = std::string(dir) + "/" + c.name + ".st";
    const std::string errFile = std::string(dir) + "/stderr.txt";
    if (std::string text = c.program(); !text.empty()) std::ofstream(file, std::ios::binary) << text;
    std::vector<std::string> args{strun};
    for (const auto& a : c.args) args.push_back(a == "@" ? file : a);
    double slow = 1;
    if (const char* f = std::getenv("STRUN_SLOW_FACTOR")) slow = std::max(1.0, std::atof(f));

    auto start = std::chrono::steady_clock::now();
    pid_t pid = fork();
    if (pid == 0) {
        std::freopen(errFile.c_str(), "w", stderr);
        std::freopen("/dev/null", "w", stdout);
        alarm(static_cast<unsigned>(c.maxSeconds * slow * 3) + 5);  // a hang is killed, and fails below
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    long megabytes = usage.ru_maxrss / 1024;
    std::string err = readAll(errFile);
    std::remove(file.c_str());
    std::remove(errFile.c_str());
    rmdir(dir);

    bool ok = true;
    std::cout << c.name << ": " << seconds << " s, " << megabytes << " MB peak\n";
    if (!WIFEXITED(status)) {
        std::cout << "  killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0) << "\n";
        ok = false;
    } else if (WEXITSTATUS(status) != c.exit) {
        std::cout << "  exit status " << WEXITSTATUS(status) << ", expected " << c.exit << "\n";
        ok = false;
    }
    if (!c.stderrPattern.empty() && err.find(c.stderrPattern) == std::string::npos) {
        std::cout << "  stderr lacks \"" << c.stderrPattern << "\"\n";
        ok = false;
    }
    if (err.find("internal") != std::string::npos || err.find("exception") != std::string::npos) {
        std::cout << "  stderr shows an internal error\n";
        ok = false;
    }
    if (seconds > c.maxSeconds * slow) {
        std::cout << "  took longer than " << c.maxSeconds * slow << " s\n";
        ok = false;
    }
    if (megabytes > c.maxMegabytes && slow == 1) {  // sanitizers inflate memory: checked in normal builds only
        std::cout << "  used more than " << c.maxMegabytes << " MB\n";
        ok = false;
    }
    if (!ok) std::cout << "---- stderr (first 2000 bytes)\n" << err.substr(0, 2000) << "\n";
    return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 2 && std::string(argv[1]) == "--list") {
        for (const auto& c : cases()) std::cout << c.name << "\n";
        return 0;
    }
    if (argc != 3) {
        std::cerr << "usage: hostile_check STRUN CASE | --list\n";
        return 2;
    }
    for (const auto& c : cases())
        if (c.name == argv[2]) return runCase(argv[1], c);
    std::cerr << "no case named '" << argv[2] << "'\n";
    return 2;
}
