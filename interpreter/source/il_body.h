// Instruction List bodies (IEC 61131-3 2nd/3rd edition, section 3.2;
// CODESYS 3.5, TwinCAT 3, matiec/Beremiz) translated to ST statements, as
// the LD, FBD and SFC bodies are (docs/graphical.md, decision 0415): the
// checker, executor, faults, watchdog and debugger then treat an IL body
// like an ST one, and every generated line points at its IL line and names
// the instruction.
//
// The current result (CR) is carried as an ST expression from instruction
// to instruction (`LD a ADD b ST x` is `x := a + b;`). Where it must
// outlive a statement or meet several paths (a label) it is kept in a
// hidden temporary declared {attribute 'strun_inferred_temp'}: the checker
// gives it the type of the first value assigned to it, so the CR has the
// type of what was loaded.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "interpreter/source/plcopen_graphical.h"

namespace strun::source::il {

// What the translation asks of the POU around the body.
struct Surroundings {
    std::string prefix;  // of the hidden temporaries' names (unique per body)
    // True when `name` is a function-block instance: `S name` / `R name`
    // are then its inputs S and R, not the set and reset of a BOOL.
    std::function<bool(const std::string& name)> isBlockInstance;
    // A problem at (line, col) of the file; the body is then left out.
    std::function<void(int line, int col, const std::string& message)> fail;
};

// Translates the IL `text`, whose first character is at (line, col) of the
// file, into `out.body` and the hidden temporaries into `out.declarations`.
// False after an error (reported through `fail`; `out` is left empty).
bool translate(std::string_view text, int line, int col, const Surroundings& around, plcopen::Translation& out);

// True when `upperWord` is an IL operator (LD, ST, S, JMPC, CAL, RET, ADD,
// ANDN, CU, ...): what tells an IL body from an ST one in a text file
// (st_textual_il.cpp, decision 0464).
bool isOperator(const std::string& upperWord);
// The length of the longest of them (JMPCN, CALCN, RETCN).
inline constexpr size_t kLongestOperator = 5;

}  // namespace strun::source::il
