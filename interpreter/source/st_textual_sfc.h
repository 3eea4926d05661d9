// Textual SFC in ST files (docs/graphical.md, decision 0233).
#pragma once

#include <string>

#include "interpreter/source/xml_inputs.h"

namespace strun::source {

// True when the text holds the word INITIAL_STEP (any case): only then is a
// file read for textual SFC, so plain ST costs one fast scan.
bool mayHoldTextualSfc(const std::string& text);

// The text with the SFC elements (INITIAL_STEP, STEP, TRANSITION) of every
// POU that has an INITIAL_STEP replaced by their ST; the origins map every
// line back to the file; errors are at the file's lines and columns.
Converted convertTextualSfc(const std::string& text);

}  // namespace strun::source
