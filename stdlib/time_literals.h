// Parsing of IEC 61131-3 duration, date, time-of-day and date-and-time
// literals into nanoseconds (decision 0030 / 0034). Prefixes are matched
// case-insensitively; each parser also accepts the text without its prefix
// (the bare command-line form `150ms`, or `2026-01-31` for a date).
#pragma once

#include <cstdint>
#include <string_view>

#include "stdlib/result.h"

namespace strun::stdlib {

// `T#1h2m3s4ms`, `TIME#-5s`, `LT#1us`, `LTIME#1.5s`, `t#1d_2h`, `T#-250ms`,
// bare `150ms`, `2s`, `1h30m` -> signed nanoseconds.
// Grammar: [prefix '#'] ['+'|'-'] part { ['_'] part }, part = number unit,
// units d h m s ms us ns (any case), each at most once and in decreasing order.
// Numbers may contain single underscores between digits; only the last part
// may have a fraction (`T#1.5s`, `T#1m1.5s`); fractions below 1 ns are
// truncated. The first part may exceed its unit's range (`T#25h`, `T#90m`);
// later parts must stay in range (h < 24, m < 60, s < 60, ms/us/ns < 1000).
// Errors: no parts, unknown or repeated or out-of-order unit, misplaced
// fraction or underscore, range, or a total beyond +-2^63 ns (about 292 years).
// `unsignedRange`: accept totals up to 2^64-1 ns too (TwinCAT's LTIME is
// unsigned); such a total comes back as INT64_MAX and `*saturated` is set,
// and `*unsignedBits`, when given, receives the total itself (TwinCAT's bits).
Result<int64_t> parseDurationLiteral(std::string_view text, bool unsignedRange = false, bool* saturated = nullptr,
                                     uint64_t* unsignedBits = nullptr);

// `D#2026-01-31`, `DATE#`, `LD#`, `LDATE#` (or bare) -> ns since 1970-01-01
// (negative before 1970). Year 1..9999, month 1..12, day valid for the month
// (leap years included); errors also when outside the int64 ns range
// (1677-09-22 .. 2262-04-11). Month and day may have one or two digits.
Result<int64_t> parseDateLiteral(std::string_view text);

// `TOD#13:05:00.25`, `TIME_OF_DAY#`, `LTOD#`, `LTIME_OF_DAY#` (or bare)
// -> ns since midnight. hour 0..23, minute 0..59, optional second 0..59 with
// an optional fraction (digits beyond nanoseconds are truncated).
Result<int64_t> parseTimeOfDayLiteral(std::string_view text);

// `DT#2026-01-31-13:05:00.5`, `DATE_AND_TIME#`, `LDT#`, `LDATE_AND_TIME#`
// (or bare) -> ns since 1970-01-01-00:00:00; date and time parts as above.
Result<int64_t> parseDateTimeLiteral(std::string_view text);

}  // namespace strun::stdlib
