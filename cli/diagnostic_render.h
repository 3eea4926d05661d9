// Prints a CompileLog the way a modern compiler does: sorted by file and
// position, exact duplicates removed, -W applied, each diagnostic as
//
//   FILE:LINE:COL: error: MESSAGE [CODE]
//     LINE | the source line
//          | ^^^^^ (under the span)
//   FILE:LINE:COL: note: TEXT        (a note with a location, with its excerpt)
//   note: TEXT / help: TEXT
//
// or, with --diagnostics-format json, one JSON object per line. The first
// line's shape is fixed by the outside interface (other tools grep for it).
#pragma once

#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/diagnostic_options.h"
#include "interpreter/source/source_set.h"

namespace strun::cli {

// Returns true when an error is left after -W (the project then does not compile).
bool printDiagnostics(const CompileLog& log, const SourceSet& sources, const DiagnosticOptions& options, std::ostream& out,
                      bool colorTerminal);

// The diagnostics printDiagnostics shows, in its order (-W applied, sorted,
// duplicates removed): strun lsp publishes the same ones.
std::vector<Diagnostic> shownDiagnostics(const CompileLog& log, const SourceSet& sources, const DiagnosticOptions& options);
// One diagnostic as --diagnostics-format json prints it: code, severity,
// file, line, column, end {line, column}, message, notes, suggestions, in the
// file the user has (XML positions for converted sources).
nlohmann::ordered_json diagnosticJson(const Diagnostic& d, const SourceSet& sources);

// A runtime fault of `strun run`: its first line `FILE:LINE:COL: runtime
// error: CODE in TASK: MESSAGE` (fixed by the outside interface, given as
// `where` and `rest`), then the source excerpt of `loc` when it is a line of an
// ST file; with --diagnostics-format json one object instead (decision 0163).
struct RuntimeFault {
    ast::Loc loc;          // file -1: unknown
    std::string where;     // FILE:LINE:COL as the first line prints it
    std::string code;      // DIV_BY_ZERO, ...
    std::string task;
    std::string message;
};
void printRuntimeFault(std::ostream& out, const RuntimeFault& fault, const SourceSet& sources, DiagnosticFormat format,
                       bool color);

// --color auto: stderr is a terminal, TERM is not "dumb" and NO_COLOR is unset.
bool stderrWantsColor(ColorMode mode);
// The same rule for any output file descriptor (strun test colours PASS / FAIL on stdout).
bool fdWantsColor(ColorMode mode, int fd);

}  // namespace strun::cli
