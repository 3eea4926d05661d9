// The words, literals and symbols of ST text, without comments, pragmas and
// blanks, each with its place: what the reading stages that rewrite parts of
// an ST file before the parser sees it (textual SFC, textual IL) look at.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace strun::source {

struct StToken {
    std::string text, up;  // as written; upper case
    size_t begin = 0, end = 0;
    int line = 1, col = 1;
    bool word = false;  // an identifier or keyword (not a typed literal such as T#5s)
};

std::vector<StToken> tokenizeSt(const std::string& text);

// The variables declared in the VAR sections among tokens [b, e) (only the
// VAR_GLOBAL ones when `globalsOnly`): upper-case name -> upper-case type word.
void declaredVariables(const std::vector<StToken>& toks, size_t b, size_t e, bool globalsOnly, std::map<std::string, std::string>& into);

}  // namespace strun::source
