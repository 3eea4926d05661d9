#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "stdlib/calendar.h"
#include "stdlib/conversions.h"

using namespace strun::stdlib;

namespace {
int64_t asSigned(uint64_t pattern) { return static_cast<int64_t>(pattern); }
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST_CASE("wrapToWidth: two's complement", "[conversions]") {
    CHECK(asSigned(wrapToWidth(40000, 16, true)) == -25536);
    CHECK(wrapToWidth(static_cast<uint64_t>(int64_t{-1}), 8, false) == 255);
    CHECK(asSigned(wrapToWidth(static_cast<uint64_t>(int64_t{-1}), 8, true)) == -1);
    CHECK(asSigned(wrapToWidth(128, 8, true)) == -128);
    CHECK(wrapToWidth(256, 8, false) == 0);
    CHECK(asSigned(wrapToWidth(32767, 16, true)) == 32767);
    CHECK(asSigned(wrapToWidth(32768, 16, true)) == -32768);
    CHECK(wrapToWidth(65536 + 5, 16, false) == 5);
    CHECK(asSigned(wrapToWidth(0x80000000u, 32, true)) == INT32_MIN);
    CHECK(wrapToWidth(UINT64_MAX, 64, false) == UINT64_MAX);
    CHECK(asSigned(wrapToWidth(UINT64_MAX, 64, true)) == -1);
    CHECK(wrapToWidth(3, 1, false) == 1);
}

TEST_CASE("roundHalfEven follows IEC 61131-3 Table 22", "[conversions]") {
    CHECK(roundHalfEven(1.6) == 2.0);
    CHECK(roundHalfEven(-1.6) == -2.0);
    CHECK(roundHalfEven(1.5) == 2.0);
    CHECK(roundHalfEven(-1.5) == -2.0);
    CHECK(roundHalfEven(1.4) == 1.0);
    CHECK(roundHalfEven(-1.4) == -1.0);
    CHECK(roundHalfEven(2.5) == 2.0);
    CHECK(roundHalfEven(-2.5) == -2.0);
    CHECK(roundHalfEven(0.5) == 0.0);
    CHECK(roundHalfEven(3.5) == 4.0);
    CHECK(roundHalfEven(0.49999999999999994) == 0.0);
    CHECK(roundHalfEven(4503599627370497.0) == 4503599627370497.0);  // 2^52 + 1 is integral
    CHECK(std::isnan(roundHalfEven(std::nan(""))));
}

TEST_CASE("REAL/LREAL to integer", "[conversions]") {
    CHECK(asSigned(realToInteger(2.5, 16, true)) == 2);
    CHECK(asSigned(realToInteger(-2.5, 16, true)) == -2);
    CHECK(asSigned(realToInteger(1.5, 32, true)) == 2);
    CHECK(asSigned(realToInteger(-1.5f, 16, true)) == -2);
    CHECK(asSigned(realToInteger(1.234, 32, true)) == 1);
    CHECK(realToInteger(0.987654321, 8, false) == 1);
    // Out of the target range: wraps like the 64-bit value would.
    CHECK(asSigned(realToInteger(40000.0, 16, true)) == -25536);
    CHECK(realToInteger(300.0, 8, false) == 44);
    CHECK(realToInteger(-1.0, 16, false) == 65535);
    CHECK(asSigned(realToInteger(-9223372036854775808.0, 64, true)) == INT64_MIN);
    CHECK(realToInteger(18446744073709549568.0, 64, false) == 18446744073709549568u);
    // NaN, infinities and values beyond 64 bits: the integer-indefinite pattern.
    CHECK(realToInteger(std::nan(""), 16, true) == 0);
    CHECK(realToInteger(kInf, 32, true) == 0);
    CHECK(realToInteger(-kInf, 32, false) == 0);
    CHECK(asSigned(realToInteger(1e30, 64, true)) == INT64_MIN);
    CHECK(realToInteger(std::nan(""), 64, false) == (uint64_t{1} << 63));
    CHECK(realToInteger(18446744073709551616.0, 64, false) == (uint64_t{1} << 63));
}

TEST_CASE("TRUNC toward zero", "[conversions]") {
    CHECK(asSigned(truncToInteger(1.6, 32, true)) == 1);
    CHECK(asSigned(truncToInteger(-1.6, 32, true)) == -1);
    CHECK(asSigned(truncToInteger(1.9, 16, true)) == 1);
    CHECK(asSigned(truncToInteger(-1.4, 16, true)) == -1);
    CHECK(asSigned(truncToInteger(2.5, 64, true)) == 2);
    CHECK(asSigned(truncToInteger(-0.9, 64, true)) == 0);
    CHECK(truncToInteger(kInf, 16, true) == 0);
    CHECK(asSigned(truncToInteger(70000.7, 16, true)) == 4464);
}

TEST_CASE("STRING to integer (CODESYS rules)", "[conversions]") {
    CHECK(asSigned(stringToInteger("123", 16, true).value()) == 123);
    CHECK(asSigned(stringToInteger("  -45", 16, true).value()) == -45);
    CHECK(asSigned(stringToInteger("+7", 8, true).value()) == 7);
    CHECK(stringToInteger("16#FF", 16, false).value() == 255);
    CHECK(stringToInteger("16#FFFFFFFF", 32, false).value() == 0xFFFFFFFFu);
    CHECK(asSigned(stringToInteger("16#FFFF", 16, true).value()) == -1);
    CHECK(stringToInteger("2#1111_1111", 8, false).value() == 255);
    CHECK(stringToInteger("8#17", 16, false).value() == 15);
    CHECK(stringToInteger("1_000", 16, false).value() == 1000);
    CHECK(stringToInteger("34abc", 16, false).value() == 34);
    CHECK(stringToInteger("2m", 16, false).value() == 2);
    CHECK(stringToInteger("9.876", 16, false).value() == 9);
    CHECK(stringToInteger("12 34", 16, false).value() == 12);
    CHECK(stringToInteger("500", 8, false).value() == 244);
    CHECK(stringToInteger("-1", 16, false).value() == 65535);
    CHECK(asSigned(stringToInteger("99999", 16, true).value()) == -31073);
    CHECK(stringToInteger("18446744073709551616", 64, false).value() == 0);  // modulo 2^64
    CHECK(stringToInteger(std::string(5000, '9'), 64, false).ok());
    for (const char* bad : {"abc34", "", "   ", "-", "+", "#5", "_1", "16#", "16#G", "10#5", "x16#FF"}) {
        INFO(bad);
        const Result<uint64_t> parsed = stringToInteger(bad, 16, true);
        CHECK_FALSE(parsed.ok());
        CHECK(parsed.value() == 0);
    }
}

TEST_CASE("STRING to REAL / LREAL", "[conversions]") {
    CHECK(stringToLReal("1.234").value() == 1.234);
    CHECK(stringToLReal("  -2.5E3xyz").value() == -2500.0);
    CHECK(stringToLReal("1.2E-34").value() == 1.2e-34);
    CHECK(stringToLReal("3,14").value() == 3.0);  // the comma ends the number
    CHECK(stringToLReal("1_000.5").value() == 1000.5);
    CHECK(stringToLReal("42").value() == 42.0);
    CHECK(stringToLReal("16#FF").value() == 255.0);
    CHECK(stringToLReal("-16#10").value() == -16.0);
    CHECK(stringToLReal("1.7E+400").value() == std::numeric_limits<double>::infinity());
    CHECK(stringToLReal("-1.7E+400").value() == -std::numeric_limits<double>::infinity());
    CHECK(stringToLReal("1E-400").value() == 0.0);
    CHECK(stringToReal("0.1").value() == 0.1f);
    CHECK(stringToReal("1E39").value() == std::numeric_limits<float>::infinity());
    CHECK(stringToReal("3.4028235E38").value() == std::numeric_limits<float>::max());
    for (const char* bad : {"", "abc", ".5", "-", "E5", "  x1"}) {
        INFO(bad);
        CHECK_FALSE(stringToLReal(bad).ok());
        CHECK(stringToLReal(bad).value() == 0.0);
        CHECK_FALSE(stringToReal(bad).ok());
    }
}

TEST_CASE("STRING to BOOL", "[conversions]") {
    CHECK(stringToBool("TRUE").value());
    CHECK(stringToBool("true").value());
    CHECK(stringToBool(" True ").value());
    CHECK_FALSE(stringToBool("FALSE").value());
    CHECK(stringToBool("false").ok());
    CHECK(stringToBool("1").value());
    CHECK_FALSE(stringToBool("0").value());
    CHECK(stringToBool("0").ok());
    CHECK(stringToBool("5").value());
    CHECK_FALSE(stringToBool("yes").ok());
    CHECK_FALSE(stringToBool("yes").value());
    CHECK_FALSE(stringToBool("").ok());
    CHECK_FALSE(stringToBool("TRUEX").ok());
}

TEST_CASE("STRING to time types", "[conversions]") {
    CHECK(stringToDuration("T#127ms").value() == 127 * kNsPerMs);
    CHECK(stringToDuration(" 2s ").value() == 2 * kNsPerSecond);
    CHECK(stringToDuration("LTIME#5us").value() == 5000);
    CHECK_FALSE(stringToDuration("T#").ok());
    CHECK(stringToDuration("garbage").value() == 0);
    CHECK(stringToDate("DATE#2019-9-9").value() == concatDate(2019, 9, 9).value());
    CHECK(stringToDate("2019-09-09").value() == concatDate(2019, 9, 9).value());
    CHECK_FALSE(stringToDate("D#2019-02-30").ok());
    CHECK(stringToTimeOfDay("TOD#14:01:05.123").value() == concatTimeOfDay(14, 1, 5, 123).value());
    CHECK(stringToDateTime("DT#2019-9-9-1:1:1.1").value() == concatDateTime(2019, 9, 9, 1, 1, 1, 100).value());
    CHECK_FALSE(stringToDateTime("DT#2019-9-9").ok());
}

TEST_CASE("numbers to STRING", "[conversions]") {
    CHECK(signedToString(-32768) == "-32768");
    CHECK(signedToString(INT64_MIN) == "-9223372036854775808");
    CHECK(unsignedToString(255) == "255");  // WORD_TO_STRING(16#FF)
    CHECK(unsignedToString(UINT64_MAX) == "18446744073709551615");
    CHECK(boolToString(true) == "TRUE");
    CHECK(boolToString(false) == "FALSE");
}

TEST_CASE("BCD", "[conversions]") {
    CHECK(isValidBcd(0x1234, 2));
    CHECK_FALSE(isValidBcd(0x12A4, 2));
    CHECK(isValidBcd(0x99, 1));
    CHECK_FALSE(isValidBcd(0x0F, 1));
    CHECK(isValidBcd(0xFF00, 1));  // only the low byte is looked at
    CHECK(isValidBcd(0x9999999999999999u, 8));

    CHECK(bcdToInteger(0x25, 1) == 25);
    CHECK(bcdToInteger(0x369, 2) == 369);  // WORD_BCD_TO_UINT(2#0011_0110_1001)
    CHECK(bcdToInteger(73, 1) == 49);      // CODESYS BCD_TO_INT(73)
    CHECK(bcdToInteger(151, 1) == 97);
    CHECK(bcdToInteger(0x12345678, 4) == 12345678);
    CHECK(bcdToInteger(0x9999999999999999u, 8) == 9999999999999999u);
    CHECK(bcdToInteger(15, 1) == UINT64_MAX);  // invalid -> all ones (-1)
    CHECK(asSigned(bcdToInteger(0x1A, 1)) == -1);

    CHECK(integerToBcd(25, 1) == 0x25);  // USINT_TO_BCD_BYTE(25) = 2#0010_0101
    CHECK(integerToBcd(49, 1) == 73);
    CHECK(integerToBcd(0, 2) == 0);
    CHECK(integerToBcd(9999, 2) == 0x9999);
    CHECK(integerToBcd(12345678, 4) == 0x12345678);
    CHECK(integerToBcd(9999999999999999u, 8) == 0x9999999999999999u);
    CHECK(integerToBcd(100, 1) == 0xFF);  // too many digits -> all ones of the width
    CHECK(integerToBcd(10000, 2) == 0xFFFF);
    CHECK(integerToBcd(static_cast<uint64_t>(int64_t{-1}), 1) == 0xFF);
    CHECK(integerToBcd(10000000000000000u, 8) == UINT64_MAX);
}

TEST_CASE("endianness", "[conversions]") {
    CHECK(toBigEndian(0x12, 1) == 0x12);
    CHECK(toBigEndian(0x1234, 2) == 0x3412);
    CHECK(toBigEndian(0x12345678, 4) == 0x78563412);
    CHECK(toBigEndian(0x0102030405060708u, 8) == 0x0807060504030201u);
    CHECK(fromBigEndian(toBigEndian(0xCAFE, 2), 2) == 0xCAFE);
    CHECK(toLittleEndian(0x1234, 2) == 0x1234);
    CHECK(fromLittleEndian(0x12345678, 4) == 0x12345678);
    CHECK(toBigEndian(0xFFFF1234, 2) == 0x3412);  // only the value's own bytes
    CHECK(toBigEndian(0x123456, 3) == 0x123456);  // unsupported size: unchanged
}
