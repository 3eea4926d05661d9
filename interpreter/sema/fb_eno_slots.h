// The ENO of a function-block instance that its POU reads or calls with
// EN/ENO (decision 0358): IEC 61131-3 gives every block an ENO, readable as
// `inst.ENO` after a call `inst(EN := x, ...)`. strun's blocks have none in
// their layout (a block never called so pays nothing), so a POU that uses
// the ENO of one of its own instances gets a hidden BOOL for it, declared
// before the POU is laid out and written by every call of the instance.
#pragma once

#include <string>

#include "interpreter/ast/ast.h"

namespace strun::sema {

// The hidden variable that holds the ENO of the instance `instance` (as
// written): a name no source can write.
std::string enoSlotName(const std::string& instance);

// Adds to `pou` (a PROGRAM or FUNCTION_BLOCK) a hidden BOOL `enoSlotName(X)`
// for every instance X declared in its own VAR blocks that its body calls
// with EN or ENO or reads as `X.ENO`.
void addFbEnoSlots(ast::Pou& pou);

// The same for the instances of the global lists: a hidden global BOOL
// `enoSlotName(X)` beside every global block instance X that some POU body
// (or method, action) calls with EN or ENO or reads as `X.ENO`; such a
// call in any POU writes it (decision 0370).
void addGlobalFbEnoSlots(std::vector<ast::CompilationUnit>& units);

}  // namespace strun::sema
