#include "interpreter/ast/ax_twincat_tokens.h"

#include <antlr4-runtime.h>

#include "grammar/STLexer.h"
#include "stdlib/number_scan.h"

namespace strun::ast {

namespace {

using L = strun_grammar::STLexer;

bool isModifier(std::size_t type) {
    switch (type) {
        case L::PUBLIC: case L::PRIVATE: case L::PROTECTED: case L::INTERNAL: case L::ABSTRACT: case L::FINAL:
        case L::OVERRIDE:
            return true;
        default:
            return false;
    }
}

// Tokens after which a declaration (or the next VAR block, or the next POU)
// may start: a `;` after a pragma that follows one of them ends nothing.
bool startsDeclarations(std::size_t type) {
    switch (type) {
        case L::SEMI: case L::END_VAR: case L::VAR: case L::VAR_INPUT: case L::VAR_OUTPUT: case L::VAR_IN_OUT:
        case L::VAR_TEMP: case L::VAR_STAT: case L::VAR_GENERIC: case L::VAR_INST: case L::VAR_GLOBAL: case L::VAR_EXTERNAL:
        case L::VAR_CONFIG: case L::VAR_ACCESS: case L::CONSTANT: case L::RETAIN: case L::NON_RETAIN:
        case L::PERSISTENT: case L::STRUCT: case L::END_STRUCT: case L::END_TYPE: case L::END_PROGRAM:
        case L::END_FUNCTION: case L::END_FUNCTION_BLOCK: case L::END_METHOD: case L::END_PROPERTY:
        case L::END_INTERFACE: case L::END_CLASS: case L::END_ACTION: case L::END_NAMESPACE:
            return true;
        default:
            return false;
    }
}

// Tokens that open a block of declarations ended by END_VAR or END_STRUCT.
bool opensDeclarations(std::size_t type) {
    switch (type) {
        case L::VAR: case L::VAR_INPUT: case L::VAR_OUTPUT: case L::VAR_IN_OUT: case L::VAR_TEMP: case L::VAR_STAT: case L::VAR_GENERIC:
        case L::VAR_INST: case L::VAR_GLOBAL: case L::VAR_EXTERNAL: case L::VAR_CONFIG: case L::VAR_ACCESS: case L::STRUCT:
            return true;
        default:
            return false;
    }
}

}  // namespace

void resolveAxTwinCatForms(std::string_view text, std::vector<ScannedToken>& tokens, std::vector<std::size_t>* emptyDeclarations) {
    const std::size_t none = tokens.size();
    std::size_t lastDefault = none;  // index of the last default-channel token seen
    bool inDeclarations = false;     // inside a VAR ... END_VAR block or STRUCT ... END_STRUCT
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
        ScannedToken& token = tokens[i];
        if (token.channel != antlr4::Token::DEFAULT_CHANNEL) continue;
        const std::size_t before = lastDefault == none ? 0 : tokens[lastDefault].type;
        if (opensDeclarations(token.type)) inDeclarations = true;
        else if (token.type == L::END_VAR || token.type == L::END_STRUCT) inDeclarations = false;
        if (token.type == L::IDENTIFIER && (before == L::METHOD || before == L::PROPERTY || isModifier(before)) &&
            stdlib::equalsIgnoreCase(text.substr(token.start, token.stop + 1 - token.start), "OVERRIDE")) {
            // A modifier only when a name (or another modifier) follows:
            // `METHOD Override : BOOL` declares a method named Override.
            std::size_t j = i + 1;
            while (j + 1 < tokens.size() && tokens[j].channel != antlr4::Token::DEFAULT_CHANNEL) ++j;
            const std::size_t after = tokens[j].type;
            if (after == L::IDENTIFIER || after == L::ACTION || isModifier(after)) token.type = L::OVERRIDE;
        } else if (token.type == L::ACTION && (before == L::METHOD || before == L::PROPERTY || isModifier(before))) {
            token.type = L::IDENTIFIER;  // `METHOD PUBLIC OVERRIDE Action` names a method Action
        } else if (token.type == L::SEMI) {
            const bool afterEndVar = before == L::END_VAR && lastDefault + 1 == i;
            const bool afterPragma = i > 0 && tokens[i - 1].type == L::PRAGMA &&
                                     (lastDefault == none || startsDeclarations(before));
            if (afterEndVar || afterPragma) {
                token.channel = antlr4::Token::HIDDEN_CHANNEL;
                continue;  // the hidden `;` is not the last token seen
            }
            if (inDeclarations && before == L::SEMI) {
                token.channel = antlr4::Token::HIDDEN_CHANNEL;
                if (emptyDeclarations) emptyDeclarations->push_back(i);
                continue;
            }
        }
        lastDefault = i;
    }
}

}  // namespace strun::ast
