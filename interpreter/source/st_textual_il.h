// Instruction List bodies in text files (docs/graphical.md, decision 0464).
#pragma once

#include <string>

#include "interpreter/source/xml_inputs.h"

namespace strun::source {

// True when some body of the text may be IL: after an END_VAR, an ACTION
// header or the end of a member, the next word is an IL operator or a
// label. One scan that plain ST passes quickly (it runs on every ST file).
bool mayHoldTextualIl(const std::string& text);

// The text with every IL body replaced by its ST (il_body.cpp) and the
// hidden temporaries declared in a VAR section before it (before the POU's
// first declaration for an ACTION); the origins map every line back to the
// file; errors are at the file's lines and columns. No IL body after all:
// `text` is the input unchanged and `origins` empty.
Converted convertTextualIl(const std::string& text);

}  // namespace strun::source
