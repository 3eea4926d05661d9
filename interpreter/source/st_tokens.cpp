// ST tokens for the reading stages before the parser (st_tokens.h).
#include "interpreter/source/st_tokens.h"

#include <algorithm>
#include <cctype>

#include "stdlib/number_scan.h"

namespace strun::source {

// Words, strings, numbers and symbols, without comments, pragmas and blanks.
std::vector<StToken> tokenizeSt(const std::string& s) {
    std::vector<StToken> out;
    size_t i = 0;
    int line = 1;
    size_t lineStart = 0;
    auto advance = [&](size_t to) {
        for (; i < to && i < s.size(); ++i)
            if (s[i] == '\n') {
                ++line;
                lineStart = i + 1;
            }
    };
    while (i < s.size()) {
        const char c = s[i];
        if (std::isspace(static_cast<unsigned char>(c))) { advance(i + 1); continue; }
        if (s.compare(i, 2, "(*") == 0) { size_t e = s.find("*)", i + 2); advance(e == std::string::npos ? s.size() : e + 2); continue; }
        if (s.compare(i, 2, "/*") == 0) { size_t e = s.find("*/", i + 2); advance(e == std::string::npos ? s.size() : e + 2); continue; }
        if (s.compare(i, 2, "//") == 0) { size_t e = s.find('\n', i); advance(e == std::string::npos ? s.size() : e); continue; }
        if (c == '{') { size_t e = s.find('}', i); advance(e == std::string::npos ? s.size() : e + 1); continue; }
        StToken t;
        t.begin = i;
        t.line = line;
        t.col = static_cast<int>(i - lineStart) + 1;
        size_t e = i + 1;
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            while (e < s.size() && (std::isalnum(static_cast<unsigned char>(s[e])) || s[e] == '_')) ++e;
            // typed literals and times (T#5s, INT#3) are one token
            if (e < s.size() && s[e] == '#') {
                ++e;
                while (e < s.size() && (std::isalnum(static_cast<unsigned char>(s[e])) || s[e] == '_' || s[e] == '.' || s[e] == ':' || s[e] == '-')) ++e;
            } else {
                t.word = true;
            }
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            while (e < s.size() && (std::isalnum(static_cast<unsigned char>(s[e])) || s[e] == '_' || s[e] == '.' || s[e] == '#')) ++e;
        } else if (c == '\'' || c == '"') {
            while (e < s.size() && s[e] != c) e += s[e] == '$' ? 2 : 1;
            e = std::min(e + 1, s.size());
        } else if (s.compare(i, 2, ":=") == 0 || s.compare(i, 2, "=>") == 0 || s.compare(i, 2, "<=") == 0 || s.compare(i, 2, ">=") == 0 ||
                   s.compare(i, 2, "<>") == 0 || s.compare(i, 2, "**") == 0) {
            e = i + 2;
        }
        t.text = s.substr(i, e - i);
        t.up = stdlib::upperAscii(t.text);
        t.end = e;
        out.push_back(std::move(t));
        advance(e);
    }
    return out;
}

void declaredVariables(const std::vector<StToken>& toks, size_t b, size_t e, bool globalsOnly, std::map<std::string, std::string>& into) {
    e = std::min(e, toks.size());
    auto isVar = [](const std::string& up) { return up.rfind("VAR", 0) == 0; };
    for (size_t k = b; k < e; ++k) {
        if (!isVar(toks[k].up) || (globalsOnly && toks[k].up != "VAR_GLOBAL")) continue;
        std::vector<std::string> names;
        for (++k; k < e && toks[k].up != "END_VAR"; ++k) {
            const bool nameHere = toks[k].word && k + 1 < e && (toks[k + 1].text == ":" || toks[k + 1].text == ",");
            if (nameHere) names.push_back(toks[k].up);
            if (toks[k].text == ":" && !names.empty() && k + 1 < e) {
                for (const std::string& n : names) into[n] = toks[k + 1].up;
                names.clear();
            }
            if (toks[k].text == ";") names.clear();
        }
    }
}

}  // namespace strun::source
