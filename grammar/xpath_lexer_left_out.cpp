// What ANTLR's XPath reaches instead of XPathLexer (decision 0499).
//
// From the static ANTLR runtime, every parser program links a chain of
// objects it never calls: Parser -> ParseTreePatternMatcher ->
// ParseTreePattern -> XPath -> XPathLexer. XPathLexer's object builds the
// lexer's ATN at static initialisation, with ANTLR's dynamic_cast-heavy
// deserializer: 0.28 M instructions, a tenth of a one-line `strun run`. The
// link wraps the two symbols XPath's object takes from it (CMakeLists.txt:
// --wrap), so that object is never pulled in and these two stand in for its
// constructor and destructor. strun never evaluates an XPath, so neither is
// ever called; if one were, it stops the program with a message.
#include <cstdio>
#include <cstdlib>

namespace {

[[noreturn]] void notLinked() {
    std::fputs("strun: internal error (ANTLR's XPath lexer is not linked into strun)\n", stderr);
    std::abort();
}

}  // namespace

// The names are the linker's: __wrap_ and the mangled XPathLexer::XPathLexer(antlr4::CharStream*)
// and XPathLexer::~XPathLexer().
extern "C" [[noreturn]] void __wrap__ZN10XPathLexerC1EPN6antlr410CharStreamE() { notLinked(); }
extern "C" [[noreturn]] void __wrap__ZN10XPathLexerD1Ev() { notLinked(); }
