// ScannedTokenStream (interpreter/ast/scanned_tokens.h) answers lookahead
// from tables of its own; ANTLR's CommonTokenStream over the same tokens is
// the reference: LT, LA and LB at every position the parser can be at, and
// consume() at the end (decision 0159).
#include <catch2/catch.hpp>

#include <span>
#include <string>

#include "interpreter/ast/scanned_tokens.h"
#include "interpreter/ast/st_scanner.h"

namespace {

using strun::ast::ScannedTokenSource;
using strun::ast::ScannedTokenStream;

// -1 for null, else the token's index in its stream.
long indexOf(antlr4::Token* token) { return token == nullptr ? -1 : static_cast<long>(token->getTokenIndex()); }

void requireSameLookahead(const std::string& text) {
    INFO("source: '" << text << "'");
    const strun::ast::ScanResult scan = strun::ast::scanSource(text, 1000000);
    ScannedTokenSource fastSource(text, scan.tokens);
    ScannedTokenStream fast(&fastSource);
    ScannedTokenSource referenceSource(text, scan.tokens);
    antlr4::CommonTokenStream reference(&referenceSource);
    reference.fill();
    REQUIRE(fast.size() == reference.size());
    for (int guard = 0; guard < 10000; ++guard) {
        REQUIRE(fast.index() == reference.index());
        for (long k = -4; k <= 4; ++k) {
            INFO("position " << fast.index() << ", LT(" << k << ")");
            CHECK(indexOf(fast.LT(k)) == indexOf(reference.LT(k)));
            if (reference.LT(k) != nullptr) CHECK(fast.LA(k) == reference.LA(k));  // its LA dereferences LT's null
        }
        if (reference.LA(1) == antlr4::Token::EOF) {
            CHECK_THROWS(reference.consume());
            CHECK_THROWS(fast.consume());
            break;
        }
        fast.consume();
        reference.consume();
    }
    fast.seek(0);
    reference.seek(0);
    CHECK(fast.index() == reference.index());
    CHECK(indexOf(fast.LT(1)) == indexOf(reference.LT(1)));
}

}  // namespace

TEST_CASE("the scanned token stream looks ahead and back as CommonTokenStream does", "[lexer][tokens]") {
    for (const char* s : {"", " ", "(* only a comment *)", "x", "x := 1;", "(* a *) x (* b *) := (* c *) 1; // d\n",
                          "{attribute 'x'} PROGRAM P VAR a : INT; END_VAR a := a + 1; END_PROGRAM (* end *)",
                          "// first\n// second\nFUNCTION F : INT\nF := 1;\nEND_FUNCTION\n// after",
                          "a.b[1]^.c(x := 1, y => z);", "(* unterminated", "'open string", "@ $ stray"})
        requireSameLookahead(s);
}

// Decision 0493: the first half of a file parsed in halves reads the file's
// tokens in place, with an EOF of its own after them.
TEST_CASE("a token source over part of the tokens and a separate EOF gives that part and the EOF", "[lexer][tokens]") {
    const std::string text = "x := 1; (* c *) y := 2;";
    const strun::ast::ScanResult scan = strun::ast::scanSource(text, 1000000);
    REQUIRE(scan.tokens.size() > 6);
    const size_t keep = 4;
    strun::ast::ScannedToken eof = scan.tokens.back();
    eof.start = scan.tokens[keep].start;
    eof.stop = eof.start - 1;
    ScannedTokenSource part(text, std::span<const strun::ast::ScannedToken>(scan.tokens).first(keep), &eof);
    REQUIRE(part.size() == keep + 1);
    ScannedTokenStream stream(&part);
    REQUIRE(stream.size() == keep + 1);
    for (size_t i = 0; i < keep; ++i) {
        CHECK(stream.get(i)->getType() == scan.tokens[i].type);
        CHECK(stream.get(i)->getStartIndex() == scan.tokens[i].start);
        CHECK(stream.get(i)->getTokenIndex() == i);
    }
    CHECK(stream.get(keep)->getType() == antlr4::Token::EOF);
    CHECK(stream.get(keep)->getStartIndex() == scan.tokens[keep].start);
    // As a lexer would: EOF again past the end.
    for (size_t i = 0; i < keep + 3; ++i) (void)part.nextToken();
    CHECK(part.nextToken()->getType() == antlr4::Token::EOF);
}
