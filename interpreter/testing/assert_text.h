// Values as TcUnit prints them in a failed assertion's EXP/ACT (the formats
// of TcUnit's FB_TestSuite assert methods): BOOL as TRUE/FALSE, integers in
// decimal, bit strings as 0x and the type's width in upper-case hex digits,
// REAL/LREAL and durations/dates as their *_TO_STRING text, strings as they
// are. docs/testing.md lists them; decision 0140 the choices strun made.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "interpreter/sema/types.h"

namespace strun::testing {

// The text of the value of elementary type `t` stored at `p`.
std::string assertText(const sema::Type* t, const uint8_t* p);

// TcUnit's name of a type's class in a generic AssertEquals type mismatch
// ("INT", "DATEANDTIME", "USERDEF", "ARRAY", ...).
std::string typeClassName(const sema::Type* t);

// "0x" and up to the first 39 bytes in upper-case hex (generic AssertEquals of
// a structured value, as TcUnit prints it).
std::string hexBytes(const uint8_t* p, uint32_t size);

// The characters of a STRING / WSTRING value at `p` (up to its NUL), as UTF-8.
std::string stringText(const sema::Type* t, const uint8_t* p);
size_t stringLength(const sema::Type* t, const uint8_t* p);

}  // namespace strun::testing
