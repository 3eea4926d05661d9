// The catalogue of diagnostic codes: the one table from which `strun explain
// CODE` and the pages docs/diagnostics/<CODE>.md are produced (the ctest
// diagnostics.docs_in_sync fails when a committed page differs). Each compile
// diagnostic gets its code where it is raised (diagnostic_code.h).
//
// Codes are stable: E0xxx compile errors, W0xxx warnings (each can be
// silenced or raised with -W), and the runtime fault codes of the diagnostic
// buffer under their own names (DIV_BY_ZERO, ...). Decision 0160.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace strun::diagnostics {

enum class Kind { Error, Warning, Runtime };

struct CodeInfo {
    std::string_view code;
    Kind kind;
    std::string_view title;        // one line, used as the page heading
    std::string_view explanation;  // what it means and what to do (paragraphs separated by blank lines)
    std::string_view wrong;        // an ST example that gets the diagnostic ("" for none)
    std::string_view right;        // the same, corrected
};

// Every code, in code order.
const std::vector<CodeInfo>& catalogue();
// The entry of `code` (case-insensitive), or null.
const CodeInfo* find(std::string_view code);
// The page of one code as Markdown (docs/diagnostics/<CODE>.md) ...
std::string markdownPage(const CodeInfo& info);
// ... and as plain text for `strun explain`.
std::string textPage(const CodeInfo& info);
// The index page docs/diagnostics/README.md: every code with its title.
std::string markdownIndex();

}  // namespace strun::diagnostics
