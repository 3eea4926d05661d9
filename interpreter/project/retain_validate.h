// Whether bytes read from a --retain file are a value their type can hold
// (decision 0251): a file is data from outside, and a STRING without its
// terminator or a BOOL byte of 2 would make the program misbehave in ways
// no ST statement can (LEN past the variable, `b` TRUE but `b = TRUE` FALSE).
#pragma once

#include <cstdint>
#include <string>

#include "interpreter/sema/types.h"

namespace strun::project {

// True when `bytes` (t->size of them) hold a valid value of `t`: every BOOL
// 0 or 1, every STRING / WSTRING terminated within its length, every
// enumeration one of its values, every subrange within its bounds, at any
// depth of arrays and structures. Otherwise false with `why` saying what
// (", element 3: BOOL byte 2"). Types without such rules are always valid.
bool validRetainedValue(const sema::Type* t, const uint8_t* bytes, std::string& why);

}  // namespace strun::project
