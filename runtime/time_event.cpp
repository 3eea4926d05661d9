#include "runtime/time_event.h"

#include <algorithm>

#include "runtime/civil_time.h"

namespace strun::rt {

namespace {

// About 290 years of nanoseconds fit in int64; occurrences further away never come.
constexpr int64_t kMaxDays = 106'000;

int64_t atDay(int64_t days, int64_t timeOfDay) {
    if (days > kMaxDays || days < -kMaxDays) return kNever;
    return days * kNanosPerDay + timeOfDay;
}

int64_t fixedPeriod(TimeRepeat repeat) {
    switch (repeat) {
    case TimeRepeat::Hourly: return 3'600 * kNanosPerSecond;
    case TimeRepeat::Daily: return kNanosPerDay;
    case TimeRepeat::Weekly: return 7 * kNanosPerDay;
    default: return 0;
    }
}

// Month number `index` after AT's month, on `day` clamped to that month's length
// (`day` 0 means the month's last day).
int64_t inMonth(const CivilDate& first, int64_t index, int day, int64_t timeOfDay) {
    int64_t monthsSinceYear0 = first.year * 12 + (first.month - 1) + index;
    CivilDate date;
    date.year = monthsSinceYear0 / 12;
    date.month = int(monthsSinceYear0 % 12) + 1;
    if (date.year > 1970 + 300 || date.year < 1970 - 300) return kNever;
    int last = daysInMonth(date.year, date.month);
    date.day = day == 0 ? last : std::min(day, last);
    return atDay(daysFromCivil(date), timeOfDay);
}

}  // namespace

int64_t timeEventOccurrence(int64_t at, TimeRepeat repeat, int64_t index) {
    if (index < 0) return kNever;
    if (repeat == TimeRepeat::Once) return index == 0 ? at : kNever;
    if (int64_t period = fixedPeriod(repeat)) {
        // 128-bit: an AT long before 1970 (LDT#1700-...) is a negative `at`, and kNever - at would overflow.
        const __int128 occurrence = static_cast<__int128>(at) + static_cast<__int128>(index) * period;
        return occurrence >= kNever ? kNever : static_cast<int64_t>(occurrence);
    }
    CivilDate first = civilFromDays(dayOf(at));
    int64_t timeOfDay = nanosOfDay(at);
    switch (repeat) {
    case TimeRepeat::Monthly: return inMonth(first, index, first.day, timeOfDay);
    case TimeRepeat::MonthEnd: return inMonth(first, index, 0, timeOfDay);
    case TimeRepeat::Yearly: return inMonth(first, index * 12, first.day, timeOfDay);
    default: return kNever;
    }
}

int64_t nextTimeEventOccurrence(int64_t at, TimeRepeat repeat, int64_t notBefore) {
    if (at >= notBefore) return at;
    if (repeat == TimeRepeat::Once) return kNever;
    if (int64_t period = fixedPeriod(repeat)) {
        const uint64_t distance = static_cast<uint64_t>(notBefore) - static_cast<uint64_t>(at);  // > 0, exact even past INT64_MAX
        const int64_t index = static_cast<int64_t>(distance / uint64_t(period) + (distance % uint64_t(period) != 0 ? 1 : 0));
        return timeEventOccurrence(at, repeat, index);
    }
    // Calendar repeats: start one step before the estimated month and walk forward.
    CivilDate first = civilFromDays(dayOf(at));
    CivilDate target = civilFromDays(dayOf(notBefore));
    int64_t months = (target.year - first.year) * 12 + (target.month - first.month);
    int64_t index = repeat == TimeRepeat::Yearly ? months / 12 - 1 : months - 1;
    index = std::max<int64_t>(index, 0);
    for (;;) {
        int64_t occurrence = timeEventOccurrence(at, repeat, index);
        if (occurrence == kNever || occurrence >= notBefore) return occurrence;
        ++index;
    }
}

}  // namespace strun::rt
