// Lexer: every literal form, case-insensitive keywords, comments, pragmas and
// the error tokens for malformed input, as the scanner strun runs produces
// them (interpreter/ast/st_scanner.h).
#include <catch2/catch.hpp>

#include <antlr4-runtime.h>

#include "grammar/STLexer.h"
#include "interpreter/ast/st_scanner.h"
#include "interpreter/ast/utf8_input.h"

using strun_grammar::STLexer;

namespace {

struct Lexed {
    std::string type;  // symbolic token name
    std::string text;
    size_t channel;
    size_t line, col;  // col 1-based
};

std::string tokenName(size_t type) {
    static antlr4::ANTLRInputStream empty("");
    static STLexer vocabularySource(&empty);
    return std::string(vocabularySource.getVocabulary().getSymbolicName(type));
}

std::vector<Lexed> lexAll(const std::string& source) {
    const std::string text = strun::ast::sanitizeUtf8(source);
    const strun::ast::ScanResult scanned = strun::ast::scanSource(text, 1000000);
    std::vector<Lexed> out;
    for (const strun::ast::ScannedToken& t : scanned.tokens) {
        if (t.type == antlr4::Token::EOF) break;
        out.push_back({tokenName(t.type), text.substr(t.start, t.stop + 1 - t.start), t.channel, t.line, t.column + 1});
    }
    return out;
}

// "TYPE:text TYPE:text" of the default-channel tokens.
std::string lex(const std::string& source) {
    std::string out;
    for (const Lexed& t : lexAll(source)) {
        if (t.channel != antlr4::Token::DEFAULT_CHANNEL) continue;
        if (!out.empty()) out += ' ';
        out += t.type + ":" + t.text;
    }
    return out;
}

// The single token the whole source lexes to, as "TYPE:text".
std::string one(const std::string& source) { return lex(source); }

}  // namespace

TEST_CASE("lexer: integer and real literals", "[lexer]") {
    CHECK(one("123") == "INTEGER:123");
    CHECK(one("1_000") == "INTEGER:1_000");
    CHECK(one("16#FF") == "BASED_INTEGER:16#FF");
    CHECK(one("16#ff_ff") == "BASED_INTEGER:16#ff_ff");
    CHECK(one("2#1010_1010") == "BASED_INTEGER:2#1010_1010");
    CHECK(one("8#17") == "BASED_INTEGER:8#17");
    CHECK(one("1.5E-3") == "REAL_LITERAL:1.5E-3");
    CHECK(one("1.0") == "REAL_LITERAL:1.0");
    CHECK(one("3e5") == "REAL_LITERAL:3e5");
    CHECK(one("2.5e+10") == "REAL_LITERAL:2.5e+10");
    // 5000 digits is one token; the range is the checker's business.
    CHECK(one(std::string(5000, '9')) == "INTEGER:" + std::string(5000, '9'));
}

TEST_CASE("lexer: subrange and bit access are not reals", "[lexer]") {
    CHECK(lex("1..10") == "INTEGER:1 DOTDOT:.. INTEGER:10");
    CHECK(lex("-5..-1") == "MINUS:- INTEGER:5 DOTDOT:.. MINUS:- INTEGER:1");
    CHECK(lex("x.3") == "IDENTIFIER:x DOT:. INTEGER:3");
    CHECK(lex("a[1].15") == "IDENTIFIER:a LBRACK:[ INTEGER:1 RBRACK:] DOT:. INTEGER:15");
    CHECK(lex("w.%X3") == "IDENTIFIER:w DOT:. PARTIAL_ACCESS:%X3");
    CHECK(lex("1.0..2.5") == "REAL_LITERAL:1.0 DOTDOT:.. REAL_LITERAL:2.5");
}

TEST_CASE("lexer: typed literals", "[lexer]") {
    CHECK(one("INT#-5") == "TYPED_LITERAL:INT#-5");
    CHECK(one("REAL#1.0") == "TYPED_LITERAL:REAL#1.0");
    CHECK(one("BOOL#1") == "TYPED_LITERAL:BOOL#1");
    CHECK(one("BOOL#TRUE") == "TYPED_LITERAL:BOOL#TRUE");
    CHECK(one("WORD#16#FFFF") == "TYPED_LITERAL:WORD#16#FFFF");
    CHECK(one("Color#Red") == "TYPED_LITERAL:Color#Red");
    CHECK(one("STRING#'x'") == "TYPED_LITERAL:STRING#'x'");
    CHECK(one("WSTRING#\"x\"") == "TYPED_LITERAL:WSTRING#\"x\"");
    CHECK(one("LREAL#-1.5E3") == "TYPED_LITERAL:LREAL#-1.5E3");
    CHECK(lex("TRUE FALSE true False") == "TRUE:TRUE FALSE:FALSE TRUE:true FALSE:False");
}

TEST_CASE("lexer: duration literals", "[lexer]") {
    for (const char* s : {"T#1h2m3s4ms", "TIME#-5s", "LT#1us", "LTIME#1.5s", "T#1.5s", "t#1d_2h", "T#-250ms",
                          "time#100ns", "T#1m", "T#1ms", "T#1d2h3m4s5ms6us7ns", "ltime#5m"})
        CHECK(one(s) == std::string("DURATION_LITERAL:") + s);
}

TEST_CASE("lexer: date and time-of-day literals", "[lexer]") {
    for (const char* s : {"D#2026-01-31", "DATE#2026-01-31", "LD#2026-01-31", "LDATE#2026-01-31", "d#2026-1-1"})
        CHECK(one(s) == std::string("DATE_LITERAL:") + s);
    for (const char* s : {"TOD#13:05:00.25", "TIME_OF_DAY#13:05:00", "LTOD#13:05:00", "tod#1:2:3", "TOD#13:05"})
        CHECK(one(s) == std::string("TOD_LITERAL:") + s);
    for (const char* s : {"DT#2026-01-31-13:05:00", "DATE_AND_TIME#2026-01-31-13:05:00.5", "LDT#2026-01-31-13:05:00",
                          "dt#2026-1-31-1:5:0"})
        CHECK(one(s) == std::string("DT_LITERAL:") + s);
}

TEST_CASE("lexer: strings with $ escapes", "[lexer]") {
    CHECK(one("'abc'") == "STRING_LITERAL:'abc'");
    CHECK(one("''") == "STRING_LITERAL:''");
    CHECK(one("'a$Nb$L$R$T$'$$$0A$\"'") == "STRING_LITERAL:'a$Nb$L$R$T$'$$$0A$\"'");
    CHECK(one("'say \"hi\"'") == "STRING_LITERAL:'say \"hi\"'");
    CHECK(one("\"wide$\"x\"") == "WSTRING_LITERAL:\"wide$\"x\"");
    CHECK(one("\"it's\"") == "WSTRING_LITERAL:\"it's\"");
    CHECK(one("'(* not a comment *)'") == "STRING_LITERAL:'(* not a comment *)'");
}

TEST_CASE("lexer: keywords are case-insensitive, identifiers keep their case", "[lexer]") {
    CHECK(lex("if If iF IF") == "IF:if IF:If IF:iF IF:IF");
    CHECK(lex("end_if End_If") == "END_IF:end_if END_IF:End_If");
    CHECK(lex("function_block Function_Block") == "FUNCTION_BLOCK:function_block FUNCTION_BLOCK:Function_Block");
    CHECK(lex("and_then Or_Else mod") == "AND_THEN:and_then OR_ELSE:Or_Else MOD:mod");
    CHECK(lex("MyVar my_var_2 _x iff endif") ==
          "IDENTIFIER:MyVar IDENTIFIER:my_var_2 IDENTIFIER:_x IDENTIFIER:iff IDENTIFIER:endif");
    CHECK(lex("__NEW") == "IDENTIFIER:__NEW");
}

TEST_CASE("lexer: operators", "[lexer]") {
    CHECK(lex(":= => ?= ** <= >= <> < > = & ^") ==
          "ASSIGN::= ARROW:=> TRY_ASSIGN:?= POW:** LE:<= GE:>= NE:<> LT_OP:< GT_OP:> EQ:= AMP:& CARET:^");
    CHECK(lex("x S= y") == "IDENTIFIER:x IDENTIFIER:S EQ:= IDENTIFIER:y");
}

TEST_CASE("lexer: direct addresses", "[lexer]") {
    for (const char* s : {"%IX0.0", "%QW2", "%MD10", "%IB3", "%QX1.7", "%I*", "%Q*", "%ix0.0", "%IW2.1.3", "%ML4"})
        CHECK(one(s) == std::string("DIRECT_ADDRESS:") + s);
}

TEST_CASE("lexer: comments, nested comments and pragmas", "[lexer]") {
    CHECK(lex("a (* c *) b") == "IDENTIFIER:a IDENTIFIER:b");
    CHECK(lex("a (* outer (* inner *) still comment *) b") == "IDENTIFIER:a IDENTIFIER:b");
    CHECK(lex("a (* (* (* x *) *) *) b") == "IDENTIFIER:a IDENTIFIER:b");
    CHECK(lex("a (* ** *) b (***) c (* *** *) d") == "IDENTIFIER:a IDENTIFIER:b IDENTIFIER:c IDENTIFIER:d");
    CHECK(lex("a /* c (* */ b") == "IDENTIFIER:a IDENTIFIER:b");
    CHECK(lex("a // c\nb") == "IDENTIFIER:a IDENTIFIER:b");
    CHECK(lex("a (* multi\nline\n*) b") == "IDENTIFIER:a IDENTIFIER:b");

    auto all = lexAll("{attribute 'hide'} x");
    REQUIRE(all.size() == 2);
    CHECK(all[0].type == "PRAGMA");
    CHECK(all[0].channel == STLexer::PRAGMAS);
    CHECK(all[0].text == "{attribute 'hide'}");
    CHECK(all[1].type == "IDENTIFIER");
    // Line and column are tracked through a multi-line nested comment.
    auto after = lexAll("(* a\n (* b *)\n*)  x");
    REQUIRE(after.size() == 1);
    CHECK(after[0].line == 3);
    CHECK(after[0].col == 5);
}

TEST_CASE("lexer: malformed input becomes error-channel tokens at its start", "[lexer]") {
    auto comment = lexAll("x := 1;\n  (* never (* closed *) ...\nmore");
    REQUIRE(!comment.empty());
    CHECK(comment.back().type == "UNTERMINATED_BLOCK_COMMENT");
    CHECK(comment.back().channel == STLexer::ERRORS);
    CHECK(comment.back().line == 2);
    CHECK(comment.back().col == 3);

    auto cComment = lexAll("a /* open");
    CHECK(cComment.back().type == "UNTERMINATED_C_COMMENT");

    auto str = lexAll("s := 'abc;\nx");
    CHECK(str[2].type == "UNTERMINATED_STRING");
    CHECK(str[2].col == 6);
    CHECK(str[3].type == "IDENTIFIER");  // lexing goes on on the next line

    auto pragma = lexAll("{attribute 'x'");
    CHECK(pragma.back().type == "UNTERMINATED_PRAGMA");

    auto stray = lexAll("a ` b");
    REQUIRE(stray.size() == 3);
    CHECK(stray[1].type == "ERROR_CHAR");
    CHECK(stray[1].channel == STLexer::ERRORS);
}

TEST_CASE("lexer: a large file's tokens fit the room reserved for them (decision 0494)", "[lexer]") {
    std::string text;
    while (text.size() < 200000) text += "counter := counter + 1; (* one statement *)\n";
    const strun::ast::ScanResult scan = strun::ast::scanSource(text, 1000000);
    REQUIRE(scan.tokens.size() < text.size() / 4);
    CHECK(scan.tokens.capacity() == text.size() / 4 + 16);  // never grown and copied
    CHECK(strun::ast::scanSource("a b c", 3).tokens.capacity() <= 3 + 16);  // bounded by the limit
}

TEST_CASE("lexer: the token limit stops scanning and says so", "[lexer]") {
    const strun::ast::ScanResult within = strun::ast::scanSource("a b c", 3);
    CHECK_FALSE(within.overLimit);
    CHECK(within.tokens.size() == 4);  // three and EOF
    const strun::ast::ScanResult over = strun::ast::scanSource("a b c d e f", 3);
    CHECK(over.overLimit);
    CHECK(over.tokens.back().type == antlr4::Token::EOF);
    CHECK(over.tokens.size() <= 5);
}
