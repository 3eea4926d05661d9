// Low-level scanners for the digit groups of IEC numeric text, shared by the
// literal parsers (which demand that the whole text matches) and the
// STRING_TO_* conversions (which take the longest valid prefix).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "stdlib/ascii_case.h"  // equalsIgnoreCase, upperAscii, lowerAscii

namespace strun::stdlib {

// A literal shown in an error message, cut short so a huge one cannot flood it.
std::string quoted(std::string_view text);

// 0..35 for 0-9, a-z, A-Z; -1 otherwise.
int digitValue(char c);

struct DigitScan {
    size_t end = 0;         // index after the last consumed character
    size_t digits = 0;      // digits consumed (0: nothing matched)
    uint64_t value = 0;     // exact value; meaningful only when !overflow
    uint64_t wrapped = 0;   // value modulo 2^64 (for wrapping conversions)
    bool overflow = false;  // the value exceeded 2^64-1
};

// Consumes `digit { ['_'] digit }` in `base` starting at `pos`. An underscore
// is consumed only when a digit follows it, so a trailing or doubled
// underscore is left at `end` for the caller to reject.
DigitScan scanDigits(std::string_view text, size_t pos, unsigned base);

struct RealScan {
    size_t end = 0;           // index after the last consumed character
    bool matched = false;     // at least one mantissa digit
    bool hasFraction = false;
    bool hasExponent = false;
    std::string normalized;   // sign, digits, '.', 'e', exponent: underscores removed
    int64_t decimalExponent = 0;  // rough power of ten of the value (for range decisions)
    bool isZero = true;           // all mantissa digits are 0
};

// Consumes `[+|-] digits ['.' digits] [(e|E) [+|-] digits]`, digits with
// single underscores. '.' and the exponent are consumed only when digits
// follow them.
RealScan scanReal(std::string_view text, size_t pos);

// Converts a scan to double / float with correct rounding. A magnitude too
// large becomes +-infinity (and sets `overflowed`), one too small becomes +-0.
double realScanToDouble(const RealScan& scan, bool* overflowed = nullptr);
float realScanToFloat(const RealScan& scan, bool* overflowed = nullptr);

// Removes leading and trailing spaces and tabs (and CR/LF).
std::string_view trimBlanks(std::string_view text);

}  // namespace strun::stdlib
