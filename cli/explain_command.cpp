// strun explain [CODE]: the page of a diagnostic code (the same text as
// docs/diagnostics/CODE.md), or the list of codes.
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "interpreter/source/closest_name.h"
#include "interpreter/source/diagnostic_codes.h"

namespace strun::cli {

CLI::App* addExplainCommand(CLI::App& app, std::string& code) {
    CLI::App* explain = app.add_subcommand("explain", "explain a diagnostic code (E0101, W0003, DIV_BY_ZERO); without CODE list them");
    explain->add_option("CODE", code, "the code, as printed at the end of a diagnostic")->type_name("CODE");
    return explain;
}

int explainCommand(const std::string& code) {
    if (code.empty()) {
        for (const auto& info : diagnostics::catalogue()) std::cout << info.code << "  " << info.title << '\n';
        return kExitOk;
    }
    if (const diagnostics::CodeInfo* info = diagnostics::find(code)) {
        std::cout << diagnostics::textPage(*info);
        return kExitOk;
    }
    std::vector<std::string> codes;
    for (const auto& info : diagnostics::catalogue()) codes.emplace_back(info.code);
    std::string upperCode = code;
    for (char& c : upperCode)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    const std::string near = closestName(upperCode, codes);
    std::cerr << "strun explain: unknown code '" << code << "'" << (near.empty() ? "" : "; did you mean '" + near + "'?")
              << " (`strun explain` lists the codes)\n";
    return kExitUsage;
}

}  // namespace strun::cli
