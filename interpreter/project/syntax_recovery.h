// Checking a project that has syntax errors (decision 0161). When every
// syntax error is local (a missing ';', a missing END_IF, a foreign operator,
// an unexpected token), the tree the parser recovered is checked as well, so
// that the file's other mistakes are reported in the same run. What the
// checker then says about the broken lines themselves (placeholders the
// parser put in) or about variables whose uses were lost is dropped.
#pragma once

#include <set>
#include <string>
#include <utility>

#include "interpreter/source/source_set.h"

namespace strun::project {

struct SyntaxDamage {
    bool checkable = true;                 // false: some error is not local; do not check semantics
    std::set<std::pair<int, int>> lines;   // (file, line) of every syntax error
    std::set<int> files;                   // files with syntax errors
    std::set<std::string> skippedNames;    // declarations the parser skipped (their uses are not reported)
};

SyntaxDamage assessSyntaxErrors(const CompileLog& log);
// Removes the checker's diagnostics on damaged lines, and the warnings that
// lost statements make wrong (unused variables, unassigned results).
void dropSyntaxCascades(CompileLog& log, const SyntaxDamage& damage);

}  // namespace strun::project
