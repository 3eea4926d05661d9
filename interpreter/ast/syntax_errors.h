// Readable syntax errors. ANTLR's default messages ("mismatched input 'x'
// expecting {...50 tokens...}") are replaced by "unexpected 'x', expected ';'",
// or, when many tokens would fit, "unexpected 'x', expected an expression".
// Recovery is ANTLR's default (single-token insertion/deletion, resync); the
// reporter keeps at most one message per source line so that one mistake does
// not produce a cascade. A missing ';' is reported after the token it should
// follow, a missing END_IF (END_FOR, ...) at the IF it should close, with a
// note where it was expected.
#pragma once

#include <set>
#include <string>

#include <antlr4-runtime.h>

#include "interpreter/source/source_set.h"

namespace strun::ast {

// How a token is named in a message: 'END_IF', ';', identifier, end of file.
std::string describeTokenType(size_t type, const antlr4::dfa::Vocabulary& vocabulary);
// The offending token as found in the text: 'END_IF', 'foo', end of file.
std::string describeFoundToken(const antlr4::Token* token);

class SyntaxErrorReporter;

// The END_ keyword `word` (an identifier) is a near miss of ("END_WHIL" ->
// "END_WHILE"), or "" when it is none.
std::string mistypedEndKeyword(const std::string& word);

class FriendlyErrorStrategy : public antlr4::DefaultErrorStrategy {
public:
    explicit FriendlyErrorStrategy(SyntaxErrorReporter* reporter = nullptr) : reporter_(reporter) {}

protected:
    void reportNoViableAlternative(antlr4::Parser* parser, const antlr4::NoViableAltException& e) override;
    void reportInputMismatch(antlr4::Parser* parser, const antlr4::InputMismatchException& e) override;
    void reportFailedPredicate(antlr4::Parser* parser, const antlr4::FailedPredicateException& e) override;
    void reportUnwantedToken(antlr4::Parser* parser) override;
    void reportMissingToken(antlr4::Parser* parser) override;
    // ANTLR recovers from `x := 1 + ;` by deleting the ';' and taking the
    // next statement's first word as the operand, which then garbles the
    // next statement too. Statement terminators and END_ keywords are
    // never deleted; the error stays local to the broken statement.
    antlr4::Token* singleTokenDeletion(antlr4::Parser* parser) override;

private:
    // "unexpected X, expected Y" for `found` with the given expected set, and its code.
    std::string message(antlr4::Parser* parser, antlr4::Token* found, const antlr4::misc::IntervalSet& expected, diag::Code* code);
    // Reports the error at `found`, or the better-placed error it stands for:
    // a missing ';' after the previous token, a block whose END_ keyword is missing.
    void reportAt(antlr4::Parser* parser, antlr4::Token* found, const antlr4::misc::IntervalSet& expected);
    bool reportMissingSemicolon(antlr4::Parser* parser, antlr4::Token* found, const antlr4::misc::IntervalSet& expected);
    bool reportUnclosedBlock(antlr4::Parser* parser, antlr4::Token* found, const antlr4::misc::IntervalSet& expected);
    // A declaration block whose END_VAR is missing: the code after it (a
    // statement, another VAR section) is said at the VAR, once.
    bool reportUnclosedVarBlock(antlr4::Parser* parser, antlr4::Token* found);
    // A mistyped END_ keyword (`END_WHIL`) where the error shows: "did you mean".
    bool reportMistypedKeyword(antlr4::Parser* parser, antlr4::Token* found);
    SyntaxErrorReporter* reporter_;
    size_t orphanCloser_ = 0;  // the END_ keyword of a statement recovery dropped (not reported again)
};

// A declaration the grammar accepted without its ';' (`speed : INT` and on
// the next line `limit : INT;`): the same E0002 as a statement's missing ';',
// right after `last`; the next declaration is kept (decision 0163).
void reportMissingDeclarationSemicolon(SyntaxErrorReporter& reporter, antlr4::TokenStream* tokens, antlr4::Token* first,
                                       antlr4::Token* last);

// Forwards parser errors into the CompileLog as "syntax error: ...".
class SyntaxErrorReporter : public antlr4::BaseErrorListener {
public:
    // Past this many, a file is more noise than code: one closing note instead.
    static constexpr size_t kMaxErrorsPerFile = 100;

    SyntaxErrorReporter(CompileLog& log, int fileIndex) : log_(log), fileIndex_(fileIndex) {}

    void syntaxError(antlr4::Recognizer* recognizer, antlr4::Token* offendingSymbol, size_t line,
                     size_t charPositionInLine, const std::string& msg, std::exception_ptr e) override;

    // For errors found outside the parser (lexer error tokens, the AST
    // builder): same format and the same one-per-line rule, unless `always`
    // (an unterminated comment or string must be reported even on a line
    // that already has an error: it explains everything after it).
    // Returns the diagnostic for notes and help (a scratch one when the message is suppressed).
    Diagnostic& report(diag::Code code, size_t line, size_t charPositionInLine, const std::string& msg, bool always = false);
    // The code of the next error the parser reports through syntaxError()
    // (its messages pass through ANTLR, which carries text only); E0001 when not set.
    void codeOfNext(diag::Code code) { nextCode_ = code; }
    int fileIndex() const { return fileIndex_; }
    // Counts `line` as having its error already (a cascade of one reported elsewhere).
    void markLine(size_t line) { linesWithError_.insert(line); }
    // From now on only `always` reports get through (the root cause is already reported).
    void silence() { silenced_ = true; }

private:
    Diagnostic scratch_;
    diag::Code nextCode_ = diag::E0001;
    bool silenced_ = false;
    CompileLog& log_;
    int fileIndex_;
    std::set<size_t> linesWithError_;
    size_t reported_ = 0;
};

}  // namespace strun::ast
