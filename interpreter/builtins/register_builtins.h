// Registers every standard-library function implemented in C++ with the
// checker (the ST-written blocks come from stdlib/st/*.st).
#pragma once

#include <string_view>
#include <vector>

namespace strun::sema { class Checker; }

namespace strun::stdlib {

void registerBuiltins(sema::Checker& checker);
// The native functions of the named vendor libraries (library_natives.h).
void registerLibraryBuiltins(sema::Checker& checker, const std::vector<std::string_view>& libraries);

}  // namespace strun::stdlib
