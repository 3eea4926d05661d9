#include <catch2/catch.hpp>

#include <limits>
#include <string>

#include "stdlib/string_functions.h"

using namespace strun::stdlib;
using namespace std::string_literals;

namespace {
constexpr int64_t kHuge = std::numeric_limits<int64_t>::max();
constexpr int64_t kTiny = std::numeric_limits<int64_t>::min();
}  // namespace

TEST_CASE("LEN", "[string_functions]") {
    CHECK(stringLength("") == 0);
    CHECK(stringLength("SUSI") == 4);
    CHECK(stringLength(u"\u20ACx") == 2);
    CHECK(stringLength(std::string(65535, 'a')) == 65535);
}

TEST_CASE("LEFT and RIGHT", "[string_functions]") {
    CHECK(stringLeft("SUSI", 3) == "SUS");
    CHECK(stringLeft("SUSI", 4) == "SUSI");
    CHECK(stringLeft("SUSI", 10) == "SUSI");
    CHECK(stringLeft("SUSI", 0).empty());
    CHECK(stringLeft("SUSI", -1).empty());
    CHECK(stringLeft("SUSI", kTiny).empty());
    CHECK(stringLeft("", 3).empty());
    CHECK(stringRight("SUSI", 3) == "USI");
    CHECK(stringRight("SUSI", 10) == "SUSI");
    CHECK(stringRight("SUSI", kHuge) == "SUSI");
    CHECK(stringRight("SUSI", 0).empty());
    CHECK(stringRight("SUSI", -5).empty());
    CHECK(stringLeft(u"SUSI", 2) == u"SU");
    CHECK(stringRight(u"SUSI", 2) == u"SI");
}

TEST_CASE("MID", "[string_functions]") {
    CHECK(stringMid("SUSI", 2, 2) == "US");
    CHECK(stringMid("SUSI", 4, 1) == "SUSI");
    CHECK(stringMid("SUSI", 10, 3) == "SI");  // up to the end
    CHECK(stringMid("SUSI", 1, 4) == "I");
    CHECK(stringMid("SUSI", 1, 5).empty());   // past the end
    CHECK(stringMid("SUSI", 2, 0).empty());   // position 0
    CHECK(stringMid("SUSI", 2, -1).empty());
    CHECK(stringMid("SUSI", 0, 2).empty());
    CHECK(stringMid("SUSI", -3, 2).empty());
    CHECK(stringMid("SUSI", kHuge, 2) == "USI");
    CHECK(stringMid("SUSI", 2, kHuge).empty());
    CHECK(stringMid("", 1, 1).empty());
    CHECK(stringMid("A better life. A better world.", 15, 16) == "A better world.");
    CHECK(stringMid(u"\u00E9t\u00E9", 1, 2) == u"t");
}

TEST_CASE("CONCAT", "[string_functions]") {
    CHECK(stringConcat("SUSI", "WILLI") == "SUSIWILLI");
    CHECK(stringConcat("", "") .empty());
    CHECK(stringConcat("a", "") == "a");
    CHECK(stringConcat(u"a", u"\u20AC") == u"a\u20AC");
    CHECK(stringConcat("a\0b"s, "c") == "a\0bc"s);
}

TEST_CASE("INSERT", "[string_functions]") {
    CHECK(stringInsert("SUSI", "XY", 2) == "SUXYSI");
    CHECK(stringInsert("SUSI", "XY", 0) == "XYSUSI");
    CHECK(stringInsert("SUSI", "XY", 1) == "SXYUSI");
    CHECK(stringInsert("SUSI", "XY", 4) == "SUSIXY");
    CHECK(stringInsert("SUSI", "XY", 9) == "SUSIXY");  // past the end appends
    CHECK(stringInsert("SUSI", "XY", kHuge) == "SUSIXY");
    CHECK(stringInsert("SUSI", "XY", -1) == "SUSI");
    CHECK(stringInsert("SUSI", "XY", kTiny) == "SUSI");
    CHECK(stringInsert("", "XY", 0) == "XY");
    CHECK(stringInsert("SUSI", "", 2) == "SUSI");
    CHECK(stringInsert(u"SUSI", u"\u20AC", 2) == u"SU\u20ACSI");
}

TEST_CASE("DELETE", "[string_functions]") {
    CHECK(stringDelete("SUXYSI", 2, 3) == "SUSI");
    CHECK(stringDelete("SUXYSI", 2, 1) == "XYSI");
    CHECK(stringDelete("SUXYSI", 2, 0) == "UXYSI");  // CODESYS: POS 0 deletes LEN-1 from the start
    CHECK(stringDelete("SUXYSI", 1, 0) == "SUXYSI");
    CHECK(stringDelete("SUXYSI", 10, 4) == "SUX");   // up to the end
    CHECK(stringDelete("SUXYSI", 1, 6) == "SUXYS");
    CHECK(stringDelete("SUXYSI", 1, 7) == "SUXYSI");  // past the end: unchanged
    CHECK(stringDelete("SUXYSI", 0, 2) == "SUXYSI");
    CHECK(stringDelete("SUXYSI", -2, 2) == "SUXYSI");
    CHECK(stringDelete("SUXYSI", 2, -1) == "SUXYSI");
    CHECK(stringDelete("SUXYSI", kHuge, 1).empty());
    CHECK(stringDelete("SUXYSI", kTiny, 0) == "SUXYSI");
    CHECK(stringDelete("", 1, 1).empty());
    CHECK(stringDelete(u"SUXYSI", 2, 3) == u"SUSI");
}

TEST_CASE("REPLACE", "[string_functions]") {
    CHECK(stringReplace("SUXYSI", "K", 2, 2) == "SKYSI");
    CHECK(stringReplace("SUXYSI", "K", 2, 1) == "KXYSI");
    CHECK(stringReplace("SUXYSI", "K", 2, 0) == "KUXYSI");  // CODESYS: P 0 replaces L-1 chars
    CHECK(stringReplace("SUXYSI", "K", 0, 3) == "SUKXYSI");  // L 0 inserts before P
    CHECK(stringReplace("SUXYSI", "K", -4, 3) == "SUKXYSI");  // negative L counts as 0
    CHECK(stringReplace("SUXYSI", "K", 10, 5) == "SUXYK");     // up to the end
    CHECK(stringReplace("SUXYSI", "K", 1, 7) == "SUXYSIK");    // right after the end
    CHECK(stringReplace("SUXYSI", "K", 1, 50) == "SUXYSIK");   // far past the end appends
    CHECK(stringReplace("SUXYSI", "K", 1, -1) == "SUXYSI");
    CHECK(stringReplace("SUXYSI", "", 2, 3) == "SUSI");
    CHECK(stringReplace("", "AB", 3, 1) == "AB");
    CHECK(stringReplace("SUXYSI", "K", kHuge, 1) == "K");
    CHECK(stringReplace("SUXYSI", "K", kTiny, 0) == "KSUXYSI");
    CHECK(stringReplace(u"SUXYSI", u"\u20AC", 2, 2) == u"S\u20ACYSI");
}

TEST_CASE("FIND", "[string_functions]") {
    CHECK(stringFind("SUXYSI", "XY") == 3);
    CHECK(stringFind("abcdef", "de") == 4);
    CHECK(stringFind("abcabc", "bc") == 2);
    CHECK(stringFind("SUXYSI", "Q") == 0);
    CHECK(stringFind("SUXYSI", "") == 0);
    CHECK(stringFind("", "A") == 0);
    CHECK(stringFind("", "") == 0);
    CHECK(stringFind("AB", "ABC") == 0);
    CHECK(stringFind("SUXYSI", "SUXYSI") == 1);
    CHECK(stringFind("xy", "XY") == 0);  // case-sensitive
    CHECK(stringFind(u"a\u20ACb", u"b") == 3);
}

TEST_CASE("truncate to a declared length", "[string_functions]") {
    CHECK(truncateToLength("abcdef", 3) == "abc");
    CHECK(truncateToLength("abc", 80) == "abc");
    CHECK(truncateToLength("abc", 0).empty());
    CHECK(truncateToLength("abc", -1).empty());
    CHECK(truncateToLength(std::string(100, 'x'), kDefaultStringLength).size() == 80);
    CHECK(truncateToLength(u"\u20AC\u20AC", 1) == u"\u20AC");
}
