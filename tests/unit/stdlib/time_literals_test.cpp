#include <catch2/catch.hpp>

#include <string>

#include "stdlib/calendar.h"
#include "stdlib/time_literals.h"

using namespace strun::stdlib;

namespace {
constexpr int64_t ms = kNsPerMs;
constexpr int64_t s = kNsPerSecond;
}  // namespace

TEST_CASE("duration literals: prefixes and units", "[time_literals]") {
    CHECK(parseDurationLiteral("T#1h2m3s4ms").value() == kNsPerHour + 2 * kNsPerMinute + 3 * s + 4 * ms);
    CHECK(parseDurationLiteral("TIME#-5s").value() == -5 * s);
    CHECK(parseDurationLiteral("LT#1us").value() == 1000);
    CHECK(parseDurationLiteral("LTIME#1.5s").value() == 1500 * ms);
    CHECK(parseDurationLiteral("t#1d_2h").value() == kNsPerDay + 2 * kNsPerHour);
    CHECK(parseDurationLiteral("T#1.5s").value() == 1500 * ms);
    CHECK(parseDurationLiteral("T#-250ms").value() == -250 * ms);
    CHECK(parseDurationLiteral("time#5NS").value() == 5);
    CHECK(parseDurationLiteral("Ltime#1D").value() == kNsPerDay);
    CHECK(parseDurationLiteral("T#0s").value() == 0);
    CHECK(parseDurationLiteral("T#-0s").value() == 0);
    CHECK(parseDurationLiteral("T#+3ms").value() == 3 * ms);
    CHECK(parseDurationLiteral("T#1_000ms").value() == 1000 * ms);
    CHECK(parseDurationLiteral("T#1m1.5s").value() == 61500 * ms);
    CHECK(parseDurationLiteral("T#0.5d").value() == 12 * kNsPerHour);
    CHECK(parseDurationLiteral("T#1ms500us").value() == 1500 * 1000);
    CHECK(parseDurationLiteral("T#1s_500ms").value() == 1500 * ms);
}

TEST_CASE("duration literals: bare command-line forms", "[time_literals]") {
    CHECK(parseDurationLiteral("150ms").value() == 150 * ms);
    CHECK(parseDurationLiteral("2s").value() == 2 * s);
    CHECK(parseDurationLiteral("1us").value() == 1000);
    CHECK(parseDurationLiteral("1h30m").value() == 90 * kNsPerMinute);
    CHECK(parseDurationLiteral("-20ms").value() == -20 * ms);
}

TEST_CASE("duration literals: overflow of the leading unit only", "[time_literals]") {
    CHECK(parseDurationLiteral("T#25h").value() == 25 * kNsPerHour);
    CHECK(parseDurationLiteral("T#25h_15m").value() == 25 * kNsPerHour + 15 * kNsPerMinute);
    CHECK(parseDurationLiteral("T#90m").value() == 90 * kNsPerMinute);
    CHECK(parseDurationLiteral("T#1500ms").value() == 1500 * ms);
    CHECK_FALSE(parseDurationLiteral("T#1h75m").ok());
    CHECK_FALSE(parseDurationLiteral("T#1d24h").ok());
    CHECK_FALSE(parseDurationLiteral("T#1s1000ms").ok());
    CHECK_FALSE(parseDurationLiteral("T#1m60s").ok());
    CHECK(parseDurationLiteral("T#1m59.999s").ok());
}

TEST_CASE("duration literals: fractions", "[time_literals]") {
    CHECK(parseDurationLiteral("T#0.001ms").value() == 1000);
    CHECK(parseDurationLiteral("T#1.9ns").value() == 1);  // below 1 ns: truncated
    CHECK(parseDurationLiteral("T#-1.5ms").value() == -1500 * 1000);
    CHECK(parseDurationLiteral("T#0.1234567890123456789999s").value() == 123456789);
    CHECK(parseDurationLiteral("T#1.000_001s").value() == s + 1000);
    CHECK_FALSE(parseDurationLiteral("T#1.5s200ms").ok());  // fraction only on the last unit
    CHECK_FALSE(parseDurationLiteral("T#1.s").ok());
    CHECK_FALSE(parseDurationLiteral("T#.5s").ok());
}

TEST_CASE("duration literals: range", "[time_literals]") {
    // int64 ns: 9223372036854775807 ns = 106751d23h47m16s854ms775us807ns
    CHECK(parseDurationLiteral("LT#106751d23h47m16s854ms775us807ns").value() == INT64_MAX);
    CHECK(parseDurationLiteral("LT#-106751d23h47m16s854ms775us808ns").value() == INT64_MIN);
    CHECK_FALSE(parseDurationLiteral("LT#106751d23h47m16s854ms775us808ns").ok());
    CHECK_FALSE(parseDurationLiteral("LT#106752d").ok());
    CHECK_FALSE(parseDurationLiteral("T#99999999999999999999999999ms").ok());
    CHECK_FALSE(parseDurationLiteral("T#" + std::string(5000, '9') + "s").ok());
}

TEST_CASE("duration literals: errors", "[time_literals]") {
    for (const char* bad : {"", "T#", "T#-", "T#5", "T#s", "T#5x", "T#1s1s", "T#1s1h", "T#1ms1s",
                            "X#1s", "TOD#1s", "T#1s_", "T#_1s", "T#1__s", "T#1s ", "T# 1s", "T#1m_s",
                            "T#--1s", "5", "ms"}) {
        INFO(bad);
        const Result<int64_t> parsed = parseDurationLiteral(bad);
        CHECK_FALSE(parsed.ok());
        CHECK_FALSE(parsed.error().empty());
    }
    CHECK(parseDurationLiteral("T#1__0s").value() == 10 * kNsPerSecond);  // several underscores (decision 0326)
    CHECK(parseDurationLiteral("T#1s1h").error().find("order") != std::string::npos);
    CHECK(parseDurationLiteral("T#5x").error().find("unknown unit") != std::string::npos);
    CHECK(parseDurationLiteral("X#1s").error().find("prefix") != std::string::npos);
}

TEST_CASE("date literals", "[time_literals]") {
    CHECK(parseDateLiteral("D#2026-01-31").value() == 20484 * kNsPerDay);
    CHECK(parseDateLiteral("DATE#1970-01-01").value() == 0);
    CHECK(parseDateLiteral("LD#2024-02-29").value() == 19782 * kNsPerDay);
    CHECK(parseDateLiteral("LDATE#1969-12-31").value() == -kNsPerDay);
    CHECK(parseDateLiteral("d#1900-01-01").value() == -25567 * kNsPerDay);
    CHECK(parseDateLiteral("2026-01-31").value() == 20484 * kNsPerDay);
    CHECK(parseDateLiteral("D#2019-9-9").value() == parseDateLiteral("D#2019-09-09").value());
    CHECK(parseDateLiteral("D#1677-09-22").value() == -106751 * kNsPerDay);
    CHECK(parseDateLiteral("D#2262-04-11").value() == 106751 * kNsPerDay);
    CHECK(parseDateLiteral("D#2000-02-29").ok());
    CHECK(parseDateLiteral("D#2023-12-31").ok());
}

TEST_CASE("date literals: validation", "[time_literals]") {
    for (const char* bad : {"D#2023-02-29", "D#1900-02-29", "D#2026-13-01", "D#2026-00-10",
                            "D#2026-04-31", "D#2026-01-00", "D#2026-01-32", "D#0000-01-01",
                            "D#1677-09-21", "D#2262-04-12", "D#2026-01", "D#2026/01/31",
                            "D#2026-01-31x", "D#2026-001-01", "D#", "DT#2026-01-31", "D#-2026-01-01",
                            "D#2026-1_0-01"}) {
        INFO(bad);
        const Result<int64_t> parsed = parseDateLiteral(bad);
        CHECK_FALSE(parsed.ok());
        CHECK_FALSE(parsed.error().empty());
    }
    CHECK(parseDateLiteral("D#2023-02-29").error().find("day") != std::string::npos);
    CHECK(parseDateLiteral("D#2026-13-01").error().find("month") != std::string::npos);
}

TEST_CASE("time-of-day literals", "[time_literals]") {
    CHECK(parseTimeOfDayLiteral("TOD#13:05:00.25").value() == 13 * kNsPerHour + 5 * kNsPerMinute + 250 * ms);
    CHECK(parseTimeOfDayLiteral("TIME_OF_DAY#00:00:00").value() == 0);
    CHECK(parseTimeOfDayLiteral("LTOD#23:59:59.999999999").value() == kNsPerDay - 1);
    CHECK(parseTimeOfDayLiteral("ltime_of_day#12:00:00").value() == 12 * kNsPerHour);
    CHECK(parseTimeOfDayLiteral("TOD#14:20").value() == 14 * kNsPerHour + 20 * kNsPerMinute);
    CHECK(parseTimeOfDayLiteral("TOD#1:2:3").value() == kNsPerHour + 2 * kNsPerMinute + 3 * s);
    CHECK(parseTimeOfDayLiteral("TOD#00:00:00.1234567891").value() == 123456789);
    CHECK(parseTimeOfDayLiteral("08:30:00").value() == 8 * kNsPerHour + 30 * kNsPerMinute);
    for (const char* bad : {"TOD#24:00:00", "TOD#12:60:00", "TOD#12:00:60", "TOD#12", "TOD#12:00:",
                            "TOD#12:00:00.", "TOD#-1:00:00", "TOD#12:00:00x", "TOD#123:00:00", "T#12:00:00"}) {
        INFO(bad);
        CHECK_FALSE(parseTimeOfDayLiteral(bad).ok());
    }
}

TEST_CASE("date-and-time literals", "[time_literals]") {
    CHECK(parseDateTimeLiteral("DT#2026-01-31-13:05:00.5").value() ==
          20484 * kNsPerDay + 13 * kNsPerHour + 5 * kNsPerMinute + 500 * ms);
    CHECK(parseDateTimeLiteral("DATE_AND_TIME#1970-01-01-00:00:00").value() == 0);
    CHECK(parseDateTimeLiteral("LDT#1969-12-31-23:59:59").value() == -s);
    CHECK(parseDateTimeLiteral("ldate_and_time#2024-02-29-12:00:00").value() == 19782 * kNsPerDay + 12 * kNsPerHour);
    CHECK(parseDateTimeLiteral("DT#2019-9-9-1:1:1.1").value() ==
          parseDateTimeLiteral("DT#2019-09-09-01:01:01.100").value());
    CHECK(parseDateTimeLiteral("DT#1998-02-13-14:20").ok());
    CHECK(parseDateTimeLiteral("2026-01-31-13:05:00").ok());
    CHECK(parseDateTimeLiteral("LDT#2262-04-11-23:47:16.854775807").value() == INT64_MAX);
    for (const char* bad : {"DT#2262-04-11-23:47:16.854775808", "DT#2023-02-29-00:00:00",
                            "DT#2026-01-31", "DT#2026-01-31 13:05:00", "DT#2026-01-31-25:00:00",
                            "DT#2026-01-31-13:05:00-", "D#2026-01-31-13:05:00"}) {
        INFO(bad);
        CHECK_FALSE(parseDateTimeLiteral(bad).ok());
    }
}
