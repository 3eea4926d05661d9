// ScannedTokenStream (interpreter/ast/scanned_tokens.h) answers lookahead
// from tables of its own; ANTLR's CommonTokenStream over the same tokens is
// the reference: LT, LA and LB at every position the parser can be at, and
// consume() at the end (decision 0159). A stream made with ViewsOnly and
// prepared afterwards (how parseFile makes it) answers the same.
#include <catch2/catch.hpp>

#include <optional>
#include <string>

#include "interpreter/ast/scanned_tokens.h"
#include "interpreter/ast/st_scanner.h"

namespace {

using strun::ast::ScannedTokenSource;
using strun::ast::ScannedTokenStream;

// -1 for null, else the token's index in its stream.
long indexOf(antlr4::Token* token) { return token == nullptr ? -1 : static_cast<long>(token->getTokenIndex()); }

void requireSameLookahead(const std::string& text, bool viewsFirst) {
    INFO("source: '" << text << "'" << (viewsFirst ? ", views first" : ""));
    const strun::ast::ScanResult scan = strun::ast::scanSource(text, 1000000);
    ScannedTokenSource fastSource(text, scan.tokens);
    std::optional<ScannedTokenStream> made;
    if (viewsFirst) {
        made.emplace(&fastSource, ScannedTokenStream::ViewsOnly);
        REQUIRE(made->views().size() == scan.tokens.size());
        CHECK(made->size() == 0);  // nothing fetched before prepareForParsing
        made->prepareForParsing();
        made->prepareForParsing();  // a second call changes nothing
    } else {
        made.emplace(&fastSource);
    }
    ScannedTokenStream& fast = *made;
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
        for (bool viewsFirst : {false, true}) requireSameLookahead(s, viewsFirst);
}
