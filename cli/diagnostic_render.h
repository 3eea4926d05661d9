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

#include "cli/diagnostic_options.h"
#include "interpreter/source/source_set.h"

namespace strun::cli {

// Returns true when an error is left after -W (the project then does not compile).
bool printDiagnostics(const CompileLog& log, const SourceSet& sources, const DiagnosticOptions& options, std::ostream& out,
                      bool colorTerminal);

// --color auto: stderr is a terminal, TERM is not "dumb" and NO_COLOR is unset.
bool stderrWantsColor(ColorMode mode);

}  // namespace strun::cli
