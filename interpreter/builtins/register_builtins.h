// Registers every standard-library function implemented in C++ with the
// checker (the ST-written blocks come from stdlib/st/*.st).
#pragma once

namespace strun::sema { class Checker; }

namespace strun::stdlib {

void registerBuiltins(sema::Checker& checker);

}  // namespace strun::stdlib
