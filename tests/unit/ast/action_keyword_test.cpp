// resolveActionKeyword (interpreter/ast/action_keyword.h): `ACTION` stays a
// keyword only where an action declaration starts (decision 0159).
#include <catch2/catch.hpp>

#include <string>

#include "grammar/STLexer.h"
#include "interpreter/ast/action_keyword.h"

namespace {

using L = strun_grammar::STLexer;

// The types the resolved tokens of `text` give the words spelled "action"
// (any case), in order: 'K' for the keyword, 'N' for a name.
std::string actionWords(const std::string& text) {
    strun::ast::ScanResult scan = strun::ast::scanSource(text, 100000);
    strun::ast::resolveActionKeyword(scan.tokens);
    std::string out;
    for (const auto& t : scan.tokens) {
        std::string word = text.substr(t.start, t.stop + 1 - t.start);
        for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (t.type != antlr4::Token::EOF && word == "action") out += t.type == L::ACTION ? 'K' : 'N';
    }
    return out;
}

}  // namespace

TEST_CASE("ACTION is a keyword where an action declaration starts, a name elsewhere", "[lexer][action]") {
    CHECK(actionWords("ACTION Fill: x := 1; END_ACTION") == "K");
    CHECK(actionWords("ACTION Fill x := 1; END_ACTION") == "K");
    CHECK(actionWords("action (* c *) Fill: END_ACTION") == "K");
    CHECK(actionWords("ACTION Action: END_ACTION") == "KN");
    CHECK(actionWords("ACTION Get: END_ACTION") == "K");
    CHECK(actionWords("action := action + 1;") == "NN");
    CHECK(actionWords("fb.action(); fb.Action := 1;") == "NN");
    CHECK(actionWords("VAR action : INT; END_VAR") == "N");
    CHECK(actionWords("x := Twice(action := action);") == "NN");
    CHECK(actionWords("action S= TRUE; action R= FALSE;") == "NN");
    CHECK(actionWords("action WITH Fast;") == "N");
    CHECK(actionWords("a : p.x : action READ_ONLY;") == "N");
    CHECK(actionWords("action") == "N");
    CHECK(actionWords("IF action THEN END_IF") == "N");
}
