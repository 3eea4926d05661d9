// The CODESYS storage encodings of the time types (decision 0030) and the
// conversions between them and the nanosecond values that the literal parser,
// the formatter and the calendar functions work with.
//
//   TIME   int32  milliseconds (signed)          LTIME  int64 nanoseconds (signed)
//   DATE   uint32 seconds since 1970-01-01, a multiple of 86400
//   TOD    uint32 milliseconds since midnight    LTOD   int64 nanoseconds since midnight
//   DT     uint32 seconds since 1970-01-01       LDATE / LDT  int64 nanoseconds since 1970-01-01
#pragma once

#include <cstdint>

#include "stdlib/result.h"

namespace strun::stdlib {

int64_t timeValueToNs(int32_t milliseconds);
// Sub-millisecond digits are truncated toward zero (T#1.9ms -> 1 ms);
// error when the milliseconds do not fit int32 (about +-24 days 20 hours).
Result<int32_t> nsToTimeValue(int64_t ns);

int64_t dateValueToNs(uint32_t seconds);
// Floors to the day (the time of day is dropped); error before 1970-01-01 or
// after 2106-02-07 (the last day that starts below 2^32 seconds).
Result<uint32_t> nsToDateValue(int64_t nsSinceEpoch);

int64_t todValueToNs(uint32_t milliseconds);
// Sub-millisecond digits are truncated; error outside 0 <= ns < one day.
Result<uint32_t> nsToTodValue(int64_t nsSinceMidnight);

int64_t dtValueToNs(uint32_t seconds);
// Sub-second digits are truncated; error before 1970-01-01-00:00:00 or at/after 2^32 seconds.
Result<uint32_t> nsToDtValue(int64_t nsSinceEpoch);

}  // namespace strun::stdlib
