#include "interpreter/ast/edge_keyword.h"

#include <cstring>

#include <antlr4-runtime.h>

#include "grammar/STLexer.h"
#include "stdlib/number_scan.h"

namespace strun::ast {

namespace {

using L = strun_grammar::STLexer;

std::string_view textOf(std::string_view text, const ScannedToken& t) { return text.substr(t.start, t.stop + 1 - t.start); }

// Whether `_EDGE` (any case) occurs in the text at all: most sources have no
// R_EDGE / F_EDGE, and memchr over the text is far cheaper than a walk over
// its tokens.
bool mentionsEdge(std::string_view text) {
    const char* p = text.data();
    const char* end = p + text.size();
    while (end - p >= 5) {
        const void* hit = std::memchr(p, '_', static_cast<size_t>(end - p - 4));
        if (!hit) return false;
        p = static_cast<const char*>(hit) + 1;
        if ((p[0] | 0x20) == 'e' && (p[1] | 0x20) == 'd' && (p[2] | 0x20) == 'g' && (p[3] | 0x20) == 'e') return true;
    }
    return false;
}

}  // namespace

void resolveEdgeKeyword(std::string_view text, std::vector<ScannedToken>& tokens) {
    if (!mentionsEdge(text)) return;
    // `: TYPE R_EDGE ;` (or `:=`, END_VAR): the two default-channel tokens
    // before each six-letter IDENTIFIER, and the one after it.
    std::size_t before = tokens.size(), beforeThat = tokens.size();
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        ScannedToken& t = tokens[i];
        if (t.channel != antlr4::Token::DEFAULT_CHANNEL) continue;
        if (t.type == L::IDENTIFIER && t.stop + 1 - t.start == 6 && beforeThat < tokens.size() &&
            tokens[beforeThat].type == L::COLON && tokens[before].type == L::IDENTIFIER) {
            std::size_t next = i + 1;
            while (next + 1 < tokens.size() && tokens[next].channel != antlr4::Token::DEFAULT_CHANNEL) ++next;
            const std::size_t after = next < tokens.size() ? tokens[next].type : 0;
            if (after == L::SEMI || after == L::ASSIGN || after == L::END_VAR) {
                const std::string word = stdlib::upperAscii(textOf(text, t));
                if (word == "R_EDGE") t.type = L::R_EDGE;
                if (word == "F_EDGE") t.type = L::F_EDGE;
            }
        }
        beforeThat = before;
        before = i;
    }
}

}  // namespace strun::ast
