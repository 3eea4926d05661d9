#include <catch2/catch.hpp>

#include "stdlib/text_encoding.h"

using namespace strun::stdlib;

TEST_CASE("UTF-8 to UTF-16", "[text_encoding]") {
    CHECK(utf8ToUtf16("").value().empty());
    CHECK(utf8ToUtf16("abc").value() == u"abc");
    CHECK(utf8ToUtf16("\xC3\xA9").value() == u"\u00E9");
    CHECK(utf8ToUtf16("\xE2\x82\xAC").value() == u"\u20AC");
    CHECK(utf8ToUtf16("\xF0\x9F\x98\x80").value() == u"\U0001F600");
    CHECK(utf8ToUtf16("\xF4\x8F\xBF\xBF").value() == u"\U0010FFFF");
    for (const char* bad : {"\x80", "\xC3", "\xC3(", "\xC0\xAF", "\xE0\x80\xAF", "\xED\xA0\x80",
                            "\xF4\x90\x80\x80", "\xF8\x88\x80\x80\x80", "\xFF"}) {
        INFO(bad);
        CHECK_FALSE(utf8ToUtf16(bad).ok());
    }
}

TEST_CASE("UTF-16 to UTF-8", "[text_encoding]") {
    CHECK(utf16ToUtf8(u"abc") == "abc");
    CHECK(utf16ToUtf8(u"\u00E9\u20AC") == "\xC3\xA9\xE2\x82\xAC");
    CHECK(utf16ToUtf8(u"\U0001F600") == "\xF0\x9F\x98\x80");
    const char16_t loneHigh[] = {u'a', 0xD800, u'b', 0};
    CHECK(utf16ToUtf8(loneHigh) == "a\xEF\xBF\xBD" "b");
    const char16_t loneLow[] = {0xDC00, 0};
    CHECK(utf16ToUtf8(loneLow) == "\xEF\xBF\xBD");
}

TEST_CASE("STRING bytes as text", "[text_encoding]") {
    CHECK(bytesToUtf8("abc") == "abc");
    CHECK(bytesToUtf8("\xC3\xA9") == "\xC3\xA9");        // valid UTF-8 kept
    CHECK(bytesToUtf8("caf\xE9") == "caf\xC3\xA9");      // Latin-1 e-acute
    CHECK(bytesToUtf8(std::string(1, '\xFF')) == "\xC3\xBF");
    CHECK(stringToWString("caf\xE9") == u"caf\u00E9");
    CHECK(stringToWString("\xE2\x82\xAC") == u"\u20AC");
    CHECK(wstringToString(u"\u20AC") == "\xE2\x82\xAC");
    CHECK(stringToWString(wstringToString(u"x\u00E9\U0001F600")) == u"x\u00E9\U0001F600");
}
