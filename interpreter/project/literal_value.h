// An ST literal given on the command line (--set, --stimulus) converted to
// the storage image of a variable's type, as an assignment of that literal
// would store it. Only elementary types (and enumerations) take a literal.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/sema/types.h"

namespace strun::project {

// `bytes` gets type->size bytes. False with `error` ("300 does not fit SINT
// (-128..127)") when the text is no literal of the type or out of its range.
// Accepted: TRUE/FALSE/1/0 (BOOL); decimal, signed, based (16#FF) and typed
// (INT#5) integers; reals (an integer literal too); durations, dates, times
// of day, date-and-times with or without prefix; 'text' / "text" strings and
// characters; an enumeration's value name, also as Type#NAME.
bool encodeLiteral(const sema::Type* type, std::string_view text, std::vector<uint8_t>& bytes, std::string& error);

}  // namespace strun::project
