// IEC literal forms of values, as written by --dump and by the *_TO_STRING
// conversions (decisions 0034 and 0035).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace strun::stdlib {

// Signed nanoseconds -> "T#1s500ms", "T#0s" (zero is exactly that), "T#-250ms",
// "T#1d2h3m4s5ms", "T#1ms500us", "T#5ns". Units d h m s ms us ns; zero units
// are omitted; the sign goes right after the prefix. INT64_MIN is handled.
std::string formatDuration(int64_t ns, std::string_view prefix = "T#");
// The same text for a count TwinCAT keeps unsigned (its LTIME, decision 0367):
// 2^64-1 ns is "LTIME#213503d23h34m33s709ms551us615ns", never negative.
std::string formatUnsignedDuration(uint64_t ns, std::string_view prefix = "LTIME#");

// ns since 1970-01-01 -> "D#2026-01-31" (the time of day is ignored; floors,
// so instants before 1970 land on the right day).
std::string formatDate(int64_t nsSinceEpoch, std::string_view prefix = "D#");

// ns since midnight -> "TOD#13:05:00", or "TOD#13:05:00.25" when the
// fraction of a second is not zero (up to 9 digits, trailing zeros trimmed).
// Values outside one day are taken modulo a day.
std::string formatTimeOfDay(int64_t nsSinceMidnight, std::string_view prefix = "TOD#");

// ns since 1970-01-01 -> "DT#2026-01-31-13:05:00" (fraction rule as for TOD).
std::string formatDateTime(int64_t nsSinceEpoch, std::string_view prefix = "DT#");

// REAL_TO_STRING / LREAL_TO_STRING: the shortest digits that read back as the
// same REAL (resp. LREAL); plain notation when 1e-5 <= |x| < 1e15 ("1.5",
// "0.1", "100", "-0.001"), else "1E+38", "1.5E-07"; zero is "0"; whole
// numbers carry no ".0" (in a TwinCAT project they do, below); non-finite values are "INF", "-INF", "NAN".
std::string formatReal(float value);
std::string formatLReal(double value);
// TwinCAT's text: the same, but a whole number in plain notation keeps ".0"
// ("24.0", "-23.0", "0.0"), as TwinCAT's REAL_TO_STRING writes it and TcUnit's
// messages show it (decision 0336).
std::string formatRealTwinCat(float value);
std::string formatLRealTwinCat(double value);

// Shortest round-trip text that is also a valid JSON number ("0.1", "1e+38",
// "100"). Non-finite input gives "inf", "-inf", "nan" (the --dump strings);
// callers must quote those.
std::string formatRealJson(float value);
std::string formatLRealJson(double value);

}  // namespace strun::stdlib
