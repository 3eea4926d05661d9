// conformance_check: runs one conformance program through the strun CLI and
// compares the outcome with its expectation files (.json dump subset, .err stderr patterns,
// .trace exact --trace lines, .out exact `strun test` stdout; format: tests/conformance/README.md).
//
//   conformance_check <strun-binary> <file.st>   exit 0 = pass, 1 = fail, 2 = bad usage/test
//   conformance_check --self-test                checks the comparison logic itself
//
// strun is started with fork/exec (no shell, so no quoting problems); its stdout
// and stderr go to temporary files, so a chatty child can never block on a pipe.
// A run longer than 30 s is killed and reported as a timeout.
#include <nlohmann/json.hpp>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using nlohmann::json;

constexpr int kTimeoutSeconds = 30;
constexpr double kRelativeTolerance = 1e-6;

// ---------------------------------------------------------------- directives

struct Directives {
    std::vector<std::string> args{"run", "--virtual", "--cycles", "1", "--dump"};
    std::optional<int> exit;  // unset: 0, or 1 when a .err expectation exists
    bool appendDump = true;   // `dump: no`: a `run` without --dump (the human summary)
    bool appendFile = true;   // `file: no`: the program path is not appended (`--version`, `help`)
};

// `{dir}` in an argument stands for the directory of the program (a stimulus
// file next to it), `{file}` for the program's path.
std::string expandTokens(std::string arg, const std::string& programPath, const std::string& vcdPath = "") {
    const auto slash = programPath.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : programPath.substr(0, slash);
    for (const auto& [token, value] :
         {std::pair<std::string, std::string>{"{dir}", dir}, {"{file}", programPath}, {"{vcd}", vcdPath}})
        for (std::size_t at; (at = arg.find(token)) != std::string::npos;) arg.replace(at, token.size(), value);
    return arg;
}

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
}

std::vector<std::string> splitWords(const std::string& s) {
    std::istringstream in(s);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

// The directive block is the file's first comment, when it starts with `strun-test`:
//   (* strun-test
//      args: run --virtual --cycles 3
//      exit: 0
//   *)
// Returns an error message for a malformed block.
std::optional<std::string> parseDirectives(const std::string& source, Directives& out) {
    const auto start = source.find_first_not_of(" \t\r\n");
    if (start == std::string::npos || source.compare(start, 2, "(*") != 0) return std::nullopt;
    const auto end = source.find("*)", start + 2);
    if (end == std::string::npos) return std::nullopt;  // unterminated: the compiler's problem
    std::istringstream body(source.substr(start + 2, end - start - 2));
    std::string line;
    bool first = true;
    while (std::getline(body, line)) {
        line = trim(line);
        if (first) {
            if (line.empty()) continue;
            first = false;
            if (line != "strun-test") return std::nullopt;  // an ordinary comment
            continue;
        }
        if (line.empty()) continue;
        const auto colon = line.find(':');
        if (colon == std::string::npos) return "directive line without ':': " + line;
        const std::string key = trim(line.substr(0, colon));
        const std::string value = trim(line.substr(colon + 1));
        if (key == "args") {
            out.args = splitWords(value);
            if (out.args.empty()) return "empty 'args' directive";
        } else if (key == "dump" || key == "file") {
            if (value != "no" && value != "yes") return "bad '" + key + "' directive (yes or no): " + value;
            (key == "dump" ? out.appendDump : out.appendFile) = value == "yes";
        } else if (key == "exit") {
            char* rest = nullptr;
            const long code = std::strtol(value.c_str(), &rest, 10);
            if (value.empty() || *rest != '\0' || code < 0 || code > 255)
                return "bad 'exit' directive: " + value;
            out.exit = static_cast<int>(code);
        } else {
            return "unknown directive '" + key + "'";
        }
    }
    return std::nullopt;
}

// ---------------------------------------------------------------- JSON subset match

bool numbersMatch(const json& expected, const json& actual) {
    const bool bothIntegers = expected.is_number_integer() && actual.is_number_integer();
    if (bothIntegers) {
        // Compare in the widest signed/unsigned form so ULINT and LINT extremes are exact.
        if (expected.is_number_unsigned() && actual.is_number_unsigned())
            return expected.get<std::uint64_t>() == actual.get<std::uint64_t>();
        if (expected.is_number_unsigned() || actual.is_number_unsigned()) {
            const json& u = expected.is_number_unsigned() ? expected : actual;
            const json& s = expected.is_number_unsigned() ? actual : expected;
            const auto sv = s.get<std::int64_t>();
            return sv >= 0 && static_cast<std::uint64_t>(sv) == u.get<std::uint64_t>();
        }
        return expected.get<std::int64_t>() == actual.get<std::int64_t>();
    }
    const double e = expected.get<double>();
    const double a = actual.get<double>();
    if (e == a) return true;
    // An integral expectation must be met exactly, unless the actual value is a float
    // (REAL results like 3.0000001 against an expectation of 3).
    if (expected.is_number_integer() && actual.is_number_integer()) return false;
    return std::fabs(e - a) <= kRelativeTolerance * std::max(std::fabs(e), std::fabs(a));
}

std::string kindName(const json& v) {
    if (v.is_null()) return "null";
    if (v.is_boolean()) return "boolean";
    if (v.is_number()) return "number";
    if (v.is_string()) return "string";
    if (v.is_array()) return "array";
    return "object";
}

// Appends one line per mismatch; `path` is the JSON path of `expected`.
void matchSubset(const json& expected, const json& actual, const std::string& path,
                 std::vector<std::string>& mismatches) {
    auto mismatch = [&](const std::string& why) {
        mismatches.push_back((path.empty() ? std::string("<root>") : path) + ": " + why);
    };
    if (expected.is_object()) {
        if (!actual.is_object()) {
            mismatch("expected an object, got " + kindName(actual) + " " + actual.dump());
            return;
        }
        for (const auto& [key, value] : expected.items()) {
            const std::string child = path.empty() ? key : path + "." + key;
            const auto it = actual.find(key);
            if (it == actual.end()) {
                std::string present;
                for (const auto& [k, v] : actual.items()) present += (present.empty() ? "" : ", ") + k;
                mismatches.push_back(child + ": missing (expected " + value.dump() + "); present keys: [" +
                                     present + "]");
                continue;
            }
            matchSubset(value, *it, child, mismatches);
        }
        return;
    }
    if (expected.is_array()) {
        if (!actual.is_array()) {
            mismatch("expected an array, got " + kindName(actual) + " " + actual.dump());
            return;
        }
        if (expected.size() != actual.size()) {
            mismatch("array length " + std::to_string(actual.size()) + ", expected " +
                     std::to_string(expected.size()) + "; actual " + actual.dump());
            return;
        }
        for (std::size_t i = 0; i < expected.size(); ++i)
            matchSubset(expected[i], actual[i], path + "[" + std::to_string(i) + "]", mismatches);
        return;
    }
    bool same = false;
    if (expected.is_number() && actual.is_number()) {
        same = numbersMatch(expected, actual);
    } else if (expected.type() == actual.type()) {
        same = expected == actual;
    }
    if (!same) mismatch("expected " + expected.dump() + ", actual " + actual.dump());
}

// A pattern line of a .err file must occur in one stderr line.
std::vector<std::string> missingPatterns(const std::string& patternsText, const std::string& stderrText) {
    std::vector<std::string> stderrLines;
    {
        std::istringstream in(stderrText);
        for (std::string l; std::getline(in, l);) stderrLines.push_back(l);
    }
    std::vector<std::string> missing;
    std::istringstream in(patternsText);
    for (std::string pattern; std::getline(in, pattern);) {
        if (!pattern.empty() && pattern.back() == '\r') pattern.pop_back();
        if (trim(pattern).empty()) continue;
        // `!text`: no line may contain text (reported as the pattern itself).
        const bool negated = pattern[0] == '!';
        const std::string text = negated ? pattern.substr(1) : pattern;
        bool found = false;
        for (const auto& l : stderrLines)
            if (l.find(text) != std::string::npos) { found = true; break; }
        if (found == negated) missing.push_back(pattern);
    }
    return missing;
}

// ---------------------------------------------------------------- golden traces

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) {
        if (!l.empty() && l.back() == '\r') l.pop_back();
        lines.push_back(l);
    }
    return lines;
}

// The expected trace: every line of the .trace file, trailing blank lines dropped
// (an editor's final newline must not count as an expected event).
std::vector<std::string> expectedTraceLines(const std::string& traceText) {
    auto lines = splitLines(traceText);
    while (!lines.empty() && trim(lines.back()).empty()) lines.pop_back();
    return lines;
}

// The trace strun printed: the stderr lines that start with `T#` (decision 0011:
// `<PLC time> <task> <event>[ <detail>]`); warnings and other stderr text are not trace.
std::vector<std::string> actualTraceLines(const std::string& stderrText) {
    std::vector<std::string> trace;
    for (auto& l : splitLines(stderrText))
        if (l.rfind("T#", 0) == 0) trace.push_back(l);
    return trace;
}

// Empty when the traces are equal; else a description of the first difference
// with up to `context` lines before it, both sides numbered (1-based trace lines).
std::string traceDifference(const std::vector<std::string>& expected, const std::vector<std::string>& actual,
                            std::size_t context = 3, const char* what = "trace") {
    std::size_t i = 0;
    while (i < expected.size() && i < actual.size() && expected[i] == actual[i]) ++i;
    if (i == expected.size() && i == actual.size()) return "";
    std::ostringstream d;
    d << what << " differs at line " << (i + 1) << " (expected " << expected.size() << " lines, actual "
      << actual.size() << ")\n";
    for (std::size_t k = i > context ? i - context : 0; k < i; ++k)
        d << "        " << (k + 1) << "   " << expected[k] << "\n";
    d << "      expected " << (i + 1) << ": " << (i < expected.size() ? expected[i] : (std::string("<end of ") + what + ">")) << "\n";
    d << "      actual   " << (i + 1) << ": " << (i < actual.size() ? actual[i] : (std::string("<end of ") + what + ">"));
    for (std::size_t k = i + 1; k < std::min(actual.size(), i + 1 + context); ++k)
        d << "\n        " << (k + 1) << "   " << actual[k] << "   (actual)";
    return d.str();
}

// ---------------------------------------------------------------- VCD expectations

// A Value Change Dump as written by `strun run --vcd`, parsed: every signal by
// its full path (scopes joined with '.', e.g. `Main.valve.cmd`, `tasks.MainTask`)
// with its changes in time order ($dumpvars values are changes at time 0).
struct VcdChanges {
    std::map<std::string, std::vector<std::pair<long long, std::string>>> bySignal;
    std::string error;  // a structural problem of the file
};

VcdChanges parseVcd(const std::string& text) {
    VcdChanges out;
    std::istringstream in(text);
    std::vector<std::string> scopes;
    std::map<std::string, std::string> pathOfId;
    bool definitions = true, timescale = false;
    long long now = -1;
    for (std::string word; in >> word;) {
        if (definitions) {
            if (word == "$timescale") {
                std::string unit, end;
                in >> unit >> end;
                timescale = unit == "1ns" && end == "$end";
            } else if (word == "$scope") {
                std::string kind, name, end;
                in >> kind >> name >> end;
                scopes.push_back(name);
            } else if (word == "$upscope") {
                std::string end;
                in >> end;
                if (scopes.empty()) return out.error = "$upscope without $scope", out;
                scopes.pop_back();
            } else if (word == "$var") {
                std::string kind, width, id, name, end;
                in >> kind >> width >> id >> name >> end;
                if (end != "$end") return out.error = "malformed $var " + name, out;
                std::string path;
                for (const auto& sc : scopes) path += sc + ".";
                pathOfId[id] = path + name;
                out.bySignal[path + name];
            } else if (word == "$enddefinitions") {
                definitions = false;
                if (!scopes.empty()) return out.error = "unclosed $scope", out;
                if (!timescale) return out.error = "no `$timescale 1ns $end`", out;
            } else if (word[0] == '$' && word != "$end") {
                for (std::string skip; in >> skip && skip != "$end";) {}
            }
            continue;
        }
        if (word == "$dumpvars" || word == "$end") continue;
        if (word[0] == '#') {
            long long t = std::atoll(word.c_str() + 1);
            if (t <= now) return out.error = "time " + word + " does not increase", out;
            now = t;
            continue;
        }
        if (now < 0) return out.error = "a value before the first #time", out;
        std::string value, id;
        if (word[0] == 'b' || word[0] == 'r' || word[0] == 's') {
            value = word;
            in >> id;
        } else {
            value = word.substr(0, 1);
            id = word.substr(1);
        }
        auto it = pathOfId.find(id);
        if (it == pathOfId.end()) return out.error = "undeclared identifier '" + id + "'", out;
        out.bySignal[it->second].push_back({now, value});
    }
    if (definitions) out.error = "no $enddefinitions";
    return out;
}

// Lines of a .vcd expectation:
//   PATH TIME VALUE     the signal changes to VALUE at TIME ns (`1`, `b101`, `r2.5`)
//   PATH changes N      the signal has exactly N changes (the initial value counts)
//   PATH absent         no such signal
// `#` starts a comment line.
std::vector<std::string> vcdMismatches(const std::string& expectation, const VcdChanges& vcd) {
    std::vector<std::string> out;
    if (!vcd.error.empty()) return {"the VCD is malformed: " + vcd.error};
    std::istringstream in(expectation);
    for (std::string line; std::getline(in, line);) {
        line = trim(line);
        if (line.empty() || line[0] == '#') continue;
        auto words = splitWords(line);
        auto it = vcd.bySignal.find(words[0]);
        if (words.size() == 2 && words[1] == "absent") {
            if (it != vcd.bySignal.end()) out.push_back("signal " + words[0] + " should not be recorded");
            continue;
        }
        if (it == vcd.bySignal.end()) {
            out.push_back("no signal " + words[0]);
            continue;
        }
        if (words.size() == 3 && words[1] == "changes") {
            if (std::to_string(it->second.size()) != words[2])
                out.push_back(words[0] + ": " + std::to_string(it->second.size()) + " changes, expected " + words[2]);
            continue;
        }
        if (words.size() != 3) {
            out.push_back("bad .vcd expectation line: " + line);
            continue;
        }
        bool found = false;
        for (const auto& [t, v] : it->second) found = found || (std::to_string(t) == words[1] && v == words[2]);
        if (!found) {
            std::string seen;
            for (const auto& [t, v] : it->second) seen += " " + std::to_string(t) + ":" + v;
            out.push_back(words[0] + ": no change to " + words[2] + " at " + words[1] + " (changes:" + seen + ")");
        }
    }
    return out;
}

// ---------------------------------------------------------------- running strun

struct RunResult {
    bool started = false;
    bool timedOut = false;
    int exitCode = -1;  // valid when signal == 0
    int signal = 0;
    std::string out, err;
    std::string startError;
};

std::optional<std::string> readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string readFd(int fd) {
    std::string text;
    lseek(fd, 0, SEEK_SET);
    char buf[65536];
    for (ssize_t n; (n = read(fd, buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
    return text;
}

int makeTempFile(const char* tag) {
    std::string pattern = std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") +
                          "/conformance_" + tag + "_XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const int fd = mkstemp(name.data());
    if (fd >= 0) unlink(name.data());  // lives as long as the descriptor
    return fd;
}

RunResult runProgram(const std::vector<std::string>& argv) {
    RunResult result;
    const int outFd = makeTempFile("out");
    const int errFd = makeTempFile("err");
    if (outFd < 0 || errFd < 0) {
        result.startError = std::string("cannot create temp files: ") + std::strerror(errno);
        return result;
    }
    std::vector<char*> cargv;
    for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
    cargv.push_back(nullptr);

    const pid_t pid = fork();
    if (pid < 0) {
        result.startError = std::string("fork failed: ") + std::strerror(errno);
        return result;
    }
    if (pid == 0) {
        setpgid(0, 0);  // own process group, so a timeout kills strun's children too
        const int devNull = open("/dev/null", O_RDONLY);
        if (devNull >= 0) dup2(devNull, STDIN_FILENO);
        dup2(outFd, STDOUT_FILENO);
        dup2(errFd, STDERR_FILENO);
        execv(cargv[0], cargv.data());
        const std::string msg = std::string("exec ") + argv[0] + " failed: " + std::strerror(errno) + "\n";
        (void)!write(STDERR_FILENO, msg.data(), msg.size());
        _exit(127);
    }
    setpgid(pid, pid);
    result.started = true;

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kTimeoutSeconds);
    int status = 0;
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) break;
        if (std::chrono::steady_clock::now() >= deadline) {
            result.timedOut = true;
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    result.out = readFd(outFd);
    result.err = readFd(errFd);
    close(outFd);
    close(errFd);
    return result;
}

std::string joinCommand(const std::vector<std::string>& argv) {
    std::string s;
    for (const auto& a : argv) {
        if (!s.empty()) s += ' ';
        const bool plain = !a.empty() && a.find_first_of(" \t'\"\\$*?#()") == std::string::npos;
        if (plain) {
            s += a;
        } else {
            s += '\'';
            for (char c : a) s += (c == '\'') ? std::string("'\\''") : std::string(1, c);
            s += '\'';
        }
    }
    return s;
}

// ---------------------------------------------------------------- one test

std::string withoutExtension(const std::string& path) {
    const auto slash = path.find_last_of('/');
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
    return path.substr(0, dot);
}

std::string clip(const std::string& text, std::size_t limit = 20000) {
    if (text.size() <= limit) return text;
    return text.substr(0, limit) + "\n... (" + std::to_string(text.size() - limit) + " more bytes)";
}

int checkOne(const std::string& strun, const std::string& programPath) {
    const auto source = readFile(programPath);
    if (!source) {
        std::cerr << "conformance_check: cannot read " << programPath << "\n";
        return 2;
    }
    Directives directives;
    if (auto error = parseDirectives(*source, directives)) {
        std::cerr << "conformance_check: " << programPath << ": " << *error << "\n";
        return 2;
    }
    const std::string base = withoutExtension(programPath);
    const auto expectedJsonText = readFile(base + ".json");
    const auto expectedErr = readFile(base + ".err");
    const auto expectedTrace = readFile(base + ".trace");
    const auto expectedOut = readFile(base + ".out");
    if (expectedOut && (expectedJsonText || expectedErr || expectedTrace || directives.args.front() != "test")) {
        std::cerr << "conformance_check: " << programPath << " has a .out expectation: it needs the command 'test' and no .json/.err/.trace\n";
        return 2;
    }
    const auto expectedStderr = readFile(base + ".stderr");
    const auto expectedStdout = readFile(base + ".stdout");
    const auto expectedVcd = readFile(base + ".vcd");
    // `{vcd}` in the args: a temporary file strun writes the VCD to, checked against <name>.vcd.
    std::string vcdPath;
    for (const auto& a : directives.args)
        if (a.find("{vcd}") != std::string::npos && vcdPath.empty()) {
            vcdPath = std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") + "/conformance_vcd_" +
                      std::to_string(getpid()) + ".vcd";
        }
    if (expectedVcd && vcdPath.empty()) {
        std::cerr << "conformance_check: " << programPath << " has a .vcd expectation but no {vcd} in its args\n";
        return 2;
    }
    if (expectedJsonText && expectedErr) {
        std::cerr << "conformance_check: " << programPath << " has both a .json and a .err expectation\n";
        return 2;
    }
    if (expectedTrace && expectedErr) {
        std::cerr << "conformance_check: " << programPath << " has both a .trace and a .err expectation\n";
        return 2;
    }
    if (expectedTrace && directives.args.front() != "run") {
        std::cerr << "conformance_check: " << programPath << " has a .trace expectation but its command is not 'run'\n";
        return 2;
    }
    std::optional<json> expectedJson;
    if (expectedJsonText) {
        try {
            expectedJson = json::parse(*expectedJsonText);
        } catch (const json::exception& e) {
            std::cerr << "conformance_check: " << base << ".json is not valid JSON: " << e.what() << "\n";
            return 2;
        }
    }
    const int expectedExit = directives.exit.value_or(expectedErr ? 1 : 0);

    std::vector<std::string> argv{strun};
    bool hasDump = false, hasTrace = false;
    for (const auto& a : directives.args) {
        argv.push_back(expandTokens(a, programPath, vcdPath));
        hasDump = hasDump || a == "--dump";
        hasTrace = hasTrace || a == "--trace";
    }
    if (directives.args.front() == "run" && !hasDump && directives.appendDump) argv.push_back("--dump");
    if (expectedTrace && !hasTrace) argv.push_back("--trace");
    if (directives.appendFile) argv.push_back(programPath);

    const RunResult run = runProgram(argv);
    std::vector<std::string> failures;
    if (!run.started) {
        failures.push_back(run.startError);
    } else if (run.timedOut) {
        failures.push_back("timed out after " + std::to_string(kTimeoutSeconds) + " s (killed)");
    } else if (run.signal != 0) {
        failures.push_back("strun was killed by signal " + std::to_string(run.signal) + " (" +
                           strsignal(run.signal) + ")");
    } else if (run.exitCode != expectedExit) {
        failures.push_back("exit status " + std::to_string(run.exitCode) + ", expected " +
                           std::to_string(expectedExit));
    }
    const bool ranToEnd = run.started && !run.timedOut && run.signal == 0;

    if (ranToEnd && expectedJson) {
        json actual;
        bool parsed = true;
        try {
            actual = json::parse(run.out);
        } catch (const json::exception& e) {
            parsed = false;
            failures.push_back(std::string("stdout is not one JSON document: ") + e.what());
        }
        if (parsed) {
            std::vector<std::string> mismatches;
            matchSubset(*expectedJson, actual, "", mismatches);
            for (const auto& m : mismatches) failures.push_back("dump mismatch at " + m);
        }
    }
    if (ranToEnd && expectedTrace) {
        const std::string difference =
            traceDifference(expectedTraceLines(*expectedTrace), actualTraceLines(run.err));
        if (!difference.empty()) failures.push_back(difference);
    }
    if (ranToEnd && expectedOut) {
        // `{file}` in a .out line stands for the program's path as passed to strun (as in the args).
        std::vector<std::string> expected = expectedTraceLines(*expectedOut);
        for (auto& l : expected) l = expandTokens(l, programPath);
        const std::string difference = traceDifference(expected, splitLines(run.out), 3, "stdout");
        if (!difference.empty()) failures.push_back(difference);
    }
    if (ranToEnd && expectedVcd) {
        const auto vcdText = readFile(vcdPath);
        if (!vcdText) failures.push_back("strun wrote no VCD file");
        else
            for (const auto& m : vcdMismatches(*expectedVcd, parseVcd(*vcdText))) failures.push_back("vcd: " + m);
    }
    if (!vcdPath.empty()) unlink(vcdPath.c_str());
    if (ranToEnd && expectedStderr)
        for (const auto& p : missingPatterns(*expectedStderr, run.err))
            failures.push_back("no stderr line contains the pattern \"" + p + "\"");
    if (ranToEnd && expectedStdout)
        for (const auto& p : missingPatterns(*expectedStdout, run.out))
            failures.push_back("no stdout line contains the pattern \"" + p + "\"");
    if (ranToEnd && expectedErr) {
        if (!run.out.empty()) failures.push_back("stdout must be empty for a program that does not compile");
        for (const auto& p : missingPatterns(*expectedErr, run.err))
            failures.push_back("no stderr line contains the pattern \"" + p + "\"");
    }

    if (failures.empty()) return 0;
    std::cout << "FAIL " << programPath << "\n";
    std::cout << "command: " << joinCommand(argv) << "\n";
    for (const auto& f : failures) std::cout << "  - " << f << "\n";
    std::cout << "---- stderr (" << run.err.size() << " bytes)\n" << clip(run.err);
    if (!run.err.empty() && run.err.back() != '\n') std::cout << "\n";
    std::cout << "---- stdout (" << run.out.size() << " bytes)\n" << clip(run.out);
    if (!run.out.empty() && run.out.back() != '\n') std::cout << "\n";
    std::cout << "----\n";
    return 1;
}

// ---------------------------------------------------------------- self-test

// A scratch directory for one end-to-end scenario of the self-test: files
// written into it, checkOne run on its programs with a fake strun
// ("fake_strun" in the directory) and the output captured, all removed at
// the end.
class SelfTestDir {
public:
    SelfTestDir() {
        char pathTemplate[] = "/tmp/conformance_selftest_XXXXXX";
        if (const char* dir = mkdtemp(pathTemplate)) path_ = dir;
    }
    ~SelfTestDir() {
        for (const std::string& f : files_) unlink((path_ + "/" + f).c_str());
        if (ok()) rmdir(path_.c_str());
    }
    bool ok() const { return !path_.empty(); }
    void write(const std::string& name, const std::string& text, mode_t mode = 0644) {
        if (!ok()) return;
        std::ofstream(path_ + "/" + name) << text;
        chmod((path_ + "/" + name).c_str(), mode);
        files_.push_back(name);
    }
    // checkOne's result for each program, their stdout and stderr in output.
    std::vector<int> check(std::initializer_list<const char*> programs, std::string& output) const {
        std::vector<int> results;
        std::ostringstream quiet;
        auto* saved = std::cout.rdbuf(quiet.rdbuf());
        auto* savedErr = std::cerr.rdbuf(quiet.rdbuf());
        for (const char* program : programs) results.push_back(ok() ? checkOne(path_ + "/fake_strun", path_ + "/" + program) : -1);
        std::cout.rdbuf(saved);
        std::cerr.rdbuf(savedErr);
        output = quiet.str();
        return results;
    }

private:
    std::string path_;
    std::vector<std::string> files_;
};

int selfTest() {
    int failed = 0;
    auto expect = [&](bool ok, const std::string& what) {
        if (!ok) {
            ++failed;
            std::cout << "self-test FAILED: " << what << "\n";
        }
    };
    auto countMismatches = [](const char* e, const char* a) {
        std::vector<std::string> m;
        matchSubset(json::parse(e), json::parse(a), "", m);
        return m;
    };
    const char* actual = R"({"state":"RUN","time":"T#3us",
        "programs":{"Main":{"i":7,"r":0.1000000014901161,"s":"ab","b":true,
                            "a":[1,2,{"x":1,"y":2}],"m":[[1,2],[3,4]],"big":18446744073709551615,
                            "neg":-9223372036854775808,"f":"inf"}},
        "diagnostics":[]})";

    expect(countMismatches(R"({"state":"RUN"})", actual).empty(), "subset of top-level keys");
    expect(countMismatches(R"({"programs":{"Main":{"i":7}}})", actual).empty(), "nested subset");
    expect(countMismatches(R"({"programs":{"Main":{"r":0.1}}})", actual).empty(), "REAL within 1e-6");
    expect(countMismatches(R"({"programs":{"Main":{"r":0.1001}}})", actual).size() == 1, "REAL outside 1e-6");
    expect(countMismatches(R"({"programs":{"Main":{"i":7.0}}})", actual).empty(), "7.0 equals 7");
    expect(countMismatches(R"({"programs":{"Main":{"i":8}}})", actual).size() == 1, "integer differs");
    expect(countMismatches(R"({"programs":{"Main":{"i":"7"}}})", actual).size() == 1, "string vs number");
    expect(countMismatches(R"({"programs":{"Main":{"b":1}}})", actual).size() == 1, "number vs boolean");
    expect(countMismatches(R"({"programs":{"Main":{"s":"ab"}}})", actual).empty(), "string equal");
    expect(countMismatches(R"({"programs":{"Main":{"s":"aB"}}})", actual).size() == 1, "string case matters");
    expect(countMismatches(R"({"programs":{"Main":{"a":[1,2,{"x":1}]}}})", actual).empty(),
           "object subset inside array");
    expect(countMismatches(R"({"programs":{"Main":{"a":[1,2]}}})", actual).size() == 1, "array length differs");
    expect(countMismatches(R"({"programs":{"Main":{"m":[[1,2],[3,5]]}}})", actual).size() == 1,
           "nested array element differs");
    expect(countMismatches(R"({"programs":{"Main":{"zz":1}}})", actual).size() == 1, "missing key");
    expect(countMismatches(R"({"programs":{"Other":{}}})", actual).size() == 1, "missing program");
    expect(countMismatches(R"({"programs":{"Main":{"big":18446744073709551615}}})", actual).empty(),
           "ULINT max exact");
    expect(countMismatches(R"({"programs":{"Main":{"big":18446744073709551614}}})", actual).size() == 1,
           "ULINT max - 1 differs");
    expect(countMismatches(R"({"programs":{"Main":{"neg":-9223372036854775808}}})", actual).empty(),
           "LINT min exact");
    expect(countMismatches(R"({"programs":{"Main":{"f":"inf"}}})", actual).empty(), "inf string");
    expect(countMismatches(R"({"diagnostics":[]})", actual).empty(), "empty array");
    expect(countMismatches(R"({"diagnostics":[{"code":"DIV_BY_ZERO"}]})", actual).size() == 1,
           "diagnostic expected but none");
    {
        auto m = countMismatches(R"({"programs":{"Main":{"a":[1,2,{"y":3}]}}})", actual);
        expect(m.size() == 1 && m[0].rfind("programs.Main.a[2].y:", 0) == 0, "mismatch path names the element");
    }
    expect(numbersMatch(json(1e30), json(1.0000001e30)), "large REAL relative");
    expect(!numbersMatch(json(1), json(2)), "1 vs 2");
    expect(numbersMatch(json(-3), json(-3.0000001)), "integral expectation vs float actual");
    expect(!numbersMatch(json(0.0), json(1e-9)), "zero expectation is exact");

    const std::string err = "/abs/x.st:4:5: error: undeclared variable 'q'\n/abs/x.st:9:1: warning: w\n";
    expect(missingPatterns(":4:5: error:\nundeclared\n", err).empty(), "patterns found");
    expect(missingPatterns(":4:6: error:\n", err).size() == 1, "wrong column reported missing");
    expect(missingPatterns(":4:5: error: undeclared variable 'q'\n\n", err).empty(), "blank lines ignored");
    expect(missingPatterns(":9:1: error:", err).size() == 1, "warning is not an error");
    expect(missingPatterns("!fatal\n", err).empty() && missingPatterns("!undeclared\n", err).size() == 1,
           "a !pattern must not occur");

    {
        const std::string stderrText =
            "x.st:3:1: warning: unused\nT#0s Fast release\r\nT#0s Fast start\n  T#1ms not a trace line\nT#2us Fast end\n";
        const auto actualTrace = actualTraceLines(stderrText);
        expect(actualTrace == std::vector<std::string>{"T#0s Fast release", "T#0s Fast start", "T#2us Fast end"},
               "trace lines are the stderr lines starting with T#, CR stripped");
        expect(expectedTraceLines("T#0s Fast release\nT#0s Fast start\nT#2us Fast end\n\n\n") == actualTrace,
               "trailing blank lines of a .trace file are ignored");
        expect(traceDifference(actualTrace, actualTrace).empty(), "equal traces match");
        const auto wrongTime = traceDifference({"T#0s Fast release", "T#0s Fast start", "T#3us Fast end"}, actualTrace);
        expect(wrongTime.find("differs at line 3") != std::string::npos &&
                   wrongTime.find("expected 3: T#3us Fast end") != std::string::npos &&
                   wrongTime.find("actual   3: T#2us Fast end") != std::string::npos &&
                   wrongTime.find("1   T#0s Fast release") != std::string::npos,
               "first differing line shown with its context");
        const auto tooShort = traceDifference({"T#0s Fast release", "T#0s Fast start"}, actualTrace);
        expect(tooShort.find("expected 3: <end of trace>") != std::string::npos, "extra actual line reported");
        const auto tooLong = traceDifference({"T#0s Fast release", "T#0s Fast start", "T#2us Fast end", "T#9us X end"},
                                             actualTrace);
        expect(tooLong.find("actual   4: <end of trace>") != std::string::npos, "missing actual line reported");
        expect(!traceDifference({"T#0s Fast start", "T#0s Fast release", "T#2us Fast end"}, actualTrace).empty(),
               "order matters");
        expect(!traceDifference({"T#0s Fast release ", "T#0s Fast start", "T#2us Fast end"}, actualTrace).empty(),
               "trailing space matters");
        expect(!traceDifference({}, actualTrace).empty(), "an empty expectation means no trace at all");
    }
    {
        Directives d;
        expect(!parseDirectives("(* strun-test\n   args: run --virtual --cycles 3\n   exit: 3\n*)\nPROGRAM P END_PROGRAM",
                                d) && d.args.size() == 4 && d.args[3] == "3" && d.exit == 3,
               "directive block parsed");
        Directives plain;
        expect(!parseDirectives("(* just a comment *)\nPROGRAM P END_PROGRAM", plain) && plain.args.size() == 5 &&
                   !plain.exit,
               "ordinary comment ignored");
        Directives bad;
        expect(parseDirectives("(* strun-test\n colour: red\n*)", bad).has_value(), "unknown directive rejected");
        Directives noDump;
        expect(!parseDirectives("(* strun-test\n dump: no\n file: no\n*)", noDump) && !noDump.appendDump &&
                   !noDump.appendFile,
               "dump/file directives parsed");
        Directives badDump;
        expect(parseDirectives("(* strun-test\n dump: maybe\n*)", badDump).has_value(), "bad dump directive rejected");
        expect(expandTokens("{dir}/s.csv", "/a/b/t.st") == "/a/b/s.csv", "{dir} is the program's directory");
        expect(expandTokens("x={file}", "/a/b/t.st") == "x=/a/b/t.st", "{file} is the program's path");
        const std::string vcd = "$version x $end\n$timescale 1ns $end\n$scope module tasks $end\n$var wire 1 ! T $end\n"
                                "$upscope $end\n$scope module Main $end\n$var wire 16 \" n $end\n$upscope $end\n"
                                "$enddefinitions $end\n#0\n$dumpvars\n0!\nb0 \"\n$end\n1!\n#5\nb11 \"\n0!\n";
        const auto parsed = parseVcd(vcd);
        expect(parsed.error.empty() && parsed.bySignal.at("Main.n").size() == 2 && parsed.bySignal.at("tasks.T").size() == 3,
               "VCD parsed by signal path");
        expect(vcdMismatches("Main.n 5 b11\ntasks.T changes 3\nMain.x absent\n", parsed).empty(), "VCD expectations met");
        expect(vcdMismatches("Main.n 4 b11\n", parsed).size() == 1, "VCD change at the wrong time");
        expect(vcdMismatches("Main.n changes 1\n", parsed).size() == 1, "VCD change count differs");
        expect(!parseVcd("$timescale 1ns $end\n$enddefinitions $end\n#5\n#5\n").error.empty(), "VCD times must increase");
        expect(!parseVcd("$timescale 1ns $end\n$enddefinitions $end\n#0\n1?\n").error.empty(), "VCD undeclared id");
        Directives badExit;
        expect(parseDirectives("(* strun-test\n exit: x\n*)", badExit).has_value(), "bad exit rejected");
    }
    {
        const RunResult r = runProgram({"/bin/sh", "-c", "echo out; echo err >&2; exit 3"});
        expect(r.exitCode == 3 && r.out == "out\n" && r.err == "err\n", "runProgram captures streams and status");
        const RunResult missing = runProgram({"/nonexistent/strun"});
        expect(missing.exitCode == 127 && missing.err.find("exec") != std::string::npos,
               "missing binary reported");
    }
    {
        // End to end with a fake strun: --trace must be added for a .trace expectation.
        SelfTestDir d;
        d.write("fake_strun", "#!/bin/sh\ncase \"$*\" in *--trace*) echo 'T#0s Main start' >&2;; esac\n"
                              "echo 'x.st:1:1: warning: w' >&2\necho '{\"state\":\"RUN\"}'\n", 0755);
        d.write("good.st", "PROGRAM Main END_PROGRAM\n");
        d.write("good.trace", "T#0s Main start\n");
        d.write("bad.st", "PROGRAM Main END_PROGRAM\n");
        d.write("bad.trace", "T#0s Main start\nT#1us Main end\n");
        d.write("both.st", "PROGRAM Main END_PROGRAM\n");
        d.write("both.trace", "T#0s Main start\n");
        d.write("both.err", "error\n");
        std::string output;
        const std::vector<int> r = d.check({"good.st", "bad.st", "both.st"}, output);
        expect(d.ok(), "cannot create a temporary directory");
        expect(r[0] == 0, "a matching .trace passes (--trace added to the command)");
        expect(r[1] == 1 && output.find("expected 2: T#1us Main end") != std::string::npos,
               "a differing .trace fails and names the line");
        expect(r[2] == 2, ".trace together with .err is a malformed test");
    }
    {
        // A .out expectation: exact stdout of `strun test`, {file} standing for the program path.
        SelfTestDir d;
        d.write("fake_strun", "#!/bin/sh\nfor f; do :; done\necho \"FAIL S.T: $f:3: EXP: 1, ACT: 2, MSG: m\"\necho '0 passed, 1 failed'\nexit 1\n", 0755);
        const char* head = "(* strun-test\n   args: test\n   exit: 1\n*)\n";
        d.write("good.st", head);
        d.write("good.out", "FAIL S.T: {file}:3: EXP: 1, ACT: 2, MSG: m\n0 passed, 1 failed\n\n");
        d.write("bad.st", head);
        d.write("bad.out", "FAIL S.T: {file}:3: EXP: 1, ACT: 3, MSG: m\n0 passed, 1 failed\n");
        d.write("run.st", "PROGRAM Main END_PROGRAM\n");
        d.write("run.out", "x\n");
        std::string output;
        const std::vector<int> r = d.check({"good.st", "bad.st", "run.st"}, output);
        expect(d.ok(), "cannot create a temporary directory");
        expect(r[0] == 0, "a matching .out passes ({file} replaced, trailing blank lines ignored)");
        expect(r[1] == 1 && output.find("stdout differs at line 1") != std::string::npos, "a differing .out fails and names the line");
        expect(r[2] == 2, "a .out with a command other than test is a malformed test");
    }
    std::cout << (failed == 0 ? "self-test passed\n" : "self-test failed\n");
    return failed == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 2 && std::string(argv[1]) == "--self-test") return selfTest();
    if (argc != 3) {
        std::cerr << "usage: conformance_check <strun-binary> <file.st>\n"
                     "       conformance_check --self-test\n";
        return 2;
    }
    return checkOne(argv[1], argv[2]);
}
