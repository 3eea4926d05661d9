#include "interpreter/builtins/register_builtins.h"

#include <string>

#include "interpreter/builtins/register_groups.h"
#include "interpreter/sema/checker.h"

namespace strun::stdlib {

void registerBuiltins(sema::Checker& checker) {
    bind::registerNumeric(checker);
    bind::registerSelect(checker);
    bind::registerStrings(checker);
    bind::registerConvert(checker);
    bind::registerTime(checker);
    bind::registerClock(checker);
    bind::registerTaskCycle(checker);
    bind::registerMemory(checker);
}

// The bistables and counters answer to both the IEC 61131-3 input names
// (SR.S1, RS.R1, CTU.R, CTD.LD) and the CODESYS ones (SR.SET1, RS.RESET1,
// CTU.RESET, CTD.LOAD); stdlib/st declares the names in the first column.
void registerParameterAliases(sema::Checker& checker) {
    checker.addParameterAlias("SR", "S1", "SET1");
    checker.addParameterAlias("SR", "R", "RESET");
    checker.addParameterAlias("RS", "S", "SET");
    checker.addParameterAlias("RS", "R1", "RESET1");
    for (const char* suffix : {"", "_INT", "_DINT", "_LINT", "_UDINT", "_ULINT"}) {
        std::string s = suffix;
        checker.addParameterAlias("CTU" + s, "RESET", "R");
        checker.addParameterAlias("CTD" + s, "LOAD", "LD");
        checker.addParameterAlias("CTUD" + s, "RESET", "R");
        checker.addParameterAlias("CTUD" + s, "LOAD", "LD");
    }
}

}  // namespace strun::stdlib
