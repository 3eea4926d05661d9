// `ACTION Name: ... END_ACTION` declares a CODESYS action in strun's text
// form, and `action` is also a name programs use (`action := 3;`,
// `fb.action()`). The scanner makes every such word an ACTION token; this
// step keeps ACTION only where an action declaration starts and makes the
// others IDENTIFIER, so that the grammar has ACTION as a plain keyword and
// every statement list decides from one token (decision 0159).
#pragma once

#include <vector>

#include "interpreter/ast/st_scanner.h"

namespace strun::ast {

// An ACTION stays ACTION when the next token is a name (the action's) and
// the token after that is not '=' (`action S= x;` sets `action`), unless
// the words are `action WITH name;` (an FB bound to a task) or
// `action READ_ONLY;` / `action READ_WRITE;` (the type of an access path).
void resolveActionKeyword(std::vector<ScannedToken>& tokens);

}  // namespace strun::ast
