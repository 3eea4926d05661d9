#include "stdlib/value_format.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "stdlib/calendar.h"

namespace strun::stdlib {

namespace {

// "1d2h..." of a magnitude, after `out`'s prefix and sign.
std::string appendDurationUnits(std::string out, uint64_t rest) {
    struct Unit {
        const char* name;
        uint64_t ns;
    };
    static constexpr Unit kUnits[] = {
        {"d", kNsPerDay},     {"h", kNsPerHour}, {"m", kNsPerMinute}, {"s", kNsPerSecond},
        {"ms", kNsPerMs},     {"us", kNsPerUs},  {"ns", 1},
    };
    for (const Unit& unit : kUnits) {
        const uint64_t count = rest / unit.ns;
        rest %= unit.ns;
        if (count != 0) fmt::format_to(std::back_inserter(out), "{}{}", count, unit.name);
    }
    return out;
}

}  // namespace

std::string formatDuration(int64_t ns, std::string_view prefix) {
    std::string out(prefix);
    if (ns == 0) return out + "0s";
    // Work on the magnitude in unsigned arithmetic so that INT64_MIN is fine.
    uint64_t rest = ns < 0 ? 0 - static_cast<uint64_t>(ns) : static_cast<uint64_t>(ns);
    if (ns < 0) out.push_back('-');
    return appendDurationUnits(std::move(out), rest);
}

std::string formatUnsignedDuration(uint64_t ns, std::string_view prefix) {
    std::string out(prefix);
    if (ns == 0) return out + "0s";
    return appendDurationUnits(std::move(out), ns);
}

namespace {

// ".25" for 250'000'000 ns; empty for 0.
std::string secondFraction(int64_t nanosecond) {
    if (nanosecond == 0) return {};
    std::string digits = fmt::format("{:09}", nanosecond);
    while (!digits.empty() && digits.back() == '0') digits.pop_back();
    return "." + digits;
}

std::string formatClock(const TimeOfDayParts& tod) {
    return fmt::format("{:02}:{:02}:{:02}{}", tod.hour, tod.minute, tod.second,
                       secondFraction(tod.nanosecond));
}

}  // namespace

std::string formatDate(int64_t nsSinceEpoch, std::string_view prefix) {
    const DateTimeParts parts = splitDateTime(nsSinceEpoch);
    return fmt::format("{}{:04}-{:02}-{:02}", prefix, parts.year, parts.month, parts.day);
}

std::string formatTimeOfDay(int64_t nsSinceMidnight, std::string_view prefix) {
    return fmt::format("{}{}", prefix, formatClock(splitTimeOfDay(nsSinceMidnight)));
}

std::string formatDateTime(int64_t nsSinceEpoch, std::string_view prefix) {
    const DateTimeParts parts = splitDateTime(nsSinceEpoch);
    TimeOfDayParts tod;
    tod.hour = parts.hour;
    tod.minute = parts.minute;
    tod.second = parts.second;
    tod.nanosecond = parts.nanosecond;
    return fmt::format("{}{:04}-{:02}-{:02}-{}", prefix, parts.year, parts.month, parts.day,
                       formatClock(tod));
}

namespace {

template <typename T>
std::string formatIecReal(T value) {
    if (std::isnan(value)) return "NAN";
    if (std::isinf(value)) return value < 0 ? "-INF" : "INF";
    if (value == 0) return "0";  // also for -0: the sign of zero carries no information here

    // Shortest round-trip digits in scientific form, e.g. "-1.5e+20".
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value,
                                         std::chars_format::scientific);
    if (ec != std::errc{}) return "NAN";  // cannot happen with this buffer size
    const std::string_view text(buffer, static_cast<size_t>(end - buffer));
    const bool negative = text.front() == '-';
    const size_t ePos = text.find('e');
    std::string digits;  // mantissa digits without the point
    for (char c : text.substr(negative ? 1 : 0, ePos - (negative ? 1 : 0))) {
        if (c != '.') digits.push_back(c);
    }
    const int exponent = std::atoi(std::string(text.substr(ePos + 1)).c_str());

    std::string out = negative ? "-" : "";
    if (exponent >= -5 && exponent < 15) {
        if (exponent < 0) {
            out += "0.";
            out.append(static_cast<size_t>(-exponent - 1), '0');
            out += digits;
        } else if (static_cast<size_t>(exponent) + 1 >= digits.size()) {
            out += digits;
            out.append(static_cast<size_t>(exponent) + 1 - digits.size(), '0');
        } else {
            out += digits.substr(0, static_cast<size_t>(exponent) + 1);
            out += '.';
            out += digits.substr(static_cast<size_t>(exponent) + 1);
        }
        return out;
    }
    out += digits.substr(0, 1);
    if (digits.size() > 1) {
        out += '.';
        out += digits.substr(1);
    }
    out += fmt::format("E{}{:02}", exponent < 0 ? '-' : '+', std::abs(exponent));
    return out;
}

template <typename T>
std::string formatJsonNumber(T value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (ec != std::errc{}) return "nan";  // cannot happen with this buffer size
    return std::string(buffer, end);
}

}  // namespace

std::string formatReal(float value) { return formatIecReal(value); }
std::string formatLReal(double value) { return formatIecReal(value); }

namespace {
std::string withPointIfWhole(std::string text) {
    if (text.find_first_not_of("-0123456789") == std::string::npos) text += ".0";
    return text;
}
}  // namespace

std::string formatRealTwinCat(float value) { return withPointIfWhole(formatIecReal(value)); }
std::string formatLRealTwinCat(double value) { return withPointIfWhole(formatIecReal(value)); }
std::string formatRealJson(float value) { return formatJsonNumber(value); }
std::string formatLRealJson(double value) { return formatJsonNumber(value); }

}  // namespace strun::stdlib
