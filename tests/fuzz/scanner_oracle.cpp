#include "tests/fuzz/scanner_oracle.h"

#include <sstream>
#include <vector>

#include <antlr4-runtime.h>

#include "grammar/STLexer.h"
#include "interpreter/ast/st_scanner.h"

namespace strun::fuzz {

namespace {

struct Lexed {
    size_t type, channel, line, column;
    std::string text;
    bool operator==(const Lexed& o) const {
        return type == o.type && channel == o.channel && line == o.line && column == o.column && text == o.text;
    }
};

std::string describe(const Lexed& t) {
    std::ostringstream out;
    out << "type " << static_cast<long long>(t.type) << " channel " << t.channel << " at " << t.line << ":" << t.column
        << " '" << t.text << "'";
    return out.str();
}

// The generated lexer reports keywords as IDENTIFIER: the scanner's table
// tells them apart, so the reference's words go through the same table.
std::vector<Lexed> reference(const std::string& text) {
    antlr4::ANTLRInputStream input(text);
    strun_grammar::STLexer lexer(&input);
    lexer.removeErrorListeners();
    antlr4::CommonTokenStream tokens(&lexer);
    tokens.fill();
    std::vector<Lexed> out;
    for (antlr4::Token* t : tokens.getTokens()) {
        size_t type = t->getType();
        const std::string tokenText = type == antlr4::Token::EOF ? "" : t->getText();
        if (type == strun_grammar::STLexer::IDENTIFIER) type = ast::keywordOrIdentifier(tokenText);
        out.push_back({type, t->getChannel(), t->getLine(), t->getCharPositionInLine(), tokenText});
    }
    return out;
}

std::vector<Lexed> scanned(const std::string& text) {
    std::vector<Lexed> out;
    for (const ast::ScannedToken& t : ast::scanSource(text, 100000000).tokens) {
        const std::string tokenText = t.type == antlr4::Token::EOF ? "" : text.substr(t.start, t.stop + 1 - t.start);
        out.push_back({t.type, t.channel, t.line, t.column, tokenText});
    }
    return out;
}

}  // namespace

std::optional<std::string> scannerDifference(const std::string& text) {
    const std::vector<Lexed> expected = reference(text), actual = scanned(text);
    for (size_t i = 0; i < expected.size() && i < actual.size(); ++i)
        if (!(expected[i] == actual[i]))
            return "token " + std::to_string(i) + ": scanner " + describe(actual[i]) + ", grammar " + describe(expected[i]);
    if (expected.size() != actual.size())
        return "scanner made " + std::to_string(actual.size()) + " tokens, the grammar " + std::to_string(expected.size());
    return std::nullopt;
}

}  // namespace strun::fuzz
