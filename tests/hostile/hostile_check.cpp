// Hostile inputs too big to commit: each case generates its program in a
// temporary directory, runs strun on it, and checks the exit status, a
// stderr pattern, the wall time and the peak memory (docs/limits.md).
// A case with `runs` > 1 runs the same command again (a --retain file
// saved by one run is read by the next). A case with `growth` also runs
// the program made for a tenth of its size and checks that the user CPU
// time grows linearly, not quadratically: a behaviour, not a speed (issue 30).
//   hostile_check STRUN CASE      one case (each is a ctest: hostile.CASE)
//   hostile_check --list          the case names
// STRUN_SLOW_FACTOR=N multiplies the time limits (sanitizer builds).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
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
    int runs = 1;
    std::function<std::string(int)> growth = {};  // the program for size n; `program` is growth(kGrowthSize)
};

constexpr int kGrowthSize = 100000;
constexpr int kGrowthStep = 10;         // the small run is a tenth of the size
constexpr double kGrowthLimit = 30;     // between linear (10) and quadratic (100)

// A program of `n` generated pieces between a head and a tail.
std::string generated(const std::string& head, int n, const std::function<std::string(int)>& piece, const std::string& tail) {
    std::string s = head;
    for (int i = 0; i < n; ++i) s += piece(i);
    return s + tail;
}

// Each name-matching class of the checker at n: enumeration values (declared, qualified, as an initial value),
// structure members (declared, initialised by name, accessed), named arguments of a block and a function,
// program instances of a configuration.
std::string manyEnumValues(int n) {
    std::string uses;
    for (int i = 0; i < 1000; ++i) uses += "x := E#v" + std::to_string(i * (n / 1000)) + "; x := E.v" + std::to_string(n - 1 - i) + ";\n";
    return generated("TYPE E : (", n, [](int i) { return (i ? ", v" : "v") + std::to_string(i); },
                     "); END_TYPE\nPROGRAM Main VAR x : E := v" + std::to_string(n - 1) + "; END_VAR\n" + uses + "END_PROGRAM\n");
}
std::string manyMembers(int n) {
    std::string uses;
    for (int i = 0; i < 1000; ++i) uses += "s.m" + std::to_string(n - 1 - i) + " := " + std::to_string(i) + ";\n";
    return generated("TYPE S : STRUCT\n", n, [](int i) { return "m" + std::to_string(i) + " : INT := 1;\n"; },
                     "END_STRUCT END_TYPE\nPROGRAM Main VAR s : S := (m" + std::to_string(n - 1) + " := 2, m0 := 3); END_VAR\n" + uses +
                         "END_PROGRAM\n");
}
std::string manyNamedArguments(int n) {
    std::string head = generated("FUNCTION_BLOCK F VAR_INPUT\n", n, [](int i) { return "a" + std::to_string(i) + " : INT;\n"; },
                                 "END_VAR END_FUNCTION_BLOCK\nPROGRAM Main VAR f : F; END_VAR\nf(");
    // Named in reverse order (a scan from the first parameter finds each last), the last one positional
    // after the named ones (it binds by its position, decision 0204: the last input, a(n-1)).
    return generated(head, n - 1, [n](int i) { return "a" + std::to_string(n - 2 - i) + " := 1, "; }, "2);\nEND_PROGRAM\n");
}
std::string manyProgramInstances(int n) {
    return generated("PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM\nCONFIGURATION C RESOURCE R ON PLC\n"
                     "TASK T (INTERVAL := T#1s, PRIORITY := 1);\n",
                     n, [](int i) { return "PROGRAM P" + std::to_string(i) + " WITH T : Main;\n"; }, "END_RESOURCE END_CONFIGURATION\n");
}

std::string chain(int n, const std::function<std::string(int)>& link, const std::string& tail) {
    std::string s;
    for (int i = 0; i < n; ++i) s += link(i);
    return s + tail;
}

const char* kDeep = "nested more than 1000 deep";

std::vector<Case> cases() {
    const std::string main = "PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM\n";
    auto grown = [](std::function<std::string(int)> g) { return [g] { return g(kGrowthSize); }; };
    return {
        // Issue 30: names matched through hashed, once-folded tables.
        {"enum_100000_values", grown(manyEnumValues), {"check", "@"}, 0, "", 60, 1500, 1, manyEnumValues},
        {"struct_100000_members", grown(manyMembers), {"check", "@"}, 0, "", 60, 1500, 1, manyMembers},
        {"named_arguments_100000", grown(manyNamedArguments), {"check", "@"}, 0, "", 60, 1500, 1, manyNamedArguments},
        {"program_instances_100000", grown(manyProgramInstances), {"check", "@"}, 0, "", 60, 2000, 1, manyProgramInstances},
        // `[N(x)]` checks x once: 50 million DINT (200 MB) without a node per element.
        {"array_initialiser_50_million",
         [] { return std::string("PROGRAM Main VAR a : ARRAY[0..49999999] OF DINT := [50000000(7)]; s : DINT; END_VAR\n"
                                 "s := a[0] + a[49999999]; END_PROGRAM\n"); },
         {"run", "--virtual", "--cycles", "1", "@"}, 0, "", 60, 900},
        // --vcd of ten million array elements: a bounded number recorded, scope names shared.
        {"vcd_10_million_elements",
         [] { return std::string("PROGRAM Main VAR a : ARRAY[0..9999999] OF BYTE; END_VAR a[0] := a[0] + 1; END_PROGRAM\n"); },
         {"run", "--virtual", "--cycles", "2", "--vcd", "@.vcd", "@"}, 0, "more than 100000 variables to record", 60, 400},
        // A 64 MiB RETAIN array saved and read back in pieces: never its hex text whole in memory
        // (the run itself holds about 200 MB: the instance and its initial image; the restore adds one value's buffer).
        {"retain_64_mib_array",
         [] { return std::string("PROGRAM Main VAR RETAIN a : ARRAY[0..16777215] OF DINT; END_VAR a[16777215] := a[16777215] + 1; END_PROGRAM\n"); },
         {"run", "--virtual", "--cycles", "1", "--retain", "@.retain", "@"}, 0, "", 120, 300, 2},
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

struct Outcome {
    int status = 0;
    double seconds = 0;
    double userSeconds = 0;  // the algorithm's own time: the kernel's page handling (system time) varies too much from run to run
    long megabytes = 0;
    std::string err;
};
Outcome runOnce(const std::vector<std::string>& args, const std::string& errFile, double maxSeconds);
bool check(const Case& c, const Outcome& o, double slow, int run);

int runCase(const std::string& strun, const Case& c) {
    char dirTemplate[] = "/tmp/strun-hostile-XXXXXX";
    const char* dir = mkdtemp(dirTemplate);
    if (!dir) {
        std::cerr << "cannot create a temporary directory\n";
        return 2;
    }
    const std::string file = std::string(dir) + "/" + c.name + ".st";
    const std::string errFile = std::string(dir) + "/stderr.txt";
    std::vector<std::string> args{strun};
    for (const auto& a : c.args) args.push_back(a.rfind('@', 0) == 0 ? file + a.substr(1) : a);  // "@.vcd": beside the program
    double slow = 1;
    if (const char* f = std::getenv("STRUN_SLOW_FACTOR")) slow = std::max(1.0, std::atof(f));

    bool ok = true;
    // The smallest user time of three runs of the tenth: a run disturbed by the machine is never the baseline.
    double userTenth = 0;
    if (c.growth) {
        std::ofstream(file, std::ios::binary | std::ios::trunc) << c.growth(kGrowthSize / kGrowthStep);
        for (int run = 0; run < 3; ++run) {
            const double user = runOnce(args, errFile, c.maxSeconds * slow).userSeconds;
            userTenth = run == 0 ? user : std::min(userTenth, user);
        }
    }
    if (std::string text = c.program(); !text.empty()) std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    Outcome o;
    for (int run = 0; run < c.runs && ok; ++run) {
        o = runOnce(args, errFile, c.maxSeconds * slow);
        ok = check(c, o, slow, run);
    }
    if (ok && c.growth) {
        // Linear: ten times the size costs about ten times the CPU (less: start-up is shared); quadratic: a hundred.
        // The limit sits between the two, a factor of three from each; a full-size run over it is run once more.
        double user = o.userSeconds;
        auto ratio = [&] { return userTenth > 0 ? user / userTenth : 0; };
        if (ratio() > kGrowthLimit) user = std::min(user, runOnce(args, errFile, c.maxSeconds * slow).userSeconds);
        std::cout << "  user CPU " << userTenth << " s at " << kGrowthSize / kGrowthStep << ", " << user << " s at " << kGrowthSize << " (x"
                  << ratio() << ")\n";
        if (user > 0.5 * slow && ratio() > kGrowthLimit) {
            std::cout << "  grows faster than linearly\n";
            ok = false;
        }
    }
    std::filesystem::remove_all(dir);
    return ok ? 0 : 1;
}

}  // namespace

namespace {

Outcome runOnce(const std::vector<std::string>& arguments, const std::string& errFile, double maxSeconds) {
    std::vector<std::string> args = arguments;
    std::cout.flush();  // else the child's freopen of stdout writes the parent's pending lines a second time
    auto start = std::chrono::steady_clock::now();
    pid_t pid = fork();
    if (pid == 0) {
        std::freopen(errFile.c_str(), "w", stderr);
        std::freopen("/dev/null", "w", stdout);
        alarm(static_cast<unsigned>(maxSeconds * 3) + 5);  // a hang is killed, and fails below
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    Outcome o;
    rusage usage{};
    wait4(pid, &o.status, 0, &usage);
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    o.userSeconds = double(usage.ru_utime.tv_sec) + double(usage.ru_utime.tv_usec) / 1e6;
    o.megabytes = usage.ru_maxrss / 1024;
    o.err = readAll(errFile);
    return o;
}

bool check(const Case& c, const Outcome& o, double slow, int run) {
    const int status = o.status;
    const double seconds = o.seconds;
    const long megabytes = o.megabytes;
    const std::string& err = o.err;
    bool ok = true;
    std::cout << c.name << (run ? " (run " + std::to_string(run + 1) + ")" : std::string()) << ": " << seconds << " s, " << megabytes
              << " MB peak\n";
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
    return ok;
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
