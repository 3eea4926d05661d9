#include "cli/man_page.h"

#include <string>

#include <CLI/CLI.hpp>

#include "cli/exit_codes.h"

namespace strun::cli {

namespace {

// Text for roff: backslashes doubled, a leading '.' or '\'' escaped, '-' as \-.
std::string roff(const std::string& text) {
    std::string out;
    bool lineStart = true;
    for (char c : text) {
        if (lineStart && (c == '.' || c == '\'')) out += "\\&";
        if (c == '\\') out += "\\\\";
        else if (c == '-') out += "\\-";
        else out += c;
        lineStart = c == '\n';
    }
    return out;
}

// CLI11's own text for an option's names and value ("-j,--jobs N"), as in --help.
class OptionText : public CLI::Formatter {
public:
    std::string names(const CLI::Option* opt) const {
        if (opt->get_positional()) return positional(opt);
        return make_option_name(opt, false) + make_option_opts(opt);
    }
    // "FILE..." (several, required), "[CODE]" (optional).
    static std::string positional(const CLI::Option* opt) {
        std::string name = opt->get_name(true, false) + (opt->get_expected_max() > 1 ? "..." : "");
        return opt->get_required() ? name : "[" + name + "]";
    }
};

void options(const CLI::App& command, std::ostream& out) {
    OptionText text;
    for (const CLI::Option* opt : command.get_options()) {
        if (opt->get_name() == "--help" || opt->get_name() == "-h,--help" || opt->get_name().find("help") != std::string::npos) continue;
        if (opt->get_description().empty()) continue;
        out << ".TP\n.B " << roff(text.names(opt)) << "\n" << roff(opt->get_description()) << "\n";
    }
}

}  // namespace

int printManPage(const CLI::App& app, std::ostream& out) {
    out << ".\\\" Made by `strun help --man` from the text of --help (cli/man_page.cpp): do not edit.\n";
    out << ".TH STRUN 1 \"\" \"strun " STRUN_VERSION "\" \"User Commands\"\n";
    out << ".SH NAME\nstrun \\- " << roff("IEC 61131-3 Structured Text interpreter with a PLC task runtime") << "\n";
    out << ".SH SYNOPSIS\n";
    auto all = [](const CLI::App*) { return true; };
    for (const CLI::App* sub : app.get_subcommands(all)) {
        out << ".B strun " << sub->get_name() << "\n[\\fIoptions\\fR]";
        for (const CLI::Option* opt : sub->get_options())
            if (opt->get_positional()) out << " \\fI" << roff(OptionText::positional(opt)) << "\\fR";
        out << "\n.br\n";
    }
    out << ".B strun \\-\\-version\n";
    out << ".SH DESCRIPTION\n"
        << roff("strun compiles IEC 61131-3 Structured Text (also PLCopen XML exports and TwinCAT objects) and runs it under "
                "a PLC task runtime: cyclic, event and freewheeling tasks with priorities, watchdogs and the task models of "
                "several PLC families, on the real clock or a deterministic virtual one. It also checks a project without "
                "running it and runs its TcUnit / CfUnit unit tests.")
        << "\n.PP\n"
        << roff("Several FILEs form one project; a directory stands for every source file under it; - reads ST from "
                "standard input.")
        << "\n";
    out << ".SH COMMANDS\n";
    for (const CLI::App* sub : app.get_subcommands(all)) {
        out << ".SS strun " << sub->get_name() << "\n" << roff(sub->get_description()) << "\n";
        options(*sub, out);
        if (!sub->get_footer().empty()) out << ".PP\n" << roff(sub->get_footer()) << "\n";
    }
    out << ".SH EXIT STATUS\n"
        << ".TP\n.B 0\nsuccess (test: every test passed)\n"
        << ".TP\n.B 1\n" << roff("the project does not compile; test: a test failed, or no test ran (without --allow-empty)") << "\n"
        << ".TP\n.B 2\n" << roff("bad command line (an unknown command or option names the closest valid one)") << "\n"
        << ".TP\n.B 3\n" << roff("run: the PLC went to STOP/HALT because of a runtime fault") << "\n";
    out << ".SH EXAMPLES\n.nf\n"
        << roff("strun run --virtual --cycles 10 --dump plant.st\n"
                "strun run --virtual --for T#10s --set Main.start=TRUE@T#2s --vcd run.vcd plant.st\n"
                "strun check --target m340 project/\n"
                "strun test --junit report.xml project/\n"
                "strun explain E0101\n")
        << ".fi\n";
    out << ".SH SEE ALSO\n"
        << roff("The documentation installed with strun (e.g. /usr/local/share/doc/strun or /usr/share/doc/strun): cli.md "
                "(the command line), testing.md (strun test), targets.md (the PLC families), diagnostics.md and "
                "diagnostics/ (every code, also strun explain), limits.md, and the examples in examples/.")
        << "\n";
    return kExitOk;
}

}  // namespace strun::cli
