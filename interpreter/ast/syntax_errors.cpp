#include "interpreter/ast/syntax_errors.h"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "grammar/STLexer.h"
#include "grammar/STParser.h"

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
        case P::RuleExpression: case P::RulePostfixExpr: case P::RulePrimary: case P::RuleLiteral:
        case P::RuleCaseLabel: case P::RuleExpressionList: case P::RuleArrayRange:
            return "an expression";
        case P::RuleStatement: case P::RuleStmtList: case P::RuleCaseBody: case P::RuleCaseStatement:
            return "a statement";
        case P::RuleTypeSpec:
            return "a type";
        case P::RuleVarDecl: case P::RuleVarName: case P::RuleVarBlock:
            return "a variable declaration";
        case P::RuleCompilationUnit: case P::RuleTopLevelItem: case P::RuleNamespaceDecl:
            return "a declaration (PROGRAM, FUNCTION, FUNCTION_BLOCK, INTERFACE, TYPE, VAR_GLOBAL, CONFIGURATION)";
        case P::RuleInitializer: case P::RuleArrayInitItem: case P::RuleStructInitItem:
            return "an initial value";
        case P::RuleArgList: case P::RuleArg:
            return "an argument";
        case P::RulePostfixOp: case P::RuleMemberName:
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
                                           const antlr4::misc::IntervalSet& expected) {
    const auto& vocabulary = parser->getVocabulary();
    std::vector<std::string> names;
    std::vector<std::string> structural;
    // ACTION is also a name: it reads as 'ACTION' only where no identifier could stand.
    const bool nameExpected = expected.contains(static_cast<size_t>(L::IDENTIFIER));
    for (size_t type : expected.toList()) {
        std::string name = type == L::ACTION && !nameExpected ? "'ACTION'" : describeTokenType(type, vocabulary);
        if (std::find(names.begin(), names.end(), name) != names.end()) continue;
        names.push_back(name);
        if (type != antlr4::Token::EOF && isStructuralKeyword(vocabulary.getSymbolicName(type)))
            structural.push_back(name);
    }
    std::string text = "unexpected " + describeFoundToken(found);
    if (!names.empty() && names.size() <= 4) return text + ", expected " + joinAlternatives(names);

    std::vector<std::string> hint;
    antlr4::ParserRuleContext* context = parser->getContext();
    if (context != nullptr) {
        const std::string phrase = phraseForRule(context->getRuleIndex());
        if (!phrase.empty()) hint.push_back(phrase);
    }
    if (structural.size() <= 3)
        hint.insert(hint.end(), structural.begin(), structural.end());
    if (hint.empty()) return text;
    return text + ", expected " + joinAlternatives(hint);
}

void FriendlyErrorStrategy::reportNoViableAlternative(antlr4::Parser* parser, const antlr4::NoViableAltException& e) {
    parser->notifyErrorListeners(e.getOffendingToken(), message(parser, e.getOffendingToken(), e.getExpectedTokens()),
                                 std::make_exception_ptr(e));
}

void FriendlyErrorStrategy::reportInputMismatch(antlr4::Parser* parser, const antlr4::InputMismatchException& e) {
    parser->notifyErrorListeners(e.getOffendingToken(), message(parser, e.getOffendingToken(), e.getExpectedTokens()),
                                 std::make_exception_ptr(e));
}

void FriendlyErrorStrategy::reportFailedPredicate(antlr4::Parser* parser, const antlr4::FailedPredicateException& e) {
    parser->notifyErrorListeners(e.getOffendingToken(), "unexpected " + describeFoundToken(e.getOffendingToken()),
                                 std::make_exception_ptr(e));
}

void FriendlyErrorStrategy::reportUnwantedToken(antlr4::Parser* parser) {
    if (inErrorRecoveryMode(parser)) return;
    beginErrorCondition(parser);
    antlr4::Token* found = parser->getCurrentToken();
    parser->notifyErrorListeners(found, message(parser, found, getExpectedTokens(parser)), nullptr);
}

void FriendlyErrorStrategy::reportMissingToken(antlr4::Parser* parser) {
    if (inErrorRecoveryMode(parser)) return;
    beginErrorCondition(parser);
    antlr4::Token* found = parser->getCurrentToken();
    parser->notifyErrorListeners(found, message(parser, found, getExpectedTokens(parser)), nullptr);
}

antlr4::Token* FriendlyErrorStrategy::singleTokenDeletion(antlr4::Parser* parser) {
    const size_t type = parser->getTokenStream()->LA(1);
    if (type == L::SEMI || isStructuralKeyword(parser->getVocabulary().getSymbolicName(type))) return nullptr;
    return DefaultErrorStrategy::singleTokenDeletion(parser);
}

void SyntaxErrorReporter::syntaxError(antlr4::Recognizer*, antlr4::Token*, size_t line, size_t charPositionInLine,
                                      const std::string& msg, std::exception_ptr) {
    report(line, charPositionInLine, msg);
}

void SyntaxErrorReporter::report(size_t line, size_t charPositionInLine, const std::string& msg, bool always) {
    if (!linesWithError_.insert(line).second && !always) return;
    if (reported_ > kMaxErrorsPerFile) return;
    if (reported_++ == kMaxErrorsPerFile) {
        log_.error(Loc{fileIndex_, static_cast<int>(line), static_cast<int>(charPositionInLine) + 1},
                   "syntax error: too many errors in this file, the rest are not reported");
        return;
    }
    log_.error(Loc{fileIndex_, static_cast<int>(line), static_cast<int>(charPositionInLine) + 1},
               "syntax error: " + msg);
}

}  // namespace strun::ast
