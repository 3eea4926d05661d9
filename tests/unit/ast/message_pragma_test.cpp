// {warning 'text'} and {error 'text'} (CODESYS message pragmas) are scanned
// by hand (interpreter/ast/parse.cpp, decision 0491); the forms accepted and
// refused are those of the regular expression it replaced:
// ^\{\s*(warning|error)\s+'([^']*)'\s*\}$, case-insensitive.
#include <catch2/catch.hpp>

#include <string>

#include "parse_test_support.h"

namespace {

// The messages parsing one program with `pragma` in its body gives, as
// "CODE text" lines.
std::string messagesOf(const std::string& pragma) {
    auto p = strun::ast::test::parse("PROGRAM P\nVAR x : INT; END_VAR\n" + pragma + "\nx := 1;\nEND_PROGRAM\n");
    std::string out;
    for (const auto& m : p->log.messages()) out += m.code + " " + m.message + "\n";
    return out;
}

}  // namespace

TEST_CASE("message pragmas: the forms that report their text", "[parser][pragma]") {
    CHECK(messagesOf("{warning 'plain'}") == "W0010 plain\n");
    CHECK(messagesOf("{error 'stop here'}") == "E0010 stop here\n");
    CHECK(messagesOf("{  WARNING \t 'blanks and case'  }") == "W0010 blanks and case\n");
    CHECK(messagesOf("{ErRoR 'mixed case'}") == "E0010 mixed case\n");
    CHECK(messagesOf("{warning ''}") == "W0010 \n");  // empty text
    CHECK(messagesOf("{warning 'with (parentheses) and \"quotes\"'}") == "W0010 with (parentheses) and \"quotes\"\n");
}

TEST_CASE("message pragmas: other pragmas are not messages", "[parser][pragma]") {
    CHECK(messagesOf("{warning'no blank after the keyword'}").empty());
    CHECK(messagesOf("{warnings 'another word'}").empty());
    CHECK(messagesOf("{warning 'a quote' 'and more'}").empty());
    CHECK(messagesOf("{warning 'it''s'}").empty());  // no doubled quotes inside
    CHECK(messagesOf("{warning unquoted}").empty());
    CHECK(messagesOf("{warning 'text' x}").empty());
    CHECK(messagesOf("{info 'an ordinary pragma'}").empty());
    CHECK(messagesOf("{attribute 'hide'}").empty());
}
