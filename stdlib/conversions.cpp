#include "stdlib/conversions.h"

#include <bit>
#include <cmath>
#include <limits>

#include "stdlib/number_scan.h"
#include "stdlib/time_literals.h"

namespace strun::stdlib {

namespace {

uint64_t lowMask(int bits) {
    if (bits >= 64) return ~uint64_t{0};
    if (bits <= 0) return 0;
    return (uint64_t{1} << bits) - 1;
}

int clampBytes(int bytes) { return bytes < 1 ? 1 : (bytes > 8 ? 8 : bytes); }

// What x86 cvttsd2si yields for NaN, infinities and out-of-range values.
constexpr uint64_t kIntegerIndefinite = uint64_t{1} << 63;

// An integral double to its 64-bit pattern, or the indefinite value.
uint64_t integralToPattern(double integral) {
    constexpr double kTwoPow63 = 9223372036854775808.0;
    constexpr double kTwoPow64 = 18446744073709551616.0;
    if (!std::isfinite(integral) || integral >= kTwoPow64 || integral < -kTwoPow63) {
        return kIntegerIndefinite;
    }
    if (integral >= kTwoPow63) return static_cast<uint64_t>(integral);
    return static_cast<uint64_t>(static_cast<int64_t>(integral));
}

}  // namespace

uint64_t wrapToWidth(uint64_t raw, int bits, bool isSigned) {
    if (bits >= 64) return raw;
    if (bits <= 0) return 0;
    const uint64_t mask = lowMask(bits);
    uint64_t value = raw & mask;
    if (isSigned && ((value >> (bits - 1)) & 1) != 0) value |= ~mask;
    return value;
}

double roundHalfEven(double value) {
    if (!std::isfinite(value)) return value;
    const double below = std::floor(value);
    const double difference = value - below;  // exact: below and value share the exponent range
    if (difference < 0.5) return below;
    if (difference > 0.5) return below + 1.0;
    return std::fmod(below, 2.0) == 0.0 ? below : below + 1.0;
}

uint64_t realToInteger(double value, int bits, bool isSigned) {
    return wrapToWidth(integralToPattern(roundHalfEven(value)), bits, isSigned);
}

uint64_t truncToInteger(double value, int bits, bool isSigned) {
    return wrapToWidth(integralToPattern(std::trunc(value)), bits, isSigned);
}

namespace {

size_t skipLeadingBlanks(std::string_view text) {
    size_t pos = 0;
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t')) ++pos;
    return pos;
}

// A based integer `2#..`, `8#..`, `16#..` at pos (sign already consumed).
// Returns false when the text there is not one.
bool scanBasedInteger(std::string_view text, size_t pos, uint64_t& wrapped) {
    const DigitScan base = scanDigits(text, pos, 10);
    if (base.digits == 0 || base.end >= text.size() || text[base.end] != '#' || base.overflow) {
        return false;
    }
    if (base.value != 2 && base.value != 8 && base.value != 16) return false;
    const DigitScan digits = scanDigits(text, base.end + 1, static_cast<unsigned>(base.value));
    if (digits.digits == 0) return false;
    wrapped = digits.wrapped;
    return true;
}

}  // namespace

Result<uint64_t> stringToInteger(std::string_view text, int bits, bool isSigned) {
    size_t pos = skipLeadingBlanks(text);
    bool negative = false;
    if (pos < text.size() && (text[pos] == '+' || text[pos] == '-')) {
        negative = text[pos] == '-';
        ++pos;
    }
    uint64_t magnitude = 0;
    if (!scanBasedInteger(text, pos, magnitude)) {
        const DigitScan decimal = scanDigits(text, pos, 10);
        if (decimal.digits == 0) {
            return Result<uint64_t>::failure("the string does not start with an integer");
        }
        // A base other than 2, 8, 16 or a based literal without digits is not a number.
        if (decimal.end < text.size() && text[decimal.end] == '#') {
            return Result<uint64_t>::failure("the string holds an invalid based integer");
        }
        magnitude = decimal.wrapped;
    }
    const uint64_t raw = negative ? 0 - magnitude : magnitude;
    return Result<uint64_t>::success(wrapToWidth(raw, bits, isSigned));
}

namespace {

template <typename T>
Result<T> stringToFloating(std::string_view text) {
    const size_t start = skipLeadingBlanks(text);
    size_t pos = start;
    bool negative = false;
    if (pos < text.size() && (text[pos] == '+' || text[pos] == '-')) {
        negative = text[pos] == '-';
        ++pos;
    }
    uint64_t based = 0;
    if (scanBasedInteger(text, pos, based)) {
        const T magnitude = static_cast<T>(based);
        return Result<T>::success(negative ? -magnitude : magnitude);
    }
    const RealScan scan = scanReal(text, start);
    if (!scan.matched) return Result<T>::failure("the string does not start with a number");
    if constexpr (sizeof(T) == sizeof(float)) {
        return Result<T>::success(realScanToFloat(scan));
    } else {
        return Result<T>::success(realScanToDouble(scan));
    }
}

}  // namespace

Result<float> stringToReal(std::string_view text) { return stringToFloating<float>(text); }
Result<double> stringToLReal(std::string_view text) { return stringToFloating<double>(text); }

Result<bool> stringToBool(std::string_view text) {
    const std::string_view trimmed = trimBlanks(text);
    if (equalsIgnoreCase(trimmed, "TRUE")) return Result<bool>::success(true);
    if (equalsIgnoreCase(trimmed, "FALSE")) return Result<bool>::success(false);
    const Result<uint64_t> number = stringToInteger(trimmed, 64, false);
    if (!number) return Result<bool>::failure("the string is neither TRUE, FALSE nor a number");
    return Result<bool>::success(number.value() != 0);
}

Result<int64_t> stringToDuration(std::string_view text) {
    return parseDurationLiteral(trimBlanks(text));  // a failure carries 0
}
Result<int64_t> stringToDate(std::string_view text) {
    return parseDateLiteral(trimBlanks(text));  // a failure carries 0
}
Result<int64_t> stringToTimeOfDay(std::string_view text) {
    return parseTimeOfDayLiteral(trimBlanks(text));  // a failure carries 0
}
Result<int64_t> stringToDateTime(std::string_view text) {
    return parseDateTimeLiteral(trimBlanks(text));  // a failure carries 0
}

std::string signedToString(int64_t value) { return std::to_string(value); }
std::string unsignedToString(uint64_t value) { return std::to_string(value); }
std::string boolToString(bool value) { return value ? "TRUE" : "FALSE"; }

bool isValidBcd(uint64_t bcd, int bytes) {
    const int nibbles = clampBytes(bytes) * 2;
    for (int i = 0; i < nibbles; ++i) {
        if (((bcd >> (4 * i)) & 0xF) > 9) return false;
    }
    return true;
}

uint64_t bcdToInteger(uint64_t bcd, int bytes) {
    if (!isValidBcd(bcd, bytes)) return std::numeric_limits<uint64_t>::max();
    const int nibbles = clampBytes(bytes) * 2;
    uint64_t value = 0;
    for (int i = nibbles - 1; i >= 0; --i) value = value * 10 + ((bcd >> (4 * i)) & 0xF);
    return value;
}

uint64_t integerToBcd(uint64_t value, int bytes) {
    const int width = clampBytes(bytes);
    uint64_t largest = 1;
    for (int i = 0; i < width * 2; ++i) largest *= 10;  // 10^16 fits in uint64
    if (value >= largest) return lowMask(width * 8);
    uint64_t bcd = 0;
    for (int i = 0; value != 0; ++i, value /= 10) bcd |= (value % 10) << (4 * i);
    return bcd;
}

namespace {

uint64_t swapBytes(uint64_t value, int bytes) {
    uint64_t swapped = 0;
    for (int i = 0; i < bytes; ++i) swapped = (swapped << 8) | ((value >> (8 * i)) & 0xFF);
    return swapped;
}

bool supportedSize(int bytes) { return bytes == 1 || bytes == 2 || bytes == 4 || bytes == 8; }

uint64_t reorder(uint64_t value, int bytes, std::endian wanted) {
    if (!supportedSize(bytes)) return value;
    const uint64_t masked = value & lowMask(bytes * 8);
    return std::endian::native == wanted ? masked : swapBytes(masked, bytes);
}

}  // namespace

uint64_t toBigEndian(uint64_t value, int bytes) { return reorder(value, bytes, std::endian::big); }
// Swapping is its own inverse.
uint64_t fromBigEndian(uint64_t value, int bytes) { return reorder(value, bytes, std::endian::big); }
uint64_t toLittleEndian(uint64_t value, int bytes) { return reorder(value, bytes, std::endian::little); }
uint64_t fromLittleEndian(uint64_t value, int bytes) {
    return reorder(value, bytes, std::endian::little);
}

}  // namespace strun::stdlib
