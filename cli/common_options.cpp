// Options and arguments more than one subcommand takes.
#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/option_types.h"
#include "cli/warning_options.h"
#include "interpreter/source/closest_name.h"
#include "runtime/plc_profile.h"

namespace strun::cli {

namespace {

std::string profileNames() {
    std::string names;
    for (const rt::PlcProfile& p : rt::allProfiles()) {
        if (!names.empty()) names += ", ";
        names += p.id;
    }
    return names;
}

CLI::Validator targetValidator() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            text = trimmed(text);
            const rt::PlcProfile* profile = rt::findProfile(text);
            if (!profile) {
                std::vector<std::string> ids;
                for (const rt::PlcProfile& p : rt::allProfiles()) ids.emplace_back(p.id);
                const std::string near = closestName(text, ids);
                return "unknown target '" + text + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?") + "; the targets are: " + profileNames();
            }
            text = std::string(profile->id);  // the canonical spelling
            return {};
        },
        "", "NAME");
}

}  // namespace

void addFileArguments(CLI::App& command, CommandLine& line) {
    command.add_option("FILE", line.files, "the project's sources: ST files, PLCopen XML, TwinCAT objects, or directories of them (- reads ST from standard input)")
        ->required()
        ->check(readableFileValidator(true))
        ->type_name("FILE");
}

void addCompileOptions(CLI::App& command, CommandLine& line) {
    command.add_option("--target", line.compile.target, "the PLC family whose task model and limits apply: " + profileNames())
        ->transform(targetValidator())
        ->type_name("NAME")
        ->default_str("generic");
    command.add_flag("--strict", line.compile.strict, "IEC 61131-3 typing: implicit conversions are errors, not warnings");
    addDiagnosticOptions(command, line.diagnostics);
}

}  // namespace strun::cli
