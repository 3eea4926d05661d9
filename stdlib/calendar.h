// Proleptic Gregorian calendar arithmetic on the interpreter's nanosecond
// time line (0 = 1970-01-01-00:00:00, negative before), and the IEC 61131-3
// date/time functions built on it: SPLIT_*, CONCAT_*, DAY_OF_WEEK, plus the
// month arithmetic that MONTHLY / YEARLY time events need.
#pragma once

#include <cstdint>

#include "stdlib/result.h"

namespace strun::stdlib {

inline constexpr int64_t kNsPerUs = 1'000;
inline constexpr int64_t kNsPerMs = 1'000'000;
inline constexpr int64_t kNsPerSecond = 1'000'000'000;
inline constexpr int64_t kNsPerMinute = 60 * kNsPerSecond;
inline constexpr int64_t kNsPerHour = 60 * kNsPerMinute;
inline constexpr int64_t kNsPerDay = 24 * kNsPerHour;
inline constexpr int64_t kSecondsPerDay = 86'400;

// Years accepted by the validating functions (concat*, literal parsing).
inline constexpr int64_t kMinYear = 1;
inline constexpr int64_t kMaxYear = 9999;

bool isLeapYear(int64_t year);
// 28..31; 0 when month is outside 1..12.
int daysInMonth(int64_t year, int64_t month);
bool isValidDate(int64_t year, int64_t month, int64_t day);

// Days since 1970-01-01 for a valid civil date (any year whose day count fits;
// callers validate month/day first). Howard Hinnant's algorithm.
int64_t daysFromCivil(int64_t year, int month, int day);

struct CivilDate {
    int64_t year = 1970;
    int month = 1;  // 1..12
    int day = 1;    // 1..31
    bool operator==(const CivilDate&) const = default;
};
CivilDate civilFromDays(int64_t daysSinceEpoch);

// IEC DAY_OF_WEEK: 0 = Sunday .. 6 = Saturday.
int dayOfWeek(int64_t daysSinceEpoch);

// Floor division helpers: the day containing a nanosecond instant and the
// position inside that day (always 0 <= result < kNsPerDay), also for instants before 1970.
int64_t floorDiv(int64_t value, int64_t divisor);
int64_t floorMod(int64_t value, int64_t divisor);

struct TimeOfDayParts {
    int hour = 0;
    int minute = 0;
    int second = 0;
    int64_t nanosecond = 0;  // 0..999'999'999
    int millisecond() const { return static_cast<int>(nanosecond / kNsPerMs); }
    bool operator==(const TimeOfDayParts&) const = default;
};

struct DateTimeParts {
    int64_t year = 1970;
    int month = 1;
    int day = 1;
    int hour = 0;
    int minute = 0;
    int second = 0;
    int64_t nanosecond = 0;  // 0..999'999'999
    int millisecond() const { return static_cast<int>(nanosecond / kNsPerMs); }
    bool operator==(const DateTimeParts&) const = default;
};

// SPLIT_TOD / SPLIT_LTOD: the value is taken modulo one day first, so every
// input splits into a valid time of day.
TimeOfDayParts splitTimeOfDay(int64_t nsSinceMidnight);
// SPLIT_DATE / SPLIT_DT / SPLIT_LDT (the time fields are 0 for a pure date).
DateTimeParts splitDateTime(int64_t nsSinceEpoch);

// CONCAT_DATE / CONCAT_LDATE: ns since epoch of that date at 00:00.
// Errors: month outside 1..12, day outside the month, year outside kMinYear..kMaxYear,
// or a date beyond the int64 nanosecond range (1677-09-22 .. 2262-04-11).
Result<int64_t> concatDate(int64_t year, int64_t month, int64_t day);
// CONCAT_TOD / CONCAT_LTOD: ns since midnight. hour 0..23, minute 0..59,
// second 0..59, millisecond 0..999.
Result<int64_t> concatTimeOfDay(int64_t hour, int64_t minute, int64_t second, int64_t millisecond);
// CONCAT_DT / CONCAT_LDT.
Result<int64_t> concatDateTime(int64_t year, int64_t month, int64_t day, int64_t hour,
                               int64_t minute, int64_t second, int64_t millisecond);
// CONCAT_DATE_TOD / CONCAT_DATE_LTOD: dateNs must be a midnight, 0 <= todNs < one day.
Result<int64_t> concatDateAndTimeOfDay(int64_t dateNs, int64_t todNs);

// Calendar month arithmetic for MONTHLY / YEARLY events: the same day-of-month
// `months` months later (or earlier when negative), clamped to the last day of
// the target month (Jan 31 + 1 month = Feb 28 or 29). The time of day is kept.
// Error when the result leaves the int64 nanosecond range.
Result<int64_t> addMonths(int64_t nsSinceEpoch, int64_t months);
// Same on whole days since the epoch; error when the target year leaves
// -1'000'000 .. 1'000'000 (keeps the arithmetic far from int64 overflow).
Result<int64_t> addMonthsToDays(int64_t daysSinceEpoch, int64_t months);

}  // namespace strun::stdlib
