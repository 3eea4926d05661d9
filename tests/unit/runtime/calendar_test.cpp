// Civil-date arithmetic and the time-event repeat rules (decision 0014).
#include <catch2/catch.hpp>

#include "runtime/civil_time.h"
#include "runtime/time_event.h"

using namespace strun::rt;

namespace {
int64_t at(int64_t year, int month, int day, int hour = 0, int minute = 0, int second = 0) {
    return daysFromCivil({year, month, day}) * kNanosPerDay + ((hour * 60 + minute) * 60 + second) * kNanosPerSecond;
}
}  // namespace

TEST_CASE("civil dates round-trip and know leap years", "[calendar]") {
    CHECK(daysFromCivil({1970, 1, 1}) == 0);
    CHECK(daysFromCivil({2000, 3, 1}) == 11017);
    CHECK(daysFromCivil({1969, 12, 31}) == -1);
    for (int64_t day = -800'000; day <= 800'000; day += 997) {
        CivilDate date = civilFromDays(day);
        REQUIRE(daysFromCivil(date) == day);
    }
    CHECK(isLeapYear(2024));
    CHECK_FALSE(isLeapYear(2023));
    CHECK_FALSE(isLeapYear(1900));
    CHECK(isLeapYear(2000));
    CHECK(daysInMonth(2024, 2) == 29);
    CHECK(daysInMonth(2100, 2) == 28);
    CHECK(daysInMonth(2023, 4) == 30);
    CHECK(dayOf(-1) == -1);
    CHECK(nanosOfDay(-1) == kNanosPerDay - 1);
}

TEST_CASE("ONCE fires at AT only, if not past", "[calendar]") {
    int64_t when = at(2024, 5, 1, 12);
    CHECK(nextTimeEventOccurrence(when, TimeRepeat::Once, when - 1) == when);
    CHECK(nextTimeEventOccurrence(when, TimeRepeat::Once, when) == when);
    CHECK(nextTimeEventOccurrence(when, TimeRepeat::Once, when + 1) == kNever);
}

TEST_CASE("HOURLY, DAILY and WEEKLY keep a fixed distance from AT", "[calendar]") {
    int64_t first = at(2024, 2, 28, 23, 30);
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::Hourly, first + 1) == at(2024, 2, 29, 0, 30));
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::Daily, first + 1) == at(2024, 2, 29, 23, 30));
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::Daily, at(2024, 3, 1)) == at(2024, 3, 1, 23, 30));
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::Weekly, first + 1) == at(2024, 3, 6, 23, 30));
    // A start before AT waits for AT itself.
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::Daily, at(2020, 1, 1)) == first);
}

TEST_CASE("MONTHLY keeps the day of month across month and year ends", "[calendar]") {
    int64_t first = at(2023, 11, 28, 6);
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::Monthly, first + 1) == at(2023, 12, 28, 6));
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::Monthly, at(2023, 12, 28, 7)) == at(2024, 1, 28, 6));
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::Monthly, at(2024, 2, 1)) == at(2024, 2, 28, 6));
    // Day 31 (rejected by the task rules) falls on the last day of shorter months.
    int64_t thirtyFirst = at(2024, 1, 31, 8);
    CHECK(timeEventOccurrence(thirtyFirst, TimeRepeat::Monthly, 1) == at(2024, 2, 29, 8));
    CHECK(timeEventOccurrence(thirtyFirst, TimeRepeat::Monthly, 2) == at(2024, 3, 31, 8));
    CHECK(timeEventOccurrence(thirtyFirst, TimeRepeat::Monthly, 3) == at(2024, 4, 30, 8));
}

TEST_CASE("MONTH_END is the last day of every month, leap Februaries included", "[calendar]") {
    int64_t first = at(2023, 12, 15, 22);  // only the time of day and the start month count
    CHECK(timeEventOccurrence(first, TimeRepeat::MonthEnd, 0) == at(2023, 12, 31, 22));
    CHECK(timeEventOccurrence(first, TimeRepeat::MonthEnd, 1) == at(2024, 1, 31, 22));
    CHECK(timeEventOccurrence(first, TimeRepeat::MonthEnd, 2) == at(2024, 2, 29, 22));
    CHECK(timeEventOccurrence(first, TimeRepeat::MonthEnd, 14) == at(2025, 2, 28, 22));
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::MonthEnd, at(2024, 4, 30, 22) + 1) == at(2024, 5, 31, 22));
    CHECK(nextTimeEventOccurrence(first, TimeRepeat::MonthEnd, at(2100, 2, 1)) == at(2100, 2, 28, 22));
}

TEST_CASE("YEARLY keeps month and day; 29 February falls on 28 February in common years", "[calendar]") {
    int64_t leapDay = at(2024, 2, 29, 12);
    CHECK(nextTimeEventOccurrence(leapDay, TimeRepeat::Yearly, leapDay + 1) == at(2025, 2, 28, 12));
    CHECK(nextTimeEventOccurrence(leapDay, TimeRepeat::Yearly, at(2027, 3, 1)) == at(2028, 2, 29, 12));
    int64_t newYear = at(2020, 1, 1);
    CHECK(nextTimeEventOccurrence(newYear, TimeRepeat::Yearly, at(2024, 6, 1)) == at(2025, 1, 1));
}

TEST_CASE("occurrences beyond the representable range never come", "[calendar]") {
    CHECK(nextTimeEventOccurrence(at(2024, 1, 1), TimeRepeat::Yearly, at(2262, 1, 1)) == kNever);
    CHECK(timeEventOccurrence(0, TimeRepeat::Weekly, int64_t(1) << 60) == kNever);
}
