#include "cli/option_types.h"

#include <cerrno>
#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "stdlib/time_literals.h"

namespace strun::cli {

std::string trimmed(std::string_view text) {
    size_t begin = text.find_first_not_of(" \t\r\n");
    if (begin == std::string_view::npos) return {};
    size_t end = text.find_last_not_of(" \t\r\n");
    return std::string(text.substr(begin, end - begin + 1));
}

std::optional<int64_t> parseDuration(std::string_view text, std::string& error) {
    std::string t = trimmed(text);
    // A bare 0 needs no unit: zero of every unit is the same duration.
    if (!t.empty() && t.find_first_not_of('0') == std::string::npos) return 0;
    auto r = stdlib::parseDurationLiteral(t);
    if (!r) {
        error = "'" + t + "' is not a duration (e.g. T#1s500ms, 150ms, 0): " + r.error();
        return std::nullopt;
    }
    if (r.value() < 0) {
        error = "'" + t + "' is negative";
        return std::nullopt;
    }
    return r.value();
}

CLI::Validator durationValidator() {
    return CLI::Validator(
        [](std::string& text) {
            std::string error;
            text = trimmed(text);
            return parseDuration(text, error) ? std::string() : error;
        },
        "", "DURATION");
}

CLI::Validator positiveCountValidator() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            text = trimmed(text);
            bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
            if (!digits) return "'" + text + "' is not a count (a whole number >= 1)";
            errno = 0;
            unsigned long long n = std::strtoull(text.c_str(), nullptr, 10);
            if (errno == ERANGE) return "'" + text + "' is too large";
            if (n == 0) return "must be at least 1";
            return {};
        },
        "", "N");
}

CLI::Validator dateTimeValidator() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            text = trimmed(text);
            auto r = stdlib::parseDateTimeLiteral(text);
            if (!r) return "'" + text + "' is not a date and time (e.g. DT#2026-01-31-13:05:00): " + r.error();
            return {};
        },
        "", "DT");
}

CLI::Validator readableFileValidator(bool allowStdin) {
    return CLI::Validator(
        [allowStdin](std::string& path) -> std::string {
            if (allowStdin && path == "-") return {};  // standard input
            struct stat st {};
            if (::stat(path.c_str(), &st) != 0) return "'" + path + "': no such file";
            // A directory stands for every source file under it (interpreter/source/project_inputs.h).
            if (!S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) return "'" + path + "' is not a regular file or a directory";
            if (::access(path.c_str(), R_OK) != 0) return "'" + path + "' is not readable";
            return {};
        },
        "", "FILE");
}

int64_t validatedDuration(const std::string& text) {
    std::string unused;
    return parseDuration(text, unused).value_or(0);
}

}  // namespace strun::cli
