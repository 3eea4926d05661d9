#include "stdlib/value_encodings.h"

#include <limits>

#include "stdlib/calendar.h"

namespace strun::stdlib {

int64_t timeValueToNs(int32_t milliseconds) {
    return static_cast<int64_t>(milliseconds) * kNsPerMs;
}

Result<int32_t> nsToTimeValue(int64_t ns) {
    const int64_t ms = ns / kNsPerMs;  // C++ division truncates toward zero
    if (ms < std::numeric_limits<int32_t>::min() || ms > std::numeric_limits<int32_t>::max()) {
        return Result<int32_t>::failure("duration does not fit TIME (int32 milliseconds); use LTIME");
    }
    return Result<int32_t>::success(static_cast<int32_t>(ms));
}

int64_t dateValueToNs(uint32_t seconds) {
    return static_cast<int64_t>(seconds) * kNsPerSecond;
}

Result<uint32_t> nsToDateValue(int64_t nsSinceEpoch) {
    const int64_t days = floorDiv(nsSinceEpoch, kNsPerDay);
    const int64_t seconds = days * kSecondsPerDay;
    if (seconds < 0 || seconds > std::numeric_limits<uint32_t>::max()) {
        return Result<uint32_t>::failure(
            "date is outside the DATE range 1970-01-01 .. 2106-02-07; use LDATE");
    }
    return Result<uint32_t>::success(static_cast<uint32_t>(seconds));
}

int64_t todValueToNs(uint32_t milliseconds) {
    return static_cast<int64_t>(milliseconds) * kNsPerMs;
}

Result<uint32_t> nsToTodValue(int64_t nsSinceMidnight) {
    if (nsSinceMidnight < 0 || nsSinceMidnight >= kNsPerDay) {
        return Result<uint32_t>::failure("time of day is outside 00:00:00 .. 23:59:59.999");
    }
    return Result<uint32_t>::success(static_cast<uint32_t>(nsSinceMidnight / kNsPerMs));
}

int64_t dtValueToNs(uint32_t seconds) {
    return static_cast<int64_t>(seconds) * kNsPerSecond;
}

Result<uint32_t> nsToDtValue(int64_t nsSinceEpoch) {
    const int64_t seconds = floorDiv(nsSinceEpoch, kNsPerSecond);
    if (seconds < 0 || seconds > std::numeric_limits<uint32_t>::max()) {
        return Result<uint32_t>::failure(
            "date and time is outside the DT range 1970-01-01-00:00:00 .. 2106-02-07-06:28:15; use LDT");
    }
    return Result<uint32_t>::success(static_cast<uint32_t>(seconds));
}

}  // namespace strun::stdlib
