#include "cli/warning_options.h"

#include <vector>

#include <CLI/CLI.hpp>

#include "cli/option_types.h"
#include "interpreter/source/closest_name.h"
#include "interpreter/source/diagnostic_codes.h"

namespace strun::cli {

namespace {

std::string upper(std::string text) {
    for (char& c : text)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    return text;
}

// The warning code `code` names, or a refusal with the closest code.
std::string checkWarningCode(const std::string& code) {
    const diagnostics::CodeInfo* info = diagnostics::find(code);
    if (info && info->kind == diagnostics::Kind::Warning) return "";
    if (info) return "'" + code + "' is not a warning; only warning codes (W...) can be silenced or made errors";
    std::vector<std::string> codes;
    for (const auto& c : diagnostics::catalogue())
        if (c.kind == diagnostics::Kind::Warning) codes.emplace_back(c.code);
    std::string near = closestName(upper(code), codes);
    return "unknown warning code '" + code + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?") +
           " (`strun explain` lists the codes)";
}

}  // namespace

std::string applyWarningOption(const std::string& raw, DiagnosticOptions& options) {
    const std::string value = trimmed(raw);
    if (value == "error") {
        options.warningsAreErrors = true;
        return "";
    }
    std::string code;
    WarningLevel level = WarningLevel::Off;
    if (value.rfind("no-", 0) == 0) {
        code = value.substr(3);
    } else if (auto eq = value.find('='); eq != std::string::npos) {
        code = value.substr(0, eq);
        const std::string what = value.substr(eq + 1);
        if (what == "error") level = WarningLevel::Error;
        else if (what == "warning") level = WarningLevel::Warning;
        else if (what == "off") level = WarningLevel::Off;
        else return "'" + value + "': expected CODE=error, CODE=warning or CODE=off";
    } else {
        return "'" + value + "': expected error (-Werror), no-CODE or CODE=error";
    }
    if (std::string problem = checkWarningCode(code); !problem.empty()) return problem;
    options.levels[upper(code)] = level;
    return "";
}

void addDiagnosticOptions(CLI::App& command, DiagnosticOptions& options) {
    command.add_option_function<std::string>(
               "--color",
               [&options](const std::string& v) {
                   options.color = v == "always" ? ColorMode::Always : v == "never" ? ColorMode::Never : ColorMode::Auto;
               },
               "colour in diagnostics: auto (a terminal, TERM not dumb, NO_COLOR unset), always, never")
        ->check(CLI::IsMember({"auto", "always", "never"}))
        ->type_name("WHEN")
        ->default_str("auto");
    command.add_option_function<std::string>(
               "--diagnostics-format",
               [&options](const std::string& v) { options.format = v == "json" ? DiagnosticFormat::Json : DiagnosticFormat::Text; },
               "text (source excerpts) or json (one object per line)")
        ->check(CLI::IsMember({"text", "json"}))
        ->type_name("FORMAT")
        ->default_str("text");
    command.add_option_function<std::vector<std::string>>(
               "-W",
               [&options](const std::vector<std::string>& values) {
                   for (const std::string& v : values) applyWarningOption(v, options);
               },
               "-Werror: warnings are errors; -W no-CODE silences a warning; -W CODE=error makes it an error (repeatable)")
        ->check(CLI::Validator(
            [](std::string& v) {
                DiagnosticOptions scratch;
                return applyWarningOption(v, scratch);
            },
            "", "SETTING"))
        ->type_name("SETTING")
        ->allow_extra_args(false);
}

}  // namespace strun::cli
