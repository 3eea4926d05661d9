#include "stdlib/bind/register_builtins.h"

#include "interpreter/sema/checker.h"

namespace strun::stdlib {

void registerBuiltins(sema::Checker& checker) {
    (void)checker;
}

}  // namespace strun::stdlib
