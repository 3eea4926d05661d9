#include "stdlib/bind/register_builtins.h"

#include "interpreter/sema/checker.h"
#include "stdlib/bind/register_groups.h"

namespace strun::stdlib {

void registerBuiltins(sema::Checker& checker) {
    bind::registerNumeric(checker);
    bind::registerSelect(checker);
    bind::registerStrings(checker);
    bind::registerConvert(checker);
    bind::registerTime(checker);
    bind::registerClock(checker);
}

}  // namespace strun::stdlib
