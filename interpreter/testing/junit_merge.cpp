#include "interpreter/testing/junit_merge.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace strun::testing {

namespace {

// The value of attribute `name` in the tag `line` ("" when absent).
std::string attribute(const std::string& line, const std::string& name) {
    const std::string key = " " + name + "=\"";
    size_t at = line.find(key);
    if (at == std::string::npos) return {};
    at += key.size();
    size_t end = line.find('"', at);
    return end == std::string::npos ? std::string() : line.substr(at, end - at);
}

long long count(const std::string& line, const std::string& name) {
    try {
        return std::stoll(attribute(line, name));
    } catch (...) {
        return 0;
    }
}

double seconds(const std::string& line) {
    try {
        return std::stod(attribute(line, "time"));
    } catch (...) {
        return 0.0;
    }
}

}  // namespace

bool mergeJUnit(const std::vector<std::string>& inputs, const std::string& output, std::string& error) {
    long long tests = 0, failures = 0, disabled = 0;
    double time = 0.0;
    int id = 0;
    std::ostringstream body;
    for (const std::string& path : inputs) {
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            error = "cannot read '" + path + "'";
            return false;
        }
        std::string line;
        bool seenRoot = false;
        while (std::getline(in, line)) {
            if (line.rfind("<?xml", 0) == 0 || line == "</testsuites>") continue;
            if (line.rfind("<testsuites ", 0) == 0) {
                seenRoot = true;
                tests += count(line, "tests");
                failures += count(line, "failures");
                disabled += count(line, "disabled");
                // The slices ran side by side: the whole run took as long as the longest.
                time = std::max(time, seconds(line));
                continue;
            }
            if (!seenRoot) {
                error = "'" + path + "' is not a JUnit report written by strun test";
                return false;
            }
            const std::string open = "  <testsuite id=\"";
            if (line.rfind(open, 0) == 0) {
                size_t end = line.find('"', open.size());
                line = open + std::to_string(id++) + line.substr(end);
            }
            body << line << '\n';
        }
        if (!seenRoot) {
            error = "'" + path + "' is not a JUnit report written by strun test";
            return false;
        }
    }
    std::ofstream xml(output, std::ios::binary | std::ios::trunc);
    if (!xml) {
        error = "cannot write '" + output + "'";
        return false;
    }
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml << fmt::format("<testsuites name=\"strun\" tests=\"{}\" failures=\"{}\" disabled=\"{}\" errors=\"0\" time=\"{:.6f}\">\n", tests,
                       failures, disabled, time);
    xml << body.str() << "</testsuites>\n";
    xml.flush();
    if (!xml) {
        error = "cannot write '" + output + "'";
        return false;
    }
    return true;
}

}  // namespace strun::testing
