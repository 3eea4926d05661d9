// Type conversions of IEC 61131-3 (*_TO_*, TRUNC, BCD, endianness) with the
// CODESYS behaviour where the standard leaves room (decisions 0031, 0032, 0036).
//
// Integer values travel as a 64-bit pattern: a signed type's value is
// sign-extended (cast the result to int64_t), an unsigned one zero-extended.
// `bits` is the width of the target type: 8 (SINT/USINT/BYTE), 16, 32 or 64;
// any width 1..64 works (1 for BOOL as a bit).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "stdlib/result.h"

namespace strun::stdlib {

// Two's-complement wrap of `raw` to `bits` bits: the low bits kept, then
// sign-extended when isSigned, zero-extended otherwise. Pass an int64_t
// freely (it converts modulo 2^64). Example: wrapToWidth(40000, 16, true)
// -> (uint64_t)-25536; wrapToWidth(-1, 8, false) -> 255.
uint64_t wrapToWidth(uint64_t raw, int bits, bool isSigned);

// Round to nearest, ties to even (IEC 60559 / IEC 61131-3 Table 22 note):
// 1.5 -> 2, 2.5 -> 2, -2.5 -> -2, 0.5 -> 0. NaN and infinities pass through.
double roundHalfEven(double value);

// REAL/LREAL_TO_<integer>: roundHalfEven, then wrap to the target width.
// NaN, +-inf and values outside [-2^63, 2^64) give the x86 "integer
// indefinite" 16#8000_0000_0000_0000 wrapped to the width (0 for 8/16/32 bits,
// -2^63 for LINT, 2^63 for ULINT/LWORD). A REAL argument converts to double exactly.
uint64_t realToInteger(double value, int bits, bool isSigned);
// TRUNC / TRUNC_*: toward zero, same out-of-range rule.
uint64_t truncToInteger(double value, int bits, bool isSigned);

// STRING_TO_<integer>/<bit string> (CODESYS): leading blanks skipped, then an
// optional sign, then a decimal number with underscores ('1_000') or a based one
// ('16#FF', '2#1010', '8#17'); anything after the number is ignored ('34abc' -> 34,
// '9.87' -> 9). The number is taken modulo 2^64 and wrapped to the width
// ('500' as BYTE -> 244, '-1' as UINT -> 65535). No number at the start
// ('abc34', '', '  ') -> failure with value 0.
Result<uint64_t> stringToInteger(std::string_view text, int bits, bool isSigned);

// STRING_TO_REAL / STRING_TO_LREAL: leading blanks, then a real number
// ('1.5', '-2.5E3', '1_000.5', '3e5'), or a based integer ('16#FF' -> 255.0);
// trailing text ignored. Too large -> +-inf ('1.7E+400'), too small -> 0.
// No number at the start -> failure with value 0.
Result<float> stringToReal(std::string_view text);
Result<double> stringToLReal(std::string_view text);

// STRING_TO_BOOL: blanks trimmed; 'TRUE' / 'FALSE' in any case; otherwise an
// integer as for stringToInteger, TRUE when non-zero ('1', '0', '5'). Anything
// else -> failure with value FALSE.
Result<bool> stringToBool(std::string_view text);

// STRING_TO_TIME/LTIME, _DATE/LDATE, _TOD/LTOD, _DT/LDT: blanks trimmed, then the
// literal with or without its prefix ('T#1s', '1s', 'DT#2019-9-9-1:1:1.1').
// Results in ns like the literal parsers (stdlib/time_literals.h); invalid -> failure, value 0.
Result<int64_t> stringToDuration(std::string_view text);
Result<int64_t> stringToDate(std::string_view text);
Result<int64_t> stringToTimeOfDay(std::string_view text);
Result<int64_t> stringToDateTime(std::string_view text);

// *_TO_STRING of the non-time types. Integers and bit strings are decimal
// (WORD_TO_STRING(16#FF) = '255'); BOOL is 'TRUE' / 'FALSE'. For REAL/LREAL use
// formatReal / formatLReal, for the time types formatDuration etc. (value_format.h).
std::string signedToString(int64_t value);
std::string unsignedToString(uint64_t value);
std::string boolToString(bool value);

// BCD of `bytes` bytes (1 BYTE, 2 WORD, 4 DWORD, 8 LWORD); only the low
// bytes*8 bits of the input are looked at.
// IS_VALID_BCD: every nibble 0..9.
bool isValidBcd(uint64_t bcd, int bytes);
// *_BCD_TO_*: the decimal value; an invalid nibble gives all ones
// (UINT64_MAX, i.e. -1 as a signed value), as CODESYS Util BCD_TO_INT does.
uint64_t bcdToInteger(uint64_t bcd, int bytes);
// *_TO_BCD_*: the BCD pattern; a value with more than bytes*2 decimal digits
// (or a negative one, passed as a huge uint64) gives all ones of the width
// (16#FF, 16#FFFF, ...), as CODESYS Util INT_TO_BCD does.
uint64_t integerToBcd(uint64_t value, int bytes);

// TO_BIG_ENDIAN / FROM_BIG_ENDIAN / TO_LITTLE_ENDIAN / FROM_LITTLE_ENDIAN for
// 1, 2, 4, 8 byte values, independent of the host byte order. The value is
// its numeric pattern; the result is the pattern whose in-memory bytes are in
// the requested order. Other sizes return the value unchanged.
uint64_t toBigEndian(uint64_t value, int bytes);
uint64_t fromBigEndian(uint64_t value, int bytes);
uint64_t toLittleEndian(uint64_t value, int bytes);
uint64_t fromLittleEndian(uint64_t value, int bytes);

}  // namespace strun::stdlib
