// The options that shape compile diagnostics (run, check, test):
//   --color auto|always|never, --diagnostics-format text|json,
//   -W no-CODE, -W CODE=error, -W CODE=warning, -Werror (as `-W error`).
#pragma once

#include <string>

#include "cli/cli11_fwd.h"

#include "cli/diagnostic_options.h"

namespace strun::cli {

void addDiagnosticOptions(CLI::App& command, DiagnosticOptions& options);
// One -W value into `options`; "" or the reason it is refused.
std::string applyWarningOption(const std::string& value, DiagnosticOptions& options);

}  // namespace strun::cli
