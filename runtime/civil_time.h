// Proleptic Gregorian calendar arithmetic on "calendar nanoseconds" (ns since
// 1970-01-01-00:00:00, no time zone, no leap seconds), as PLC date-times are.
// Used by the time-event tasks; self-contained so the runtime does not depend
// on the stdlib's calendar.
#pragma once

#include <cstdint>

namespace strun::rt {

constexpr int64_t kNanosPerSecond = 1'000'000'000;
constexpr int64_t kNanosPerDay = 86'400 * kNanosPerSecond;

struct CivilDate {
    int64_t year = 1970;
    int month = 1;  // 1..12
    int day = 1;    // 1..31
};

bool isLeapYear(int64_t year);
int daysInMonth(int64_t year, int month);
// Days since 1970-01-01 of a civil date (month and day must be valid).
int64_t daysFromCivil(const CivilDate& date);
CivilDate civilFromDays(int64_t days);

// Split calendar nanoseconds into the day number and the nanoseconds into that day
// (always 0 <= nanosOfDay < kNanosPerDay, also before 1970).
int64_t dayOf(int64_t calendarNanos);
int64_t nanosOfDay(int64_t calendarNanos);

}  // namespace strun::rt
