// Options and arguments more than one subcommand takes.
#include "cli/commands.h"
#include "cli/option_types.h"
#include "cli/warning_options.h"
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
            if (!profile) return "unknown target '" + text + "'; the targets are: " + profileNames();
            text = std::string(profile->id);  // the canonical spelling
            return {};
        },
        "", "NAME");
}

}  // namespace

void addFileArguments(CLI::App& command, CommandLine& line) {
    command.add_option("FILE", line.files, "the project's sources: ST files, PLCopen XML, TwinCAT objects, or directories of them")
        ->required()
        ->check(readableFileValidator())
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
