// Every parser and conversion must answer any input with a value or an error
// message: no crash, no hang, no exception. Deterministic pseudo-random inputs
// built from the characters that matter to the grammars.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <string>

#include "stdlib/conversions.h"
#include "stdlib/literals.h"
#include "stdlib/string_functions.h"
#include "stdlib/time_literals.h"
#include "stdlib/value_format.h"

using namespace strun::stdlib;

namespace {

std::string randomText(std::mt19937_64& rng) {
    static const std::string kAlphabet =
        "0123456789_#.:-+eEdhmsunTtDOLIAF$'\"NRP xX\xC3\xA9\xFF";
    std::uniform_int_distribution<size_t> length(0, 24);
    std::uniform_int_distribution<size_t> pick(0, kAlphabet.size() - 1);
    std::string text;
    const size_t n = length(rng);
    for (size_t i = 0; i < n; ++i) text.push_back(kAlphabet[pick(rng)]);
    return text;
}

template <typename T>
void checkConsistent(const Result<T>& result) {
    // ok() and the message agree: a failure always explains itself.
    CHECK(result.ok() == result.error().empty());
}

}  // namespace

TEST_CASE("parsers answer arbitrary text with a value or an error", "[robustness]") {
    std::mt19937_64 rng(61131);
    for (int round = 0; round < 20000; ++round) {
        std::string text = randomText(rng);
        if (round % 3 == 0) text = "T#" + text;
        if (round % 5 == 0) text = "'" + text + "'";
        INFO(text);
        checkConsistent(parseIntegerLiteral(text));
        checkConsistent(parseSignedIntegerLiteral(text));
        checkConsistent(parseRealLiteral(text));
        checkConsistent(parseStringLiteral(text));
        checkConsistent(parseWideStringLiteral(text));
        checkConsistent(parseDurationLiteral(text));
        checkConsistent(parseDateLiteral(text));
        checkConsistent(parseTimeOfDayLiteral(text));
        checkConsistent(parseDateTimeLiteral(text));
        checkConsistent(stringToInteger(text, 16, true));
        checkConsistent(stringToReal(text));
        checkConsistent(stringToBool(text));
        const Result<int64_t> duration = parseDurationLiteral(text);
        if (duration) {
            // Whatever parses formats and parses back to the same value.
            CHECK(parseDurationLiteral(formatDuration(duration.value())).value() == duration.value());
        }
    }
}

TEST_CASE("string functions accept any positions", "[robustness]") {
    std::mt19937_64 rng(2013);
    std::uniform_int_distribution<int64_t> position(-3, 30);
    for (int round = 0; round < 5000; ++round) {
        const std::string a = randomText(rng);
        const std::string b = randomText(rng);
        const int64_t p = position(rng);
        const int64_t l = position(rng);
        CHECK(stringLength(stringMid(a, l, p)) <= std::max<int64_t>(0, l));
        CHECK(stringLength(stringLeft(a, l)) <= stringLength(a));
        CHECK(stringLength(stringDelete(a, l, p)) <= stringLength(a));
        CHECK(stringLength(stringInsert(a, b, p)) >= stringLength(a));
        CHECK(stringLength(stringReplace(a, b, l, p)) <= stringLength(a) + stringLength(b));
        const int64_t found = stringFind(a, b);
        CHECK(found >= 0);
        if (found > 0) CHECK(stringMid(a, stringLength(b), found) == b);
    }
}
