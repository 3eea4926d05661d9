#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "stdlib/calendar.h"
#include "stdlib/literals.h"
#include "stdlib/time_literals.h"
#include "stdlib/value_format.h"

using namespace strun::stdlib;

TEST_CASE("formatDuration", "[value_format]") {
    CHECK(formatDuration(0) == "T#0s");
    CHECK(formatDuration(1500 * kNsPerMs) == "T#1s500ms");
    CHECK(formatDuration(-250 * kNsPerMs) == "T#-250ms");
    CHECK(formatDuration(kNsPerDay + 2 * kNsPerHour + 3 * kNsPerMinute + 4 * kNsPerSecond + 5 * kNsPerMs) ==
          "T#1d2h3m4s5ms");
    CHECK(formatDuration(kNsPerMs + 500 * kNsPerUs) == "T#1ms500us");
    CHECK(formatDuration(5) == "T#5ns");
    CHECK(formatDuration(kNsPerHour + 1) == "T#1h1ns");
    CHECK(formatDuration(25 * kNsPerHour) == "T#1d1h");
    CHECK(formatDuration(-(kNsPerMinute + kNsPerSecond)) == "T#-1m1s");
    CHECK(formatDuration(INT64_MAX) == "T#106751d23h47m16s854ms775us807ns");
    CHECK(formatDuration(INT64_MIN) == "T#-106751d23h47m16s854ms775us808ns");
    CHECK(formatDuration(2 * kNsPerSecond, "LTIME#") == "LTIME#2s");
    CHECK(formatDuration(0, "LTIME#") == "LTIME#0s");
}

TEST_CASE("formatDuration round-trips through parseDurationLiteral", "[value_format]") {
    for (int64_t ns : {int64_t{0}, int64_t{1}, int64_t{-1}, 999 * kNsPerMs, -kNsPerDay - 7, INT64_MAX,
                       INT64_MIN, 123456789012345, -98765432101}) {
        INFO(ns);
        CHECK(parseDurationLiteral(formatDuration(ns)).value() == ns);
    }
}

TEST_CASE("formatDate / formatTimeOfDay / formatDateTime", "[value_format]") {
    CHECK(formatDate(20484 * kNsPerDay) == "D#2026-01-31");
    CHECK(formatDate(0) == "D#1970-01-01");
    CHECK(formatDate(-kNsPerDay) == "D#1969-12-31");
    CHECK(formatDate(-1) == "D#1969-12-31");  // floors: one ns before 1970 is still 1969-12-31
    CHECK(formatDate(19782 * kNsPerDay + 5) == "D#2024-02-29");
    CHECK(formatDate(-25567 * kNsPerDay, "LD#") == "LD#1900-01-01");

    CHECK(formatTimeOfDay(13 * kNsPerHour + 5 * kNsPerMinute) == "TOD#13:05:00");
    CHECK(formatTimeOfDay(13 * kNsPerHour + 5 * kNsPerMinute + 250 * kNsPerMs) == "TOD#13:05:00.25");
    CHECK(formatTimeOfDay(0) == "TOD#00:00:00");
    CHECK(formatTimeOfDay(kNsPerDay - 1) == "TOD#23:59:59.999999999");
    CHECK(formatTimeOfDay(kNsPerMs) == "TOD#00:00:00.001");
    CHECK(formatTimeOfDay(kNsPerDay + kNsPerHour) == "TOD#01:00:00");  // modulo one day
    CHECK(formatTimeOfDay(5 * kNsPerHour, "LTOD#") == "LTOD#05:00:00");

    CHECK(formatDateTime(20484 * kNsPerDay + 13 * kNsPerHour + 5 * kNsPerMinute) == "DT#2026-01-31-13:05:00");
    CHECK(formatDateTime(20484 * kNsPerDay + 500 * kNsPerMs) == "DT#2026-01-31-00:00:00.5");
    CHECK(formatDateTime(-kNsPerSecond) == "DT#1969-12-31-23:59:59");
    CHECK(formatDateTime(0) == "DT#1970-01-01-00:00:00");
    CHECK(formatDateTime(INT64_MAX) == "DT#2262-04-11-23:47:16.854775807");
    CHECK(formatDateTime(INT64_MIN) == "DT#1677-09-21-00:12:43.145224192");
    CHECK(formatDateTime(kNsPerDay, "LDT#") == "LDT#1970-01-02-00:00:00");
}

TEST_CASE("date and time formats round-trip through the parsers", "[value_format]") {
    for (int64_t ns : {int64_t{0}, -kNsPerSecond, 20484 * kNsPerDay + 47 * kNsPerMs, INT64_MAX,
                       -106751 * kNsPerDay + 1}) {
        INFO(ns);
        CHECK(parseDateTimeLiteral(formatDateTime(ns)).value() == ns);
    }
    for (int64_t ns : {int64_t{0}, kNsPerDay - 1, 12 * kNsPerHour + 1}) {
        CHECK(parseTimeOfDayLiteral(formatTimeOfDay(ns)).value() == ns);
    }
}

TEST_CASE("formatReal / formatLReal (REAL_TO_STRING)", "[value_format]") {
    CHECK(formatReal(1.5f) == "1.5");
    CHECK(formatReal(0.1f) == "0.1");
    CHECK(formatReal(1.0f) == "1");
    CHECK(formatReal(100.0f) == "100");
    CHECK(formatReal(-2.25f) == "-2.25");
    CHECK(formatReal(0.0f) == "0");
    CHECK(formatReal(-0.0f) == "0");
    CHECK(formatReal(1.0e38f) == "1E+38");
    CHECK(formatReal(3.4028235e38f) == "3.4028235E+38");
    CHECK(formatReal(1.5e-7f) == "1.5E-07");
    CHECK(formatReal(0.00001f) == "0.00001");
    CHECK(formatReal(123456.7f) == "123456.7");
    CHECK(formatReal(16777216.0f) == "16777216");
    CHECK(formatReal(std::numeric_limits<float>::infinity()) == "INF");
    CHECK(formatReal(-std::numeric_limits<float>::infinity()) == "-INF");
    CHECK(formatReal(std::nanf("")) == "NAN");

    CHECK(formatLReal(0.1) == "0.1");
    CHECK(formatLReal(1.0 / 3.0) == "0.3333333333333333");
    CHECK(formatLReal(1e15) == "1E+15");
    CHECK(formatLReal(999999999999999.0) == "999999999999999");
    CHECK(formatLReal(1.7976931348623157e308) == "1.7976931348623157E+308");
    CHECK(formatLReal(5e-324) == "5E-324");
    CHECK(formatLReal(-1234.5) == "-1234.5");
    // REAL keeps the float's shortest digits, not the double's.
    CHECK(formatLReal(static_cast<double>(0.1f)) == "0.10000000149011612");
}

TEST_CASE("formatReal output reads back as the same value", "[value_format]") {
    for (float value : {0.1f, 1.5f, 3.14159265f, 1e38f, 1e-38f, 123456.789f, -7.0e-6f}) {
        INFO(value);
        CHECK(static_cast<float>(parseRealLiteral(formatReal(value)).value()) == value);
    }
    for (double value : {0.1, 2.718281828459045, 1e300, -4.9e-324, 12345678.9}) {
        INFO(value);
        CHECK(parseRealLiteral(formatLReal(value)).value() == value);
    }
}

TEST_CASE("JSON number text", "[value_format]") {
    CHECK(formatRealJson(0.1f) == "0.1");
    CHECK(formatRealJson(1.0f) == "1");
    CHECK(formatRealJson(1e38f) == "1e+38");
    CHECK(formatLRealJson(0.1) == "0.1");
    CHECK(formatLRealJson(-2.5) == "-2.5");
    CHECK(formatLRealJson(std::numeric_limits<double>::infinity()) == "inf");
    CHECK(formatLRealJson(-std::numeric_limits<double>::infinity()) == "-inf");
    CHECK(formatLRealJson(std::nan("")) == "nan");
    CHECK(formatRealJson(std::nanf("")) == "nan");
}
