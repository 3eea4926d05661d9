#include <catch2/catch.hpp>

#include "stdlib/calendar.h"

using namespace strun::stdlib;

TEST_CASE("leap years and month lengths", "[calendar]") {
    CHECK(isLeapYear(2024));
    CHECK_FALSE(isLeapYear(2023));
    CHECK_FALSE(isLeapYear(1900));
    CHECK(isLeapYear(2000));
    CHECK(isLeapYear(1600));
    CHECK(isLeapYear(-4));  // proleptic: year -4 (5 BC) is a leap year
    CHECK(daysInMonth(2024, 2) == 29);
    CHECK(daysInMonth(2023, 2) == 28);
    CHECK(daysInMonth(2023, 1) == 31);
    CHECK(daysInMonth(2023, 4) == 30);
    CHECK(daysInMonth(2023, 12) == 31);
    CHECK(daysInMonth(2023, 0) == 0);
    CHECK(daysInMonth(2023, 13) == 0);
    CHECK(isValidDate(2024, 2, 29));
    CHECK_FALSE(isValidDate(2023, 2, 29));
    CHECK_FALSE(isValidDate(2023, 6, 31));
    CHECK_FALSE(isValidDate(2023, 6, 0));
}

TEST_CASE("days from civil and back", "[calendar]") {
    CHECK(daysFromCivil(1970, 1, 1) == 0);
    CHECK(daysFromCivil(2026, 1, 31) == 20484);
    CHECK(daysFromCivil(2024, 2, 29) == 19782);
    CHECK(daysFromCivil(1969, 12, 31) == -1);
    CHECK(daysFromCivil(1900, 1, 1) == -25567);
    CHECK(daysFromCivil(2000, 3, 1) == 11017);
    CHECK(daysFromCivil(1600, 2, 29) == -135081);
    CHECK(civilFromDays(20484) == CivilDate{2026, 1, 31});
    CHECK(civilFromDays(-1) == CivilDate{1969, 12, 31});
    CHECK(civilFromDays(-135081) == CivilDate{1600, 2, 29});
    // Every day over a few centuries converts back to itself.
    for (int64_t day = -150'000; day <= 150'000; day += 7) {
        const CivilDate date = civilFromDays(day);
        REQUIRE(isValidDate(date.year, date.month, date.day));
        REQUIRE(daysFromCivil(date.year, date.month, date.day) == day);
    }
}

TEST_CASE("day of week: 0 is Sunday", "[calendar]") {
    CHECK(dayOfWeek(0) == 4);                          // 1970-01-01 Thursday
    CHECK(dayOfWeek(daysFromCivil(2026, 1, 31)) == 6);  // Saturday
    CHECK(dayOfWeek(daysFromCivil(2026, 2, 1)) == 0);   // Sunday
    CHECK(dayOfWeek(daysFromCivil(2024, 2, 29)) == 4);
    CHECK(dayOfWeek(-1) == 3);                         // 1969-12-31 Wednesday
    CHECK(dayOfWeek(daysFromCivil(1900, 1, 1)) == 1);   // Monday
    CHECK(dayOfWeek(-8) == 3);
}

TEST_CASE("floor division helpers", "[calendar]") {
    CHECK(floorDiv(7, 2) == 3);
    CHECK(floorDiv(-7, 2) == -4);
    CHECK(floorDiv(-8, 2) == -4);
    CHECK(floorMod(-7, 2) == 1);
    CHECK(floorMod(7, 2) == 1);
    CHECK(floorMod(-1, kNsPerDay) == kNsPerDay - 1);
    CHECK(floorDiv(INT64_MIN, kNsPerDay) == -106752);
    CHECK(floorMod(INT64_MIN, kNsPerDay) == 763'145'224'192);
}

TEST_CASE("split time of day and date-time", "[calendar]") {
    const TimeOfDayParts tod = splitTimeOfDay(13 * kNsPerHour + 5 * kNsPerMinute + 7 * kNsPerSecond + 250 * kNsPerMs);
    CHECK(tod == TimeOfDayParts{13, 5, 7, 250 * kNsPerMs});
    CHECK(tod.millisecond() == 250);
    CHECK(splitTimeOfDay(kNsPerDay + 1) == TimeOfDayParts{0, 0, 0, 1});
    CHECK(splitTimeOfDay(-1) == TimeOfDayParts{23, 59, 59, 999'999'999});

    const DateTimeParts dt = splitDateTime(daysFromCivil(2024, 2, 29) * kNsPerDay + 23 * kNsPerHour + 59 * kNsPerMinute +
                                           59 * kNsPerSecond + 999 * kNsPerMs);
    CHECK(dt == DateTimeParts{2024, 2, 29, 23, 59, 59, 999 * kNsPerMs});
    CHECK(dt.millisecond() == 999);
    CHECK(splitDateTime(-1) == DateTimeParts{1969, 12, 31, 23, 59, 59, 999'999'999});
    CHECK(splitDateTime(0) == DateTimeParts{1970, 1, 1, 0, 0, 0, 0});
}

TEST_CASE("concat date, time of day, date-time", "[calendar]") {
    CHECK(concatDate(2026, 1, 31).value() == 20484 * kNsPerDay);
    CHECK(concatDate(2024, 2, 29).ok());
    CHECK(concatDate(1969, 12, 31).value() == -kNsPerDay);
    CHECK_FALSE(concatDate(2023, 2, 29).ok());
    CHECK_FALSE(concatDate(2023, 13, 1).ok());
    CHECK_FALSE(concatDate(2023, 0, 1).ok());
    CHECK_FALSE(concatDate(2023, 1, 0).ok());
    CHECK_FALSE(concatDate(0, 1, 1).ok());
    CHECK_FALSE(concatDate(10000, 1, 1).ok());
    CHECK_FALSE(concatDate(1600, 1, 1).ok());  // before the int64 ns range
    CHECK(concatDate(1600, 1, 1).error().find("range") != std::string::npos);
    CHECK(concatDate(2023, 2, 29).error().find("day 29") != std::string::npos);

    CHECK(concatTimeOfDay(13, 5, 0, 250).value() == 13 * kNsPerHour + 5 * kNsPerMinute + 250 * kNsPerMs);
    CHECK(concatTimeOfDay(23, 59, 59, 999).value() == kNsPerDay - kNsPerMs);
    CHECK_FALSE(concatTimeOfDay(24, 0, 0, 0).ok());
    CHECK_FALSE(concatTimeOfDay(-1, 0, 0, 0).ok());
    CHECK_FALSE(concatTimeOfDay(0, 60, 0, 0).ok());
    CHECK_FALSE(concatTimeOfDay(0, 0, 60, 0).ok());
    CHECK_FALSE(concatTimeOfDay(0, 0, 0, 1000).ok());

    CHECK(concatDateTime(2026, 1, 31, 13, 5, 0, 500).value() ==
          20484 * kNsPerDay + 13 * kNsPerHour + 5 * kNsPerMinute + 500 * kNsPerMs);
    CHECK(concatDateTime(1969, 12, 31, 23, 59, 59, 0).value() == -kNsPerSecond);
    CHECK_FALSE(concatDateTime(2023, 2, 29, 0, 0, 0, 0).ok());
    CHECK_FALSE(concatDateTime(2023, 2, 28, 0, 0, 0, -1).ok());
    CHECK_FALSE(concatDateTime(2262, 4, 11, 23, 59, 59, 0).ok());  // beyond INT64_MAX ns

    CHECK(concatDateAndTimeOfDay(kNsPerDay, kNsPerHour).value() == kNsPerDay + kNsPerHour);
    CHECK(concatDateAndTimeOfDay(-kNsPerDay, 0).value() == -kNsPerDay);
    CHECK_FALSE(concatDateAndTimeOfDay(kNsPerDay + 1, 0).ok());
    CHECK_FALSE(concatDateAndTimeOfDay(0, kNsPerDay).ok());
    CHECK_FALSE(concatDateAndTimeOfDay(0, -1).ok());
}

TEST_CASE("add months with end-of-month clamping", "[calendar]") {
    auto date = [](int64_t y, int m, int d) { return daysFromCivil(y, m, d); };
    CHECK(addMonthsToDays(date(2026, 1, 31), 1).value() == date(2026, 2, 28));
    CHECK(addMonthsToDays(date(2024, 1, 31), 1).value() == date(2024, 2, 29));
    CHECK(addMonthsToDays(date(2024, 3, 31), 1).value() == date(2024, 4, 30));
    CHECK(addMonthsToDays(date(2024, 12, 15), 1).value() == date(2025, 1, 15));
    CHECK(addMonthsToDays(date(2024, 2, 29), 12).value() == date(2025, 2, 28));
    CHECK(addMonthsToDays(date(2024, 2, 29), 48).value() == date(2028, 2, 29));
    CHECK(addMonthsToDays(date(2026, 1, 15), -1).value() == date(2025, 12, 15));
    CHECK(addMonthsToDays(date(2026, 3, 31), -1).value() == date(2026, 2, 28));
    CHECK(addMonthsToDays(date(1970, 1, 1), -1).value() == date(1969, 12, 1));
    CHECK(addMonthsToDays(date(2026, 5, 5), 0).value() == date(2026, 5, 5));
    CHECK_FALSE(addMonthsToDays(0, INT64_MAX).ok());
    CHECK_FALSE(addMonthsToDays(0, INT64_MIN).ok());

    const int64_t start = date(2026, 1, 31) * kNsPerDay + 8 * kNsPerHour;
    CHECK(addMonths(start, 1).value() == date(2026, 2, 28) * kNsPerDay + 8 * kNsPerHour);
    CHECK(addMonths(-kNsPerHour, 1).value() == date(1970, 1, 31) * kNsPerDay + 23 * kNsPerHour);
    CHECK_FALSE(addMonths(date(2262, 1, 1) * kNsPerDay, 12).ok());
}
