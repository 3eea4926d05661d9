#include "stdlib/time_literals.h"

#include <array>
#include <initializer_list>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "stdlib/calendar.h"
#include "stdlib/number_scan.h"

namespace strun::stdlib {

namespace {

// Strips one of `prefixes` followed by '#'. Text without '#' is returned as is
// (the bare form); an unknown prefix is an error (empty optional-like result).
Result<std::string_view> stripPrefix(std::string_view text,
                                     std::initializer_list<std::string_view> prefixes,
                                     std::string_view kind) {
    const size_t hash = text.find('#');
    if (hash == std::string_view::npos) return Result<std::string_view>::success(text);
    const std::string_view prefix = text.substr(0, hash);
    for (std::string_view allowed : prefixes) {
        if (equalsIgnoreCase(prefix, allowed)) {
            return Result<std::string_view>::success(text.substr(hash + 1));
        }
    }
    return Result<std::string_view>::failure(
        fmt::format("'{}#' is not a {} literal prefix in {}", prefix, kind, quoted(text)));
}

bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isDecimal(char c) { return c >= '0' && c <= '9'; }

struct DurationUnit {
    std::string_view name;
    int64_t ns;
    int64_t limitWhenNotFirst;  // the value must stay below this unless it is the first part
};

constexpr std::array<DurationUnit, 7> kDurationUnits{{
    {"d", kNsPerDay, std::numeric_limits<int64_t>::max()},
    {"h", kNsPerHour, 24},
    {"m", kNsPerMinute, 60},
    {"s", kNsPerSecond, 60},
    {"ms", kNsPerMs, 1000},
    {"us", kNsPerUs, 1000},
    {"ns", 1, 1000},
}};

// Digits of a fraction taken into account: 18 keep sub-nanosecond precision
// even for days (1e-18 d < 1 ns) while fitting in uint64.
constexpr size_t kMaxFractionDigits = 18;

// value * unitNs / 10^digits of the fraction digits in text[from, to), truncated.
__int128 fractionNs(std::string_view text, size_t from, size_t to, int64_t unitNs) {
    uint64_t numerator = 0;
    uint64_t denominator = 1;
    size_t used = 0;
    for (size_t i = from; i < to && used < kMaxFractionDigits; ++i) {
        if (text[i] == '_') continue;
        numerator = numerator * 10 + static_cast<uint64_t>(text[i] - '0');
        denominator *= 10;
        ++used;
    }
    return static_cast<__int128>(numerator) * unitNs / denominator;
}

}  // namespace

Result<int64_t> parseDurationLiteral(std::string_view text, bool unsignedRange, bool* saturated, uint64_t* unsignedBits) {
    using R = Result<int64_t>;
    const Result<std::string_view> stripped =
        stripPrefix(text, {"T", "TIME", "LT", "LTIME"}, "duration");
    if (!stripped) return R::failure(stripped.error());
    const std::string_view body = stripped.value();

    size_t pos = 0;
    bool negative = false;
    if (pos < body.size() && (body[pos] == '-' || body[pos] == '+')) {
        negative = body[pos] == '-';
        ++pos;
    }
    if (pos >= body.size()) return R::failure(fmt::format("duration literal {} has no value", quoted(text)));

    const __int128 kMagnitudeLimit = (static_cast<__int128>(1) << (unsignedRange ? 64 : 63)) - (unsignedRange ? 1 : 0);  // |INT64_MIN| or UINT64_MAX
    __int128 total = 0;
    int previousUnit = -1;
    bool sawFraction = false;
    int parts = 0;
    while (pos < body.size()) {
        if (parts > 0 && body[pos] == '_') ++pos;  // `T#1d_2h`
        if (pos >= body.size() || !isDecimal(body[pos])) {
            return R::failure(fmt::format("expected a number at '{}' in duration literal {}",
                                          body.substr(pos, 8), quoted(text)));
        }
        if (sawFraction) {
            return R::failure(fmt::format(
                "only the last unit may have a fraction in duration literal {}", quoted(text)));
        }
        const DigitScan whole = scanDigits(body, pos, 10);
        pos = whole.end;
        size_t fractionFrom = 0;
        size_t fractionTo = 0;
        if (pos < body.size() && body[pos] == '.') {
            const DigitScan fraction = scanDigits(body, pos + 1, 10);
            if (fraction.digits == 0) {
                return R::failure(fmt::format("a digit must follow '.' in duration literal {}", quoted(text)));
            }
            fractionFrom = pos + 1;
            fractionTo = fraction.end;
            pos = fraction.end;
            sawFraction = true;
        }
        const size_t unitStart = pos;
        while (pos < body.size() && isLetter(body[pos])) ++pos;
        const std::string_view unitName = body.substr(unitStart, pos - unitStart);
        if (unitName.empty()) {
            return R::failure(fmt::format("missing unit (d, h, m, s, ms, us, ns) in duration literal {}",
                                          quoted(text)));
        }
        int unit = -1;
        for (size_t u = 0; u < kDurationUnits.size(); ++u) {
            if (equalsIgnoreCase(unitName, kDurationUnits[u].name)) unit = static_cast<int>(u);
        }
        if (unit < 0) {
            return R::failure(fmt::format("unknown unit '{}' in duration literal {}", unitName, quoted(text)));
        }
        if (unit <= previousUnit) {
            return R::failure(fmt::format(
                "units must appear once each, in the order d h m s ms us ns, in duration literal {}",
                quoted(text)));
        }
        const DurationUnit& info = kDurationUnits[static_cast<size_t>(unit)];
        if (whole.overflow || static_cast<__int128>(whole.value) >= kMagnitudeLimit) {
            return R::failure(fmt::format("duration literal {} is out of range", quoted(text)));
        }
        if (parts > 0 && static_cast<int64_t>(whole.value) >= info.limitWhenNotFirst) {
            return R::failure(fmt::format("{}{} is out of range (must be below {}) in duration literal {}",
                                          whole.value, info.name, info.limitWhenNotFirst, quoted(text)));
        }
        total += static_cast<__int128>(whole.value) * info.ns;
        if (fractionTo > fractionFrom) total += fractionNs(body, fractionFrom, fractionTo, info.ns);
        if (total > kMagnitudeLimit) {
            return R::failure(fmt::format("duration literal {} is out of range (more than 292 years)",
                                          quoted(text)));
        }
        previousUnit = unit;
        ++parts;
    }
    constexpr __int128 kSignedLimit = static_cast<__int128>(1) << 63;
    if (negative) {
        if (total > kSignedLimit) return R::failure(fmt::format("duration literal {} is out of range", quoted(text)));
        return R::success(static_cast<int64_t>(-total));
    }
    if (total >= kSignedLimit) {
        if (!unsignedRange) return R::failure(fmt::format("duration literal {} is out of range", quoted(text)));
        if (saturated) *saturated = true;
        if (unsignedBits) *unsignedBits = static_cast<uint64_t>(total);
        return R::success(INT64_MAX);
    }
    return R::success(static_cast<int64_t>(total));
}

namespace {

// Reads 1..maxDigits decimal digits (no underscores) at pos.
bool readField(std::string_view text, size_t& pos, size_t maxDigits, int64_t& value) {
    const size_t start = pos;
    value = 0;
    while (pos < text.size() && isDecimal(text[pos])) {
        if (pos - start >= maxDigits) return false;
        value = value * 10 + (text[pos] - '0');
        ++pos;
    }
    return pos > start;
}

bool expectChar(std::string_view text, size_t& pos, char c) {
    if (pos < text.size() && text[pos] == c) {
        ++pos;
        return true;
    }
    return false;
}

// yyyy-mm-dd at pos -> ns since the epoch.
Result<int64_t> parseDatePart(std::string_view body, size_t& pos, std::string_view whole) {
    int64_t year = 0;
    int64_t month = 0;
    int64_t day = 0;
    if (!readField(body, pos, 6, year) || !expectChar(body, pos, '-') ||
        !readField(body, pos, 2, month) || !expectChar(body, pos, '-') ||
        !readField(body, pos, 2, day)) {
        return Result<int64_t>::failure(
            fmt::format("malformed date in {} (expected YYYY-MM-DD)", quoted(whole)));
    }
    const Result<int64_t> date = concatDate(year, month, day);
    if (!date) return Result<int64_t>::failure(fmt::format("invalid date {}: {}", quoted(whole), date.error()));
    return date;
}

// hh:mm[:ss[.fraction]] at pos -> ns since midnight.
Result<int64_t> parseTimeOfDayPart(std::string_view body, size_t& pos, std::string_view whole) {
    int64_t hour = 0;
    int64_t minute = 0;
    int64_t second = 0;
    int64_t fractionValueNs = 0;
    const auto malformed = [&]() {
        return Result<int64_t>::failure(
            fmt::format("malformed time of day in {} (expected HH:MM:SS.fff)", quoted(whole)));
    };
    if (!readField(body, pos, 2, hour) || !expectChar(body, pos, ':') ||
        !readField(body, pos, 2, minute)) {
        return malformed();
    }
    if (expectChar(body, pos, ':')) {
        if (!readField(body, pos, 2, second)) return malformed();
        if (expectChar(body, pos, '.')) {
            const size_t start = pos;
            int64_t scale = kNsPerSecond;
            while (pos < body.size() && isDecimal(body[pos])) {
                scale /= 10;  // digits beyond nanoseconds add 0 (truncation)
                fractionValueNs += (body[pos] - '0') * scale;
                ++pos;
            }
            if (pos == start) return malformed();
        }
    }
    const Result<int64_t> tod = concatTimeOfDay(hour, minute, second, 0);
    if (!tod) return Result<int64_t>::failure(fmt::format("invalid time of day {}: {}", quoted(whole), tod.error()));
    return Result<int64_t>::success(tod.value() + fractionValueNs);
}

Result<int64_t> requireEnd(Result<int64_t> value, std::string_view body, size_t pos,
                           std::string_view whole, std::string_view kind) {
    if (value && pos != body.size()) {
        return Result<int64_t>::failure(
            fmt::format("unexpected '{}' after the {} in {}", body.substr(pos, 8), kind, quoted(whole)));
    }
    return value;
}

}  // namespace

Result<int64_t> parseDateLiteral(std::string_view text) {
    const Result<std::string_view> body = stripPrefix(text, {"D", "DATE", "LD", "LDATE"}, "date");
    if (!body) return Result<int64_t>::failure(body.error());
    size_t pos = 0;
    Result<int64_t> date = parseDatePart(body.value(), pos, text);  // advances pos
    return requireEnd(std::move(date), body.value(), pos, text, "date");
}

Result<int64_t> parseTimeOfDayLiteral(std::string_view text) {
    const Result<std::string_view> body =
        stripPrefix(text, {"TOD", "TIME_OF_DAY", "LTOD", "LTIME_OF_DAY"}, "time-of-day");
    if (!body) return Result<int64_t>::failure(body.error());
    size_t pos = 0;
    Result<int64_t> tod = parseTimeOfDayPart(body.value(), pos, text);  // advances pos
    return requireEnd(std::move(tod), body.value(), pos, text, "time of day");
}

Result<int64_t> parseDateTimeLiteral(std::string_view text) {
    const Result<std::string_view> stripped =
        stripPrefix(text, {"DT", "DATE_AND_TIME", "LDT", "LDATE_AND_TIME"}, "date-and-time");
    if (!stripped) return Result<int64_t>::failure(stripped.error());
    const std::string_view body = stripped.value();
    size_t pos = 0;
    const Result<int64_t> date = parseDatePart(body, pos, text);
    if (!date) return date;
    if (!expectChar(body, pos, '-')) {
        return Result<int64_t>::failure(
            fmt::format("expected '-' between date and time in {}", quoted(text)));
    }
    const Result<int64_t> tod = parseTimeOfDayPart(body, pos, text);
    if (!tod) return tod;
    const Result<int64_t> combined = concatDateAndTimeOfDay(date.value(), tod.value());
    if (!combined) return Result<int64_t>::failure(fmt::format("{}: {}", quoted(text), combined.error()));
    return requireEnd(combined, body, pos, text, "date and time");
}

}  // namespace strun::stdlib
