#include "interpreter/ast/nesting_guard.h"

#include <fmt/format.h>

#include "grammar/STLexer.h"

namespace strun::ast {

namespace {

using L = strun_grammar::STLexer;

bool opensBlock(size_t type) {
    switch (type) {
        case L::IF: case L::CASE: case L::FOR: case L::WHILE: case L::REPEAT:
        case L::STRUCT: case L::NAMESPACE:
            return true;
        default:
            return false;
    }
}

bool closesBlock(size_t type) {
    switch (type) {
        case L::END_IF: case L::END_CASE: case L::END_FOR: case L::END_WHILE: case L::END_REPEAT:
        case L::END_STRUCT: case L::END_NAMESPACE:
            return true;
        default:
            return false;
    }
}

bool isPrefixOperator(size_t type) { return type == L::NOT || type == L::MINUS || type == L::PLUS; }

bool isTypeConstructor(size_t type) { return type == L::ARRAY || type == L::POINTER || type == L::REFERENCE; }

bool endsTypeSpec(size_t type) {
    return type == L::SEMI || type == L::ASSIGN || type == L::END_VAR || type == L::END_STRUCT ||
           type == L::END_TYPE;
}

}  // namespace

std::optional<NestingViolation> findExcessiveNesting(const std::vector<ScannedToken>& tokens) {
    int brackets = 0;     // ( and [
    int blocks = 0;       // IF .. END_IF and friends
    int prefixRun = 0;    // consecutive NOT / - / +
    int typeRun = 0;      // ARRAY / POINTER TO / REFERENCE TO within one type
    for (size_t index = 0; index < tokens.size(); ++index) {
        if (tokens[index].channel != antlr4::Token::DEFAULT_CHANNEL) continue;
        const size_t type = tokens[index].type;
        if (type == L::LPAREN || type == L::LBRACK) ++brackets;
        else if ((type == L::RPAREN || type == L::RBRACK) && brackets > 0) --brackets;
        else if (opensBlock(type)) ++blocks;
        else if (closesBlock(type) && blocks > 0) --blocks;

        prefixRun = isPrefixOperator(type) ? prefixRun + 1 : 0;
        if (isTypeConstructor(type)) ++typeRun;
        else if (endsTypeSpec(type)) typeRun = 0;

        if (brackets + blocks > kMaxNestingDepth || prefixRun > kMaxNestingDepth || typeRun > kMaxNestingDepth)
            return NestingViolation{
                index, fmt::format("nesting too deep: more than {} nested levels (parentheses, brackets, "
                                   "statements, operators or types)",
                                   kMaxNestingDepth)};
    }
    return std::nullopt;
}

}  // namespace strun::ast
