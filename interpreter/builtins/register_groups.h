// The registration entry of each group of built-in functions (one .cpp each);
// registerBuiltins (register_builtins.cpp) calls them all.
#pragma once

namespace strun::sema { class Checker; }

namespace strun::stdlib::bind {

void registerNumeric(sema::Checker& ck);   // ABS SQRT ... EXPT, ADD ... MOVE, SHL ... ROR, AND OR XOR NOT
void registerSelect(sema::Checker& ck);    // SEL MAX MIN LIMIT MUX, GT GE EQ LE LT NE
void registerStrings(sema::Checker& ck);   // LEN LEFT RIGHT MID CONCAT INSERT DELETE REPLACE FIND
void registerConvert(sema::Checker& ck);   // *_TO_STRING, STRING_TO_*, BCD, endianness, IS_VALID
void registerTime(sema::Checker& ck);      // ADD_TIME ... DAY_OF_WEEK
void registerClock(sema::Checker& ck);     // the PLC clock read by the ST timer blocks, TIME()
void registerMemory(sema::Checker& ck);    // MEMCPY MEMMOVE MEMSET MEMCMP (bounds-checked against the memory map)
void registerTaskCycle(sema::Checker& ck); // GetCurrentTaskCycle, SetCurrentTaskCycle (--target m241)

}  // namespace strun::stdlib::bind
