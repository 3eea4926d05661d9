// When a time-event task (AT := DT#..., REPEAT := ...) is due. The rules are
// in docs/decisions/0014-time-event-calendar.md: HOURLY/DAILY/WEEKLY repeat
// at a fixed distance from AT; MONTHLY keeps AT's day of month (a day beyond
// the month's end falls on its last day — the checker rejects day > 28 as the
// seed does, so this only guards bad input); MONTH_END is the last day of
// every month at AT's time of day, starting with AT's month; YEARLY keeps
// month and day, 29 February falling on 28 February in common years.
#pragma once

#include <cstdint>

#include "runtime/task_spec.h"

namespace strun::rt {

// The first occurrence at or after `notBefore` (calendar ns), or kNever when
// there is none (a ONCE event already past, or beyond the representable range).
int64_t nextTimeEventOccurrence(int64_t atCalendarNanos, TimeRepeat repeat, int64_t notBefore);

// The occurrence number `index` (0 = the first) of a repeating event.
int64_t timeEventOccurrence(int64_t atCalendarNanos, TimeRepeat repeat, int64_t index);

}  // namespace strun::rt
