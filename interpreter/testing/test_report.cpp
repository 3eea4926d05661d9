#include "interpreter/testing/test_report.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <tuple>

#include <fmt/format.h>

#include "interpreter/ast/utf8_input.h"
#include "interpreter/sema/types.h"
#include "interpreter/testing/test_registry.h"

namespace strun::testing {

namespace {

std::string fileName(int file, const SourceSet& sources) {
    return file >= 0 && file < sources.size() ? sources.file(file).path : std::string("<unknown>");
}

// Names and messages come from the program (string literals, identifiers in
// any bytes): the report is UTF-8 and must always parse, so bytes that are
// not UTF-8 become U+FFFD, as do U+FFFE and U+FFFF, which XML 1.0 forbids.
std::string xmlEscape(const std::string& raw) {
    std::string s = ast::sanitizeUtf8(raw);
    for (size_t at = 0; (at = s.find("\xEF\xBF", at)) != std::string::npos; at += 3)
        if (at + 2 < s.size() && (s[at + 2] == '\xBE' || s[at + 2] == '\xBF')) s[at + 2] = '\xBD';
    std::string out;
    out.reserve(s.size());
    for (char ch : s) {
        switch (ch) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                // Control characters are not allowed in XML 1.0 (tab and newlines are).
                if (static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') out += ' ';
                else out += ch;
        }
    }
    return out;
}

std::string seconds(rt::PlcTime ns) { return fmt::format("{:.6f}", static_cast<double>(std::max<rt::PlcTime>(ns, 0)) / 1e9); }

// The part of a failure after the location (the JUnit message).
std::string reason(const Failure& f) {
    if (!f.fault.empty()) return f.fault;
    return "EXP: " + f.expected + ", ACT: " + f.actual + ", MSG: " + f.message;
}

// The line in the file as the user has it (a TwinCAT / PLCopen XML file is
// compiled as ST converted from it; SourceFile::original maps back).
int originalLine(const Failure& f, const SourceSet& sources) {
    if (f.file < 0 || f.file >= sources.size()) return f.line;
    return sources.file(f.file).original(f.line, 1).first;
}

}  // namespace

std::string failureText(const Failure& f, const SourceSet& sources) {
    if (f.file < 0 && !f.filePath.empty()) return fmt::format("{}:{}: {}", f.filePath, f.line, reason(f));
    if (f.file < 0) return reason(f);
    return fmt::format("{}:{}: {}", fileName(f.file, sources), originalLine(f, sources), reason(f));
}

TestCounts printResults(const TestRegistry& reg, const SourceSet& sources, std::ostream& out, bool summary, bool color) {
    const char* pass = color ? "\x1b[1;32mPASS\x1b[0m " : "PASS ";
    const char* fail = color ? "\x1b[1;31mFAIL\x1b[0m " : "FAIL ";
    TestCounts n;
    for (const auto& s : reg.suites) {
        for (const auto& t : s.tests) {
            if (t.skipped) {
                ++n.skipped;
                continue;
            }
            if (t.failures.empty()) {
                ++n.passed;
                out << pass << s.name << '.' << t.name << '\n';
            } else {
                ++n.failed;
                out << fail << s.name << '.' << t.name << ": " << failureText(t.failures.front(), sources) << '\n';
            }
        }
    }
    if (summary) out << n.passed << " passed, " << n.failed << " failed\n";
    return n;
}

bool writeJUnit(const TestRegistry& reg, const SourceSet& sources, rt::PlcTime totalTime, const std::string& path, std::string& error) {
    std::ofstream xml(path, std::ios::binary | std::ios::trunc);
    if (!xml) {
        error = "cannot write '" + path + "': " + std::strerror(errno);
        return false;
    }
    int tests = 0, failures = 0, skipped = 0;
    for (const auto& s : reg.suites)
        for (const auto& t : s.tests) {
            ++tests;
            if (t.skipped) ++skipped;
            else if (!t.failures.empty()) ++failures;
        }
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml << fmt::format("<testsuites name=\"strun\" tests=\"{}\" failures=\"{}\" disabled=\"{}\" errors=\"0\" time=\"{}\">\n", tests, failures,
                       skipped, seconds(totalTime));
    int id = 0;
    for (const auto& s : reg.suites) {
        int sFail = 0, sSkip = 0;
        rt::PlcTime sTime = 0;
        for (const auto& t : s.tests) {
            if (t.skipped) ++sSkip;
            else if (!t.failures.empty()) ++sFail;
            if (!t.skipped && t.finished) sTime += t.finishedAt - t.startedAt;
        }
        xml << fmt::format("  <testsuite id=\"{}\" name=\"{}\" tests=\"{}\" failures=\"{}\" skipped=\"{}\" errors=\"0\" time=\"{}\">\n", id++,
                           xmlEscape(s.name), s.tests.size(), sFail, sSkip, seconds(sTime));
        for (const auto& t : s.tests) {
            rt::PlcTime tTime = t.finished ? t.finishedAt - t.startedAt : 0;
            xml << fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{}\" status=\"{}\"", xmlEscape(t.name), xmlEscape(s.name),
                               seconds(tTime), t.skipped ? "SKIP" : t.failures.empty() ? "PASS" : "FAIL");
            if (!t.skipped && t.failures.empty()) {
                xml << "/>\n";
                continue;
            }
            xml << ">\n";
            if (t.skipped) xml << "      <skipped/>\n";
            for (const auto& f : t.failures) {
                std::string type = f.fault.empty() ? "ASSERT" : f.fault == "timeout" ? "TIMEOUT" : f.fault.rfind("not run", 0) == 0 ? "NOT_RUN" : "FAULT";
                xml << fmt::format("      <failure message=\"{}\" type=\"{}\"", xmlEscape(reason(f)), type);
                if (f.file >= 0) xml << fmt::format(" file=\"{}\" line=\"{}\"", xmlEscape(fileName(f.file, sources)), originalLine(f, sources));
                else if (!f.filePath.empty()) xml << fmt::format(" file=\"{}\" line=\"{}\"", xmlEscape(f.filePath), f.line);
                xml << ">" << xmlEscape(failureText(f, sources)) << "</failure>\n";
            }
            xml << "    </testcase>\n";
        }
        xml << "  </testsuite>\n";
    }
    xml << "</testsuites>\n";
    xml.close();  // the flush and the close are checked: a full disk leaves no half report unreported
    if (!xml) {
        error = "cannot write '" + path + "'; the report is incomplete";
        return false;
    }
    return true;
}

void printTestList(const TestRegistry& reg, std::ostream& out) {
    for (const auto& s : reg.suites)
        for (const std::string& name : reg.declaredTests(s)) out << s.name << '.' << name << '\n';
}

}  // namespace strun::testing
