// Two forms SIMATIC AX and TwinCAT code writes, settled on the token list
// before parsing so that the grammar stays LL(1) (decisions 0158, 0210):
//
// - `OVERRIDE` is a method modifier (`METHOD PUBLIC OVERRIDE M : BOOL`,
//   IEC 61131-3 Ed.3) but also a common variable name (a speed override).
//   The scanner makes it IDENTIFIER; this step makes it OVERRIDE where it
//   stands among a METHOD's or PROPERTY's modifiers, before its name. A
//   method's name `Action` after modifiers is a name, not an ACTION.
// - A `;` right after `END_VAR` (`END_VAR;`) or right after a pragma that
//   stands where a declaration may start (`{attribute 'x'};` in a VAR block)
//   changes nothing: it goes to the hidden channel, so the parser never sees
//   it. So does a `;` right after another `;` inside a VAR block or a STRUCT
//   (`x : INT;;`, an empty declaration): its index goes to
//   `emptyDeclarations` for a warning (decision 0276). A `;` anywhere else is
//   left as it is.
#pragma once

#include <string_view>
#include <vector>

#include "interpreter/ast/st_scanner.h"

namespace strun::ast {

void resolveAxTwinCatForms(std::string_view text, std::vector<ScannedToken>& tokens,
                           std::vector<std::size_t>* emptyDeclarations = nullptr);

}  // namespace strun::ast
