#include "interpreter/ast/action_keyword.h"

#include <antlr4-runtime.h>

#include "grammar/STLexer.h"

namespace strun::ast {

namespace {

using L = strun_grammar::STLexer;

bool isNameWord(std::size_t type) {
    switch (type) {
        case L::IDENTIFIER: case L::GET: case L::SET: case L::TASK: case L::ON: case L::WITH:
        case L::READ_ONLY: case L::READ_WRITE: case L::ACTION:
            return true;
        default:
            return false;
    }
}

}  // namespace

void resolveActionKeyword(std::vector<ScannedToken>& tokens) {
    // The next default-channel token after position i (the last token is EOF).
    auto next = [&](std::size_t i) {
        do ++i;
        while (i + 1 < tokens.size() && tokens[i].channel != antlr4::Token::DEFAULT_CHANNEL);
        return i < tokens.size() ? i : tokens.size() - 1;
    };
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
        ScannedToken& token = tokens[i];
        if (token.type != L::ACTION || token.channel != antlr4::Token::DEFAULT_CHANNEL) continue;
        const std::size_t name = next(i);
        const std::size_t after = next(name);
        const std::size_t nameType = tokens[name].type;
        const std::size_t afterType = tokens[after].type;
        const bool bindsToTask = nameType == L::WITH && isNameWord(afterType) && tokens[next(after)].type == L::SEMI;
        const bool accessMode = (nameType == L::READ_ONLY || nameType == L::READ_WRITE) && afterType == L::SEMI;
        const bool declares = isNameWord(nameType) && afterType != L::EQ && !bindsToTask && !accessMode;
        if (!declares) token.type = L::IDENTIFIER;
    }
}

}  // namespace strun::ast
