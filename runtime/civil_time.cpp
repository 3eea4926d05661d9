#include "runtime/civil_time.h"

namespace strun::rt {

bool isLeapYear(int64_t year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int daysInMonth(int64_t year, int month) {
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (month == 2 && isLeapYear(year)) return 29;
    return kDays[month - 1];
}

// Howard Hinnant's days_from_civil / civil_from_days: eras of 400 years make
// the arithmetic exact for every year, negative ones included.
int64_t daysFromCivil(const CivilDate& date) {
    int64_t year = date.year - (date.month <= 2 ? 1 : 0);
    int64_t era = (year >= 0 ? year : year - 399) / 400;
    int64_t yearOfEra = year - era * 400;
    int64_t monthFromMarch = date.month > 2 ? date.month - 3 : date.month + 9;
    int64_t dayOfYear = (153 * monthFromMarch + 2) / 5 + date.day - 1;
    int64_t dayOfEra = yearOfEra * 365 + yearOfEra / 4 - yearOfEra / 100 + dayOfYear;
    return era * 146097 + dayOfEra - 719468;
}

CivilDate civilFromDays(int64_t days) {
    days += 719468;
    int64_t era = (days >= 0 ? days : days - 146096) / 146097;
    int64_t dayOfEra = days - era * 146097;
    int64_t yearOfEra = (dayOfEra - dayOfEra / 1460 + dayOfEra / 36524 - dayOfEra / 146096) / 365;
    int64_t dayOfYear = dayOfEra - (365 * yearOfEra + yearOfEra / 4 - yearOfEra / 100);
    int64_t monthFromMarch = (5 * dayOfYear + 2) / 153;
    CivilDate date;
    date.day = int(dayOfYear - (153 * monthFromMarch + 2) / 5 + 1);
    date.month = int(monthFromMarch < 10 ? monthFromMarch + 3 : monthFromMarch - 9);
    date.year = yearOfEra + era * 400 + (date.month <= 2 ? 1 : 0);
    return date;
}

int64_t dayOf(int64_t calendarNanos) {
    int64_t day = calendarNanos / kNanosPerDay;
    if (calendarNanos % kNanosPerDay < 0) --day;
    return day;
}

// From the remainder: day * kNanosPerDay overflows for the first day of the range (1677-09-21).
int64_t nanosOfDay(int64_t calendarNanos) {
    const int64_t rest = calendarNanos % kNanosPerDay;
    return rest < 0 ? rest + kNanosPerDay : rest;
}

}  // namespace strun::rt
