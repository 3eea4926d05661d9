// Registers every standard-library function implemented in C++ with the
// checker (the ST-written blocks come from stdlib/st/*.st).
#pragma once

#include <string_view>
#include <vector>

namespace strun::sema { class Checker; }

namespace strun::stdlib {

// Registers the functions; compileProject runs it on the checker's first
// look-up of a built-in name (decision 0478).
void registerBuiltins(sema::Checker& checker);
// The CODESYS names of the bistables' and counters' inputs (SR.SET1,
// CTU.RESET): not functions, so registered before checking, not with them.
void registerParameterAliases(sema::Checker& checker);
// The native functions of the named vendor libraries (library_natives.h).
void registerLibraryBuiltins(sema::Checker& checker, const std::vector<std::string_view>& libraries);

}  // namespace strun::stdlib
