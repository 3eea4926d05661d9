// Readers of the project files that are XML: TwinCAT 3 objects (.TcPOU,
// .TcDUT, .TcGVL, .TcIO) and PLCopen TC6 XML projects. Each turns one file
// into ST text (with the origin of every line) that the ST parser reads like
// any other source; bodies in IL, LD, FBD, SFC are reported, naming the POU.
#pragma once

#include <string>
#include <vector>

#include "interpreter/source/source_set.h"

namespace strun::source {

// The ST of one file, or errors (`errors` holds XML line/column positions).
struct Converted {
    std::string text;
    std::vector<LineOrigin> origins;
    struct Problem {
        int line = 1, col = 1;
        std::string message;
    };
    std::vector<Problem> errors;
    std::vector<Problem> warnings;  // what was read but left out (W0043)
};

Converted readTwinCat(const std::string& xml);
Converted readPlcOpen(const std::string& xml);

// True when `xml` is a PLCopen TC6 project (root `project` in its namespace).
bool isPlcOpenProject(const std::string& xml);

}  // namespace strun::source
