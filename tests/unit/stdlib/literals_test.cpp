#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "stdlib/literals.h"

using namespace strun::stdlib;

TEST_CASE("integer literals: decimal and based forms", "[literals]") {
    CHECK(parseIntegerLiteral("0").value() == 0);
    CHECK(parseIntegerLiteral("123").value() == 123);
    CHECK(parseIntegerLiteral("1_000").value() == 1000);
    CHECK(parseIntegerLiteral("16#FF").value() == 255);
    CHECK(parseIntegerLiteral("16#ff_ff").value() == 0xFFFF);
    CHECK(parseIntegerLiteral("2#1010_1010").value() == 0xAA);
    CHECK(parseIntegerLiteral("8#17").value() == 15);
    CHECK(parseIntegerLiteral("18446744073709551615").value() == UINT64_MAX);
    CHECK(parseIntegerLiteral("16#FFFF_FFFF_FFFF_FFFF").value() == UINT64_MAX);
    CHECK(parseIntegerLiteral("2#" + std::string(64, '1')).value() == UINT64_MAX);
    CHECK(parseIntegerLiteral("007").value() == 7);
    CHECK(parseIntegerLiteral("10#0").value() == 0);  // CODESYS/TwinCAT decimal base written out
    CHECK(parseIntegerLiteral("10#1_234").value() == 1234);
    // Several underscores between digits, as TwinCAT accepts (decision 0326).
    CHECK(parseIntegerLiteral("1__0").value() == 10);
    CHECK(parseIntegerLiteral("16#7f_ff__ff").value() == 0x7fffff);
}

TEST_CASE("integer literals: errors", "[literals]") {
    for (const char* bad : {"", "_1", "1_", "1__", "16#", "16#_F", "16#F_", "16#F__", "16#G", "8#8", "2#102",
                            "11#5", "#5", "1a", "12 ", "-1", "+1", "1.0"}) {
        INFO(bad);
        const Result<uint64_t> parsed = parseIntegerLiteral(bad);
        CHECK_FALSE(parsed.ok());
        CHECK_FALSE(parsed.error().empty());
    }
    CHECK_FALSE(parseIntegerLiteral("18446744073709551616").ok());  // 2^64
    CHECK_FALSE(parseIntegerLiteral("16#1_0000_0000_0000_0000").ok());
    CHECK(parseIntegerLiteral("18446744073709551616").error().find("too large") != std::string::npos);
    CHECK(parseIntegerLiteral("1_").error().find("underscore") != std::string::npos);
    CHECK(parseIntegerLiteral("8#8").error().find("invalid digit") != std::string::npos);
}

TEST_CASE("integer literals: a huge literal fails fast", "[literals]") {
    const std::string huge(5000, '9');
    const auto start = std::chrono::steady_clock::now();
    const Result<uint64_t> parsed = parseIntegerLiteral(huge);
    const auto elapsed = std::chrono::steady_clock::now() - start;
    CHECK_FALSE(parsed.ok());
    CHECK(elapsed < std::chrono::milliseconds(100));
    CHECK(parsed.error().size() < 200);  // the message does not repeat the 5000 digits
    CHECK_FALSE(parseIntegerLiteral(std::string(1'000'000, '1')).ok());
}

TEST_CASE("signed integer literals", "[literals]") {
    CHECK(parseSignedIntegerLiteral("-5").value() == -5);
    CHECK(parseSignedIntegerLiteral("+5").value() == 5);
    CHECK(parseSignedIntegerLiteral("42").value() == 42);
    CHECK(parseSignedIntegerLiteral("-9223372036854775808").value() == INT64_MIN);
    CHECK(parseSignedIntegerLiteral("9223372036854775807").value() == INT64_MAX);
    CHECK_FALSE(parseSignedIntegerLiteral("9223372036854775808").ok());
    CHECK_FALSE(parseSignedIntegerLiteral("-9223372036854775809").ok());
    CHECK(parseSignedIntegerLiteral("16#7F").value() == 127);
    CHECK_FALSE(parseSignedIntegerLiteral("-16#7F").ok());
    CHECK_FALSE(parseSignedIntegerLiteral("-").ok());
    CHECK_FALSE(parseSignedIntegerLiteral("--1").ok());
}

TEST_CASE("real literals", "[literals]") {
    CHECK(parseRealLiteral("1.5E-3").value() == 1.5e-3);
    CHECK(parseRealLiteral("1.0").value() == 1.0);
    CHECK(parseRealLiteral("3e5").value() == 3e5);
    CHECK(parseRealLiteral("1_000.5").value() == 1000.5);
    CHECK(parseRealLiteral("-2.5").value() == -2.5);
    CHECK(parseRealLiteral("+0.25").value() == 0.25);
    CHECK(parseRealLiteral("7").value() == 7.0);
    CHECK(parseRealLiteral("1.0e+2").value() == 100.0);
    CHECK(parseRealLiteral("0.1").value() == 0.1);
    CHECK(parseRealLiteral("1.7976931348623157E308").value() == std::numeric_limits<double>::max());
    CHECK(parseRealLiteral("1E-400").value() == 0.0);  // underflow rounds to zero
    CHECK(std::signbit(parseRealLiteral("-1E-400").value()));
    CHECK(parseRealLiteral("0.0E999999999999999999").value() == 0.0);
}

TEST_CASE("real literals: errors", "[literals]") {
    for (const char* bad : {"", "1.", ".5", "1e", "1e+", "1.5x", "1__.0", "1.0_", "e5", "-", "1,5",
                            "inf", "nan", "1.0 "}) {
        INFO(bad);
        CHECK_FALSE(parseRealLiteral(bad).ok());
    }
    CHECK(parseRealLiteral("1__0.0").value() == 10.0);  // several underscores between digits (decision 0326)
    CHECK_FALSE(parseRealLiteral("1E400").ok());
    CHECK(parseRealLiteral("1E400").error().find("range") != std::string::npos);
    CHECK_FALSE(parseRealLiteral("-1.0E309").ok());
}

TEST_CASE("string literals: plain text and escapes", "[literals]") {
    CHECK(parseStringLiteral("''").value().empty());
    CHECK(parseStringLiteral("'abc'").value() == "abc");
    CHECK(parseStringLiteral("'a$Nb'").value() == "a\nb");
    CHECK(parseStringLiteral("'$L$R$T$P'").value() == "\n\r\t\f");
    CHECK(parseStringLiteral("'$l$r$t$p$n'").value() == "\n\r\t\f\n");
    CHECK(parseStringLiteral("'it$'s'").value() == "it's");
    CHECK(parseStringLiteral("'say $\"hi$\"'").value() == "say \"hi\"");
    CHECK(parseStringLiteral("'say \"hi\"'").value() == "say \"hi\"");
    CHECK(parseStringLiteral("'100$$'").value() == "100$");
    CHECK(parseStringLiteral("'$41$4a'").value() == "AJ");
    CHECK(parseStringLiteral("'$00'").value() == std::string(1, '\0'));
    CHECK(parseStringLiteral("'$FF'").value() == std::string(1, '\xFF'));
    CHECK(parseStringLiteral("'\xC3\xA9'").value() == "\xC3\xA9");  // UTF-8 bytes kept
}

TEST_CASE("string literals: errors", "[literals]") {
    for (const char* bad : {"", "'", "abc", "'abc", "abc'", "\"abc\"", "'a'b'", "'$'", "'a$'",
                            "'$Q'", "'$4'", "'$4G'", "'$G4'"}) {
        INFO(bad);
        const Result<std::string> parsed = parseStringLiteral(bad);
        CHECK_FALSE(parsed.ok());
        CHECK_FALSE(parsed.error().empty());
    }
    CHECK(parseStringLiteral("'$Q'").error().find("escape") != std::string::npos);
}

TEST_CASE("wide string literals", "[literals]") {
    CHECK(parseWideStringLiteral("\"\"").value().empty());
    CHECK(parseWideStringLiteral("\"wide\"").value() == u"wide");
    CHECK(parseWideStringLiteral("\"a$Nb\"").value() == u"a\nb");
    CHECK(parseWideStringLiteral("\"$0041$20AC\"").value() == u"A\u20AC");
    CHECK(parseWideStringLiteral("\"$\"q$\"\"").value() == u"\"q\"");
    CHECK(parseWideStringLiteral("\"it's\"").value() == u"it's");
    CHECK(parseWideStringLiteral("\"\xC3\xA9t\xC3\xA9\"").value() == u"\u00E9t\u00E9");
    CHECK(parseWideStringLiteral("\"\xE2\x82\xAC$N\xE2\x82\xAC\"").value() == u"\u20AC\n\u20AC");
    CHECK(parseWideStringLiteral("\"\xF0\x9F\x98\x80\"").value() == u"\U0001F600");  // surrogate pair
    // A single-quoted literal read as WSTRING keeps two-digit escapes.
    CHECK(parseWideStringLiteral("'$41b'").value() == u"Ab");
}

TEST_CASE("wide string literals: errors", "[literals]") {
    for (const char* bad : {"\"", "\"abc", "\"a\"b\"", "\"$41\"", "\"$004\"", "\"$Z\"", "\"a$\"",
                            "\"\xC3\"", "\"\xFF\"", "\"\xED\xA0\x80\"", "'a\""}) {
        INFO(bad);
        CHECK_FALSE(parseWideStringLiteral(bad).ok());
    }
    CHECK(parseWideStringLiteral("\"\xC3(\"").error().find("UTF-8") != std::string::npos);
}

TEST_CASE("quoteStringLiteral writes what parseStringLiteral reads back", "[literals]") {
    CHECK(quoteStringLiteral("it's 100$") == "'it$'s 100$$'");
    CHECK(quoteStringLiteral("a\nb\tc\r") == "'a$Nb$Tc$R'");
    CHECK(quoteStringLiteral(std::string("x\x01y", 3)) == "'x$01y'");
    CHECK(quoteStringLiteral("say \"hi\"", true) == "\"say $\"hi$\"\"");
    CHECK(quoteStringLiteral(std::string("\x02", 1), true) == "\"$0002\"");
    for (const std::string text : {std::string("plain"), std::string("it's $5\n\t"), std::string("\xC3\xA4 UTF-8"), std::string("\x1F\x7F", 2)})
        CHECK(parseStringLiteral(quoteStringLiteral(text)).value() == text);
    CHECK(parseWideStringLiteral(quoteStringLiteral("wide \"w\" $", true)).value() == u"wide \"w\" $");
}
