#include "stdlib/calendar.h"

#include <algorithm>

#include <fmt/format.h>

namespace strun::stdlib {

bool isLeapYear(int64_t year) {
    return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

int daysInMonth(int64_t year, int64_t month) {
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (month < 1 || month > 12) return 0;
    if (month == 2 && isLeapYear(year)) return 29;
    return kDays[month - 1];
}

bool isValidDate(int64_t year, int64_t month, int64_t day) {
    return month >= 1 && month <= 12 && day >= 1 && day <= daysInMonth(year, month);
}

int64_t daysFromCivil(int64_t year, int month, int day) {
    // Shift the year so it starts in March: the leap day becomes the last day.
    const int64_t y = year - (month <= 2 ? 1 : 0);
    const int64_t era = (y >= 0 ? y : y - 399) / 400;
    const int64_t yearOfEra = y - era * 400;
    const int64_t dayOfYear = (153 * (month > 2 ? month - 3 : month + 9) + 2) / 5 + day - 1;
    const int64_t dayOfEra = yearOfEra * 365 + yearOfEra / 4 - yearOfEra / 100 + dayOfYear;
    return era * 146097 + dayOfEra - 719468;
}

CivilDate civilFromDays(int64_t daysSinceEpoch) {
    const int64_t z = daysSinceEpoch + 719468;
    const int64_t era = (z >= 0 ? z : z - 146096) / 146097;
    const int64_t dayOfEra = z - era * 146097;
    const int64_t yearOfEra =
        (dayOfEra - dayOfEra / 1460 + dayOfEra / 36524 - dayOfEra / 146096) / 365;
    const int64_t dayOfYear = dayOfEra - (365 * yearOfEra + yearOfEra / 4 - yearOfEra / 100);
    const int64_t monthIndex = (5 * dayOfYear + 2) / 153;  // 0 = March
    CivilDate date;
    date.day = static_cast<int>(dayOfYear - (153 * monthIndex + 2) / 5 + 1);
    date.month = static_cast<int>(monthIndex < 10 ? monthIndex + 3 : monthIndex - 9);
    date.year = yearOfEra + era * 400 + (date.month <= 2 ? 1 : 0);
    return date;
}

int64_t floorDiv(int64_t value, int64_t divisor) {
    int64_t quotient = value / divisor;
    if ((value % divisor != 0) && ((value < 0) != (divisor < 0))) --quotient;
    return quotient;
}

int64_t floorMod(int64_t value, int64_t divisor) {
    // Not value - floorDiv(...) * divisor: that product can overflow near INT64_MIN.
    const int64_t remainder = value % divisor;
    return (remainder != 0 && ((remainder < 0) != (divisor < 0))) ? remainder + divisor : remainder;
}

int dayOfWeek(int64_t daysSinceEpoch) {
    // 1970-01-01 was a Thursday (4).
    return static_cast<int>(floorMod(floorMod(daysSinceEpoch, 7) + 4, 7));
}

TimeOfDayParts splitTimeOfDay(int64_t nsSinceMidnight) {
    int64_t rest = floorMod(nsSinceMidnight, kNsPerDay);
    TimeOfDayParts parts;
    parts.hour = static_cast<int>(rest / kNsPerHour);
    rest %= kNsPerHour;
    parts.minute = static_cast<int>(rest / kNsPerMinute);
    rest %= kNsPerMinute;
    parts.second = static_cast<int>(rest / kNsPerSecond);
    parts.nanosecond = rest % kNsPerSecond;
    return parts;
}

DateTimeParts splitDateTime(int64_t nsSinceEpoch) {
    const int64_t days = floorDiv(nsSinceEpoch, kNsPerDay);
    const CivilDate date = civilFromDays(days);
    const TimeOfDayParts tod = splitTimeOfDay(floorMod(nsSinceEpoch, kNsPerDay));
    DateTimeParts parts;
    parts.year = date.year;
    parts.month = date.month;
    parts.day = date.day;
    parts.hour = tod.hour;
    parts.minute = tod.minute;
    parts.second = tod.second;
    parts.nanosecond = tod.nanosecond;
    return parts;
}

namespace {

// days * kNsPerDay + extra, or an error when it leaves int64.
Result<int64_t> daysToNs(int64_t days, int64_t extraNs) {
    int64_t ns = 0;
    if (__builtin_mul_overflow(days, kNsPerDay, &ns) || __builtin_add_overflow(ns, extraNs, &ns)) {
        return Result<int64_t>::failure(
            "date is outside the representable range 1677-09-22 .. 2262-04-11");
    }
    return Result<int64_t>::success(ns);
}

}  // namespace

Result<int64_t> concatDate(int64_t year, int64_t month, int64_t day) {
    if (year < kMinYear || year > kMaxYear) {
        return Result<int64_t>::failure(
            fmt::format("year {} is outside {}..{}", year, kMinYear, kMaxYear));
    }
    if (month < 1 || month > 12) {
        return Result<int64_t>::failure(fmt::format("month {} is outside 1..12", month));
    }
    if (!isValidDate(year, month, day)) {
        return Result<int64_t>::failure(fmt::format("day {} is outside 1..{} for {:04}-{:02}", day,
                                                    daysInMonth(year, month), year, month));
    }
    return daysToNs(daysFromCivil(year, static_cast<int>(month), static_cast<int>(day)), 0);
}

Result<int64_t> concatTimeOfDay(int64_t hour, int64_t minute, int64_t second,
                                int64_t millisecond) {
    if (hour < 0 || hour > 23) {
        return Result<int64_t>::failure(fmt::format("hour {} is outside 0..23", hour));
    }
    if (minute < 0 || minute > 59) {
        return Result<int64_t>::failure(fmt::format("minute {} is outside 0..59", minute));
    }
    if (second < 0 || second > 59) {
        return Result<int64_t>::failure(fmt::format("second {} is outside 0..59", second));
    }
    if (millisecond < 0 || millisecond > 999) {
        return Result<int64_t>::failure(
            fmt::format("millisecond {} is outside 0..999", millisecond));
    }
    return Result<int64_t>::success(hour * kNsPerHour + minute * kNsPerMinute +
                                    second * kNsPerSecond + millisecond * kNsPerMs);
}

Result<int64_t> concatDateTime(int64_t year, int64_t month, int64_t day, int64_t hour,
                               int64_t minute, int64_t second, int64_t millisecond) {
    const Result<int64_t> tod = concatTimeOfDay(hour, minute, second, millisecond);
    if (!tod) return tod;
    const Result<int64_t> date = concatDate(year, month, day);
    if (!date) return date;
    return concatDateAndTimeOfDay(date.value(), tod.value());
}

Result<int64_t> concatDateAndTimeOfDay(int64_t dateNs, int64_t todNs) {
    if (floorMod(dateNs, kNsPerDay) != 0) {
        return Result<int64_t>::failure("the date value is not a midnight");
    }
    if (todNs < 0 || todNs >= kNsPerDay) {
        return Result<int64_t>::failure("the time of day is outside 00:00:00 .. 23:59:59.999999999");
    }
    int64_t ns = 0;
    if (__builtin_add_overflow(dateNs, todNs, &ns)) {
        return Result<int64_t>::failure("date and time is outside the representable range");
    }
    return Result<int64_t>::success(ns);
}

Result<int64_t> addMonthsToDays(int64_t daysSinceEpoch, int64_t months) {
    constexpr int64_t kYearLimit = 1'000'000;
    const CivilDate date = civilFromDays(daysSinceEpoch);
    if (months > 12 * kYearLimit * 2 || months < -12 * kYearLimit * 2) {
        return Result<int64_t>::failure("month offset is too large");
    }
    // Month index counted from year 0 so that the division below floors.
    const int64_t monthIndex = date.year * 12 + (date.month - 1) + months;
    const int64_t year = floorDiv(monthIndex, 12);
    const int month = static_cast<int>(floorMod(monthIndex, 12)) + 1;
    if (year > kYearLimit || year < -kYearLimit) {
        return Result<int64_t>::failure("resulting year is out of range");
    }
    const int day = std::min(date.day, daysInMonth(year, month));
    return Result<int64_t>::success(daysFromCivil(year, month, day));
}

Result<int64_t> addMonths(int64_t nsSinceEpoch, int64_t months) {
    const int64_t days = floorDiv(nsSinceEpoch, kNsPerDay);
    const Result<int64_t> targetDays = addMonthsToDays(days, months);
    if (!targetDays) return targetDays;
    return daysToNs(targetDays.value(), floorMod(nsSinceEpoch, kNsPerDay));
}

}  // namespace strun::stdlib
