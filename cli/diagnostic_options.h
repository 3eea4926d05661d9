// How compile diagnostics are shown and which warnings count as errors:
// --color, --diagnostics-format, -W (run, check, test). docs/cli.md.
#pragma once

#include <map>
#include <string>

namespace strun::cli {

enum class ColorMode { Auto, Always, Never };
enum class DiagnosticFormat { Text, Json };
// What -W makes of a warning code.
enum class WarningLevel { Off, Warning, Error };

struct DiagnosticOptions {
    ColorMode color = ColorMode::Auto;
    DiagnosticFormat format = DiagnosticFormat::Text;
    bool warningsAreErrors = false;             // -Werror
    std::map<std::string, WarningLevel> levels;  // -W no-CODE, -W CODE=error
};

}  // namespace strun::cli
