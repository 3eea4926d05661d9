// A position in a project's sources (1-based line and column; file is an
// index into the project's list of sources). The runtime keeps it with task
// declarations for its messages; the AST uses the same type (ast::Loc), so
// the runtime needs nothing of the interpreter.
#pragma once

namespace strun::rt {

struct SourceLoc {
    int file = 0;
    int line = 0;
    int col = 0;
};

}  // namespace strun::rt
