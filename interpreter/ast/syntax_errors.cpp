#include "interpreter/ast/syntax_errors.h"

#include <algorithm>
#include <cctype>
#include <vector>

#include <fmt/format.h>

#include "grammar/STLexer.h"
#include "grammar/STParser.h"
#include "interpreter/source/closest_name.h"

namespace strun::ast {

namespace {

using L = strun_grammar::STLexer;
using P = strun_grammar::STParser;

bool isNameToken(size_t type) { return P::isNameToken(type); }

bool isLiteralToken(size_t type) {
    switch (type) {
        case L::INTEGER: case L::BASED_INTEGER: case L::REAL_LITERAL: case L::TRUE: case L::FALSE:
        case L::STRING_LITERAL: case L::WSTRING_LITERAL: case L::DURATION_LITERAL: case L::DATE_LITERAL:
        case L::TOD_LITERAL: case L::DT_LITERAL: case L::TYPED_LITERAL:
            return true;
        default:
            return false;
    }
}

// Keywords that close or continue a construct: worth naming even when the
// full expected set is too large to list.
bool isStructuralKeyword(const std::string& symbolic) {
    return symbolic.rfind("END_", 0) == 0 || symbolic == "ELSIF" || symbolic == "ELSE" || symbolic == "UNTIL" ||
           symbolic == "THEN" || symbolic == "DO" || symbolic == "OF";
}

// What the parser was looking for, in words, by the rule it was in.
std::string phraseForRule(size_t ruleIndex) {
    switch (ruleIndex) {
        case P::RuleExpression: case P::RuleUnaryExpr:
        case P::RuleCaseLabel: case P::RuleExpressionList: case P::RuleArrayRange:
            return "an expression";
        case P::RuleStatement: case P::RuleStmtList:
            return "a statement";
        case P::RuleTypeSpec: case P::RuleTypeArguments: case P::RuleReturnType:
            return "a type";
        case P::RuleVarDecl: case P::RuleAccessDecl: case P::RuleVarName: case P::RuleVarBlock:
            return "a variable declaration";
        case P::RuleCompilationUnit: case P::RuleTopLevelItem: case P::RuleNamespaceDecl:
            return "a declaration (PROGRAM, FUNCTION, FUNCTION_BLOCK, INTERFACE, TYPE, VAR_GLOBAL, CONFIGURATION)";
        case P::RuleInitializer: case P::RuleArrayInitItem: case P::RuleStructInitItem:
            return "an initial value";
        case P::RuleArgList: case P::RuleArg:
            return "an argument";
        case P::RulePostfixOp:
            return "a member name";
        default:
            return "";
    }
}

std::string joinAlternatives(const std::vector<std::string>& items) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += (i + 1 == items.size()) ? " or " : ", ";
        out += items[i];
    }
    return out;
}

}  // namespace

std::string describeTokenType(size_t type, const antlr4::dfa::Vocabulary& vocabulary) {
    if (type == antlr4::Token::EOF) return "end of file";
    if (isNameToken(type)) return "identifier";
    if (isLiteralToken(type)) return "literal";
    if (type == L::DIRECT_ADDRESS) return "direct address";
    if (type == L::PARTIAL_ACCESS) return "bit access";
    const std::string literal = vocabulary.getLiteralName(type);
    if (!literal.empty()) return literal;  // already quoted: ';'
    return fmt::format("'{}'", vocabulary.getSymbolicName(type));
}

std::string describeFoundToken(const antlr4::Token* token) {
    if (token == nullptr || token->getType() == antlr4::Token::EOF) return "end of file";
    std::string text = token->getText();
    if (text.size() > 30) text = text.substr(0, 27) + "...";
    std::string shown;
    for (char c : text) {
        if (c == '\n') shown += "\\n";
        else if (c == '\r') shown += "\\r";
        else if (c == '\t') shown += "\\t";
        else shown += c;
    }
    return fmt::format("'{}'", shown);
}

std::string FriendlyErrorStrategy::message(antlr4::Parser* parser, antlr4::Token* found,
                                           const antlr4::misc::IntervalSet& expected, diag::Code* code) {
    const auto& vocabulary = parser->getVocabulary();
    std::vector<std::string> names;
    std::vector<std::string> structural;
    // `(x := v)` as a value (decision 0203) is rare: after `(a + b` the
    // missing ')' is news, ':=' is not.
    const bool parenthesised = expected.contains(static_cast<size_t>(L::RPAREN)) && !expected.contains(static_cast<size_t>(L::ARROW));
    for (size_t type : expected.toList()) {
        // Nor after `b := 1` (a chained `b := 1 := ...` is not what is missing).
        if ((parenthesised || expected.contains(static_cast<size_t>(L::SEMI))) && type == static_cast<size_t>(L::ASSIGN)) continue;
        std::string name = describeTokenType(type, vocabulary);
        if (std::find(names.begin(), names.end(), name) != names.end()) continue;
        names.push_back(name);
        if (type != antlr4::Token::EOF && isStructuralKeyword(vocabulary.getSymbolicName(type)))
            structural.push_back(name);
    }
    std::string text = "unexpected " + describeFoundToken(found);
    // What alone is expected names the kind of mistake: a missing ';' (E0002),
    // a construct left open (E0003); anything else is E0001.
    auto expecting = [&](const std::vector<std::string>& alternatives) {
        *code = diag::E0001;
        if (alternatives.size() == 1 && alternatives[0] == "';'") *code = diag::E0002;
        if (alternatives.size() == 1 && alternatives[0].rfind("'END_", 0) == 0) *code = diag::E0003;
        return text + ", expected " + joinAlternatives(alternatives);
    };
    *code = diag::E0001;
    if (!names.empty() && names.size() <= 4) return expecting(names);

    std::vector<std::string> hint;
    antlr4::ParserRuleContext* context = parser->getContext();
    if (context != nullptr) {
        const std::string phrase = phraseForRule(context->getRuleIndex());
        if (!phrase.empty()) hint.push_back(phrase);
    }
    if (structural.size() <= 3)
        hint.insert(hint.end(), structural.begin(), structural.end());
    if (hint.empty()) return text;
    return expecting(hint);
}

namespace {

// Columns are code points, as the scanner counts them.
size_t codePoints(const std::string& text) {
    size_t n = 0;
    for (unsigned char c : text)
        if ((c & 0xC0) != 0x80) ++n;
    return n;
}

// The source text of tokens [from, to] with runs of blanks as one space, shortened.
std::string excerpt(antlr4::TokenStream* tokens, antlr4::Token* from, antlr4::Token* to) {
    antlr4::CharStream* chars = from->getInputStream();
    if (chars == nullptr || to->getStopIndex() < from->getStartIndex()) return from->getText();
    std::string raw = chars->getText(antlr4::misc::Interval(from->getStartIndex(), to->getStopIndex()));
    std::string out;
    for (char c : raw) {
        const bool blank = c == ' ' || c == '\t' || c == '\n' || c == '\r';
        if (blank) {
            if (!out.empty() && out.back() != ' ') out += ' ';
        } else {
            out += c;
        }
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    if (codePoints(out) > 40) {
        // Keep the end: it is what the ';' follows.
        size_t cut = out.size() - 37;
        while (cut < out.size() && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80) ++cut;
        out = "..." + out.substr(cut);
    }
    return out;
}

// The END_ keyword that closes the construct a context stands for, or 0.
size_t closingKeyword(antlr4::ParserRuleContext* c) {
    if (dynamic_cast<P::IfStmtContext*>(c)) return L::END_IF;
    if (dynamic_cast<P::CaseStmtContext*>(c)) return L::END_CASE;
    if (dynamic_cast<P::ForStmtContext*>(c)) return L::END_FOR;
    if (dynamic_cast<P::WhileStmtContext*>(c)) return L::END_WHILE;
    if (dynamic_cast<P::RepeatStmtContext*>(c)) return L::END_REPEAT;
    if (dynamic_cast<P::VarBlockContext*>(c)) return L::END_VAR;
    if (dynamic_cast<P::ProgramDeclContext*>(c)) return L::END_PROGRAM;
    if (dynamic_cast<P::FunctionDeclContext*>(c)) return L::END_FUNCTION;
    if (dynamic_cast<P::FunctionBlockDeclContext*>(c)) return L::END_FUNCTION_BLOCK;
    if (dynamic_cast<P::InterfaceDeclContext*>(c)) return L::END_INTERFACE;
    if (dynamic_cast<P::ClassDeclContext*>(c)) return L::END_CLASS;
    if (dynamic_cast<P::MethodDeclContext*>(c)) return L::END_METHOD;
    if (dynamic_cast<P::ActionDeclContext*>(c)) return L::END_ACTION;
    if (dynamic_cast<P::PropertyDeclContext*>(c)) return L::END_PROPERTY;
    if (dynamic_cast<P::PropertyGetterContext*>(c)) return L::END_GET;
    if (dynamic_cast<P::PropertySetterContext*>(c)) return L::END_SET;
    if (dynamic_cast<P::TypeDeclContext*>(c)) return L::END_TYPE;
    if (dynamic_cast<P::StructTypeContext*>(c)) return L::END_STRUCT;
    return 0;
}

// The keywords that open a declaration section.
bool isVarSectionKeyword(size_t type) {
    switch (type) {
        case L::VAR: case L::VAR_INPUT: case L::VAR_OUTPUT: case L::VAR_IN_OUT: case L::VAR_TEMP: case L::VAR_STAT: case L::VAR_GENERIC:
        case L::VAR_INST: case L::VAR_GLOBAL: case L::VAR_EXTERNAL: case L::VAR_CONFIG: case L::VAR_ACCESS:
            return true;
        default:
            return false;
    }
}

// Keywords that end a POU or a type: a VAR block cannot reach past them.
bool endsDeclarationScope(size_t type) {
    switch (type) {
        case L::END_PROGRAM: case L::END_FUNCTION: case L::END_FUNCTION_BLOCK: case L::END_METHOD: case L::END_ACTION:
        case L::END_PROPERTY: case L::END_GET: case L::END_SET: case L::END_INTERFACE: case L::END_CLASS:
        case L::END_CONFIGURATION: case L::END_RESOURCE: case L::END_NAMESPACE: case L::END_TYPE:
            return true;
        default:
            return false;
    }
}

// Statements that cannot be declarations.
bool startsStatement(size_t type) {
    switch (type) {
        case L::IF: case L::FOR: case L::WHILE: case L::CASE: case L::REPEAT: case L::RETURN: case L::EXIT: case L::CONTINUE:
            return true;
        default:
            return false;
    }
}

antlr4::Token* previousOnDefaultChannel(antlr4::TokenStream* tokens, antlr4::Token* token) {
    for (size_t i = token->getTokenIndex(); i-- > 0;) {
        antlr4::Token* t = tokens->get(i);
        if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL) return t;
    }
    return nullptr;
}

}  // namespace

std::string mistypedEndKeyword(const std::string& word) {
    static const std::vector<std::string> keywords = {
        "END_IF", "END_CASE", "END_FOR", "END_WHILE", "END_REPEAT", "END_VAR", "END_PROGRAM", "END_FUNCTION",
        "END_FUNCTION_BLOCK", "END_METHOD", "END_ACTION", "END_PROPERTY", "END_GET", "END_SET", "END_TYPE", "END_STRUCT",
        "END_INTERFACE", "END_CLASS", "END_NAMESPACE", "END_CONFIGURATION", "END_RESOURCE", "END_UNION"};
    std::string upperWord;
    for (char ch : word) upperWord += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    // Only words that look like an END_ keyword: a variable called ENDIF stays a variable.
    if (upperWord.size() < 5 || upperWord.rfind("END", 0) != 0) return {};
    return closestName(upperWord, keywords);
}

bool FriendlyErrorStrategy::reportMistypedKeyword(antlr4::Parser* parser, antlr4::Token* found) {
    if (found == nullptr) return false;
    antlr4::TokenStream* tokens = parser->getTokenStream();
    // The word is the offending token (`END_WHIL END_PROGRAM`: the one before it), or
    // stands alone as a statement somewhere in the block that is left open.
    auto tryWord = [&](antlr4::Token* word) {
        if (word == nullptr || !P::isNameToken(word->getType())) return false;
        const std::string keyword = mistypedEndKeyword(word->getText());
        if (keyword.empty()) return false;
        reporter_->report(diag::E0001, word->getLine(), word->getCharPositionInLine(),
                          fmt::format("'{}' is not a keyword: did you mean '{}'?", word->getText(), keyword));
        return true;
    };
    if (tryWord(found) || tryWord(previousOnDefaultChannel(tokens, found))) return true;
    if (found->getType() != antlr4::Token::EOF && parser->getVocabulary().getSymbolicName(found->getType()).rfind("END_", 0) != 0)
        return false;
    for (antlr4::ParserRuleContext* c = parser->getContext(); c != nullptr; c = dynamic_cast<antlr4::ParserRuleContext*>(c->parent)) {
        const size_t closer = closingKeyword(c);
        if (closer == 0 || c->getStart() == nullptr) continue;
        const std::string closerName = parser->getVocabulary().getSymbolicName(closer);
        for (size_t i = c->getStart()->getTokenIndex() + 1; i < found->getTokenIndex(); ++i) {
            antlr4::Token* t = tokens->get(i);
            if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL && P::isNameToken(t->getType()) &&
                mistypedEndKeyword(t->getText()) == closerName)
                return tryWord(t);
        }
        return false;  // only the innermost open block
    }
    return false;
}

bool FriendlyErrorStrategy::reportUnclosedVarBlock(antlr4::Parser* parser, antlr4::Token* found) {
    if (found == nullptr || found->getType() == antlr4::Token::EOF) return false;
    P::VarBlockContext* block = nullptr;
    for (antlr4::ParserRuleContext* c = parser->getContext(); c != nullptr && block == nullptr;
         c = dynamic_cast<antlr4::ParserRuleContext*>(c->parent))
        block = dynamic_cast<P::VarBlockContext*>(c);
    if (block == nullptr || block->getStart() == nullptr) return false;
    antlr4::TokenStream* tokens = parser->getTokenStream();
    // What comes is code, not a declaration: `x := 1`, `f(...)`, IF ..., or the next VAR section.
    antlr4::Token* before = found;
    const size_t type = found->getType();
    if (type == L::ASSIGN || type == L::LPAREN) {
        before = previousOnDefaultChannel(tokens, found);
        if (before == nullptr || !P::isNameToken(before->getType()) || before->getLine() == block->getStart()->getLine()) return false;
    } else if (!startsStatement(type) && !isVarSectionKeyword(type)) {
        return false;
    }
    // An END_VAR further on (before the POU ends or another section opens)
    // closes this block: then it is another mistake. A new VAR section itself
    // says this one was left open.
    for (size_t i = found->getTokenIndex(); !isVarSectionKeyword(type); ++i) {
        antlr4::Token* t = tokens->get(i);
        if (t->getType() == L::END_VAR) return false;
        if (t->getType() == antlr4::Token::EOF || endsDeclarationScope(t->getType()) ||
            (i > found->getTokenIndex() && isVarSectionKeyword(t->getType())))
            break;
    }
    antlr4::Token* opener = block->getStart();
    Diagnostic& d = reporter_->report(diag::E0003, opener->getLine(), opener->getCharPositionInLine(),
                                      fmt::format("'{}' has no matching 'END_VAR'", opener->getText()));
    d.note(Loc{reporter_->fileIndex(), static_cast<int>(before->getLine()), static_cast<int>(before->getCharPositionInLine()) + 1},
           fmt::format("'END_VAR' expected before {}", describeFoundToken(before)));
    reporter_->markLine(before->getLine());  // the rest of that line is the same mistake
    return true;
}

void reportMissingDeclarationSemicolon(SyntaxErrorReporter& reporter, antlr4::TokenStream* tokens, antlr4::Token* first,
                                       antlr4::Token* last) {
    const size_t column = last->getCharPositionInLine() + codePoints(last->getText());
    reporter.report(diag::E0002, last->getLine(), column, fmt::format("expected ';' after '{}'", excerpt(tokens, first, last)));
}

bool FriendlyErrorStrategy::reportMissingSemicolon(antlr4::Parser* parser, antlr4::Token* found,
                                                   const antlr4::misc::IntervalSet& expected) {
    // In a declaration the parser may not list ';' (it was still deciding
    // between a type and an access path), but a new line there means the same.
    const bool inDeclaration = dynamic_cast<P::VarDeclContext*>(parser->getContext()) != nullptr;
    if ((!expected.contains(static_cast<size_t>(L::SEMI)) && !inDeclaration) || found == nullptr) return false;
    antlr4::TokenStream* tokens = parser->getTokenStream();
    // The last token before `found` (not LT(-1): a failed prediction has not consumed it yet).
    antlr4::Token* prev = nullptr;
    for (size_t i = found->getTokenIndex(); i-- > 0;) {
        antlr4::Token* t = tokens->get(i);
        if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL) {
            prev = t;
            break;
        }
    }
    if (prev == nullptr || prev->getType() == antlr4::Token::EOF || found->getLine() <= prev->getLine()) return false;
    // At the end of the file something larger is missing (or a comment swallowed the rest).
    if (found->getType() == antlr4::Token::EOF) return false;
    if (prev->getText().find('\n') != std::string::npos) return false;
    // The statement or declaration the ';' ends, for the message.
    antlr4::Token* first = prev;
    for (antlr4::ParserRuleContext* c = parser->getContext(); c != nullptr; c = dynamic_cast<antlr4::ParserRuleContext*>(c->parent)) {
        if (dynamic_cast<P::StatementContext*>(c) || dynamic_cast<P::VarDeclContext*>(c)) {
            if (c->getStart() != nullptr && c->getStart()->getTokenIndex() <= prev->getTokenIndex()) first = c->getStart();
            break;
        }
    }
    const size_t column = prev->getCharPositionInLine() + codePoints(prev->getText());
    Diagnostic& d = reporter_->report(diag::E0002, prev->getLine(), column, fmt::format("expected ';' after '{}'", excerpt(tokens, first, prev)));
    if (inDeclaration && P::isNameToken(found->getType()))
        d.note(fmt::format("the declaration of '{}' on the next line is skipped until the ';' is there", found->getText()));
    return true;
}

bool FriendlyErrorStrategy::reportUnclosedBlock(antlr4::Parser* parser, antlr4::Token* found,
                                                const antlr4::misc::IntervalSet& expected) {
    if (found == nullptr) return false;
    const std::string foundName = found->getType() == antlr4::Token::EOF ? "" : parser->getVocabulary().getSymbolicName(found->getType());
    // Only when the text goes on with what closes an outer construct (or ends).
    if (found->getType() != antlr4::Token::EOF && foundName.rfind("END_", 0) != 0) return false;
    // ... and only when that END_ closes a construct that is open further out:
    // a stray END_FOR after a broken FOR header is not a missing END_PROGRAM.
    bool closesOuter = found->getType() == antlr4::Token::EOF;
    for (antlr4::ParserRuleContext* c = parser->getContext(); c != nullptr && !closesOuter; c = dynamic_cast<antlr4::ParserRuleContext*>(c->parent))
        closesOuter = closingKeyword(c) == found->getType();
    if (!closesOuter) return false;
    for (antlr4::ParserRuleContext* c = parser->getContext(); c != nullptr; c = dynamic_cast<antlr4::ParserRuleContext*>(c->parent)) {
        const size_t closer = closingKeyword(c);
        if (closer == 0) continue;
        if (!expected.contains(closer) || closer == found->getType()) return false;
        antlr4::Token* opener = c->getStart();
        if (opener == nullptr) return false;
        const std::string closerName = parser->getVocabulary().getSymbolicName(closer);
        Diagnostic& d = reporter_->report(diag::E0003, opener->getLine(), opener->getCharPositionInLine(),
                                          fmt::format("'{}' has no matching '{}'", opener->getText(), closerName));
        d.note(Loc{reporter_->fileIndex(), static_cast<int>(found->getLine()), static_cast<int>(found->getCharPositionInLine()) + 1},
               fmt::format("'{}' expected before {}", closerName, describeFoundToken(found)));
        if (found->getType() == L::END_CASE) {
            // The enclosing CASE's next labels (`2:`) were read inside the open
            // block, where they cannot be labels: the same mistake, not news.
            antlr4::TokenStream* tokens = parser->getTokenStream();
            for (size_t i = opener->getTokenIndex(); i < found->getTokenIndex(); ++i)
                if (tokens->get(i)->getType() == L::COLON) reporter_->markLine(tokens->get(i)->getLine());
        }
        if (closer == L::END_IF) {
            // `ELSE IF` opens an IF of its own inside the ELSE branch.
            antlr4::TokenStream* tokens = parser->getTokenStream();
            antlr4::Token* before = nullptr;
            for (size_t i = opener->getTokenIndex(); i < found->getTokenIndex(); ++i) {
                antlr4::Token* t = tokens->get(i);
                if (t->getChannel() != antlr4::Token::DEFAULT_CHANNEL) continue;
                if (before && before->getType() == L::ELSE && t->getType() == L::IF) {
                    d.withHelp("'ELSE IF' starts a new IF that needs its own END_IF; write 'ELSIF' instead");
                    break;
                }
                before = t;
            }
        }
        return true;
    }
    return false;
}

void FriendlyErrorStrategy::reportAt(antlr4::Parser* parser, antlr4::Token* found, const antlr4::misc::IntervalSet& expected) {
    if (reporter_ != nullptr && (reportMistypedKeyword(parser, found) || reportUnclosedVarBlock(parser, found) ||
                                 reportMissingSemicolon(parser, found, expected) || reportUnclosedBlock(parser, found, expected)))
        return;
    // `IF x := 1 THEN`: the C habit of assigning in a condition, or '=' mistyped.
    if (reporter_ != nullptr && found != nullptr && found->getType() == L::ASSIGN &&
        (expected.contains(static_cast<size_t>(L::THEN)) || expected.contains(static_cast<size_t>(L::DO)))) {
        reporter_->report(diag::E0004, found->getLine(), found->getCharPositionInLine(),
                          "':=' in a condition: a condition compares, it does not assign")
            .withHelp("compare with '=': IF x = 1 THEN");
        // Recovery drops the statement, so its END_IF / END_WHILE comes unexpected: the same mistake.
        orphanCloser_ = expected.contains(static_cast<size_t>(L::THEN)) ? L::END_IF : L::END_WHILE;
        return;
    }
    // `FOR x = 1 TO 10 DO`: recovery drops the FOR, so its END_FOR comes unexpected: the same mistake.
    if (found != nullptr && found->getType() == L::EQ && expected.contains(static_cast<size_t>(L::ASSIGN)) &&
        dynamic_cast<P::ForStmtContext*>(parser->getContext()) != nullptr)
        orphanCloser_ = L::END_FOR;
    if (found != nullptr && orphanCloser_ != 0 && found->getType() == orphanCloser_) {
        orphanCloser_ = 0;
        return;
    }
    // `1 y := 2` (a CASE label without its ':'): the word after the
    // expression was taken for the S of `x S= y`, and '=' is missing after
    // it. The mistake is the word itself.
    if (auto* statement = dynamic_cast<P::ExprStmtContext*>(parser->getContext());
        statement != nullptr && statement->setOperator != nullptr && statement->eq == nullptr &&
        expected.contains(static_cast<size_t>(L::EQ)) && statement->setOperator->getStart() != nullptr) {
        antlr4::Token* word = statement->setOperator->getStart();
        parser->notifyErrorListeners(word, "unexpected " + describeFoundToken(word) + ", expected ':=', ';' or ':'", nullptr);
        return;
    }
    diag::Code code = diag::E0001;
    std::string text = message(parser, found, expected, &code);
    if (reporter_ != nullptr) reporter_->codeOfNext(code);
    parser->notifyErrorListeners(found, text, nullptr);
}

void FriendlyErrorStrategy::reportNoViableAlternative(antlr4::Parser* parser, const antlr4::NoViableAltException& e) {
    reportAt(parser, e.getOffendingToken(), e.getExpectedTokens());
}

void FriendlyErrorStrategy::reportInputMismatch(antlr4::Parser* parser, const antlr4::InputMismatchException& e) {
    reportAt(parser, e.getOffendingToken(), e.getExpectedTokens());
}

void FriendlyErrorStrategy::reportFailedPredicate(antlr4::Parser* parser, const antlr4::FailedPredicateException& e) {
    parser->notifyErrorListeners(e.getOffendingToken(), "unexpected " + describeFoundToken(e.getOffendingToken()),
                                 std::make_exception_ptr(e));
}

void FriendlyErrorStrategy::reportUnwantedToken(antlr4::Parser* parser) {
    if (inErrorRecoveryMode(parser)) return;
    beginErrorCondition(parser);
    reportAt(parser, parser->getCurrentToken(), getExpectedTokens(parser));
}

void FriendlyErrorStrategy::reportMissingToken(antlr4::Parser* parser) {
    if (inErrorRecoveryMode(parser)) return;
    beginErrorCondition(parser);
    reportAt(parser, parser->getCurrentToken(), getExpectedTokens(parser));
}

antlr4::Token* FriendlyErrorStrategy::singleTokenDeletion(antlr4::Parser* parser) {
    const size_t type = parser->getTokenStream()->LA(1);
    if (type == L::SEMI || isStructuralKeyword(parser->getVocabulary().getSymbolicName(type))) return nullptr;
    // `x := a` + newline + `y := 1;` (a missing ';'): dropping `y` would make a
    // chained assignment `x := a := 1` (decision 0203) and a phantom error.
    if (parser->getTokenStream()->LA(2) == L::ASSIGN) return nullptr;
    return DefaultErrorStrategy::singleTokenDeletion(parser);
}

void SyntaxErrorReporter::syntaxError(antlr4::Recognizer*, antlr4::Token*, size_t line, size_t charPositionInLine,
                                      const std::string& msg, std::exception_ptr) {
    const diag::Code code = nextCode_;
    nextCode_ = diag::E0001;
    report(code, line, charPositionInLine, msg);
}

Diagnostic& SyntaxErrorReporter::report(diag::Code code, size_t line, size_t charPositionInLine, const std::string& msg, bool always) {
    scratch_ = Diagnostic{};
    if (silenced_ && !always) return scratch_;
    if (!linesWithError_.insert(line).second && !always) return scratch_;
    if (reported_ > kMaxErrorsPerFile) return scratch_;
    if (reported_++ == kMaxErrorsPerFile) {
        log_.error(diag::E0007, Loc{fileIndex_, static_cast<int>(line), static_cast<int>(charPositionInLine) + 1},
                   "syntax error: too many errors in this file, the rest are not reported");
        return scratch_;
    }
    return log_.error(code, Loc{fileIndex_, static_cast<int>(line), static_cast<int>(charPositionInLine) + 1},
                      "syntax error: " + msg);
}

}  // namespace strun::ast
