// strun: the command line (the fixed interface is described in docs/cli.md).
//   strun run   [options] FILE...   compile the FILEs as one project and run it
//   strun check [options] FILE...   compile only; print diagnostics
//   strun test  [options] FILE...|DIR   run the unit tests (TcUnit / CfUnit API)
//   strun explain [CODE]            the page of a diagnostic code
//   strun help [COMMAND], strun --version
// Exit status: 0 ok, 1 does not compile, 2 bad command line, 3 PLC STOP/HALT.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string_view>

#include <CLI/CLI.hpp>
#include <malloc.h>
#include <unistd.h>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/editor_commands.h"
#include "cli/exit_codes.h"
#include "cli/huge_page_restart.h"
#include "cli/man_page.h"
#include "cli/test_command.h"
#include "cli/usage_errors.h"

#ifndef STRUN_VERSION
#error "STRUN_VERSION comes from project(strun VERSION ...) in CMakeLists.txt"
#endif

namespace strun::cli {

// strun lsp and strun debug have no options: registered here, so that
// cli/lsp_command.cpp and cli/debug_command.cpp need not include CLI11 (issue 28).
CLI::App* addLspCommand(CLI::App& app) {
    return app.add_subcommand("lsp", "a Language Server Protocol server on stdin/stdout (docs/editors.md)");
}

CLI::App* addDebugCommand(CLI::App& app) {
    return app.add_subcommand("debug", "a Debug Adapter Protocol adapter on stdin/stdout (docs/editors.md)");
}

}  // namespace strun::cli

namespace {

using namespace strun::cli;

int runMain(int argc, char** argv) {
    CLI::App app{"strun: IEC 61131-3 Structured Text interpreter with a PLC task runtime", "strun"};
    app.set_version_flag("--version", "strun " STRUN_VERSION, "print `strun " STRUN_VERSION "` and exit");
    app.require_subcommand(1);
    app.footer("Exit status: 0 success, 1 the project does not compile, 2 bad command line,\n"
               "3 the PLC went to STOP/HALT because of a runtime fault.\n"
               "`strun help COMMAND` or `strun COMMAND --help` shows the options of a command.");
    // `strun run|check|test ...` registers only that command (and help): the
    // options of the others cost ~330 000 instructions of every run (CLI11
    // compares each new option with all before it). Their options cannot
    // matter: after its command word, CLI11 parses only that command's
    // options and positionals. Any other first word (an option, a mistyped
    // or missing command, help) registers every command, for the messages
    // that list or suggest them.
    const std::string_view first = argc > 1 ? argv[1] : "";
    const bool all = first != "run" && first != "check" && first != "test";
    CommandLine line;
    CLI::App* run = all || first == "run" ? addRunCommand(app, line) : nullptr;
    CLI::App* check = all || first == "check" ? addCheckCommand(app, line) : nullptr;
    TestCommandLine testLine;
    CLI::App* test = all || first == "test" ? addTestCommand(app, line, testLine) : nullptr;
    std::string explainCode;
    CLI::App* explain = all ? addExplainCommand(app, explainCode) : nullptr;
    CLI::App* lsp = all ? addLspCommand(app) : nullptr;
    CLI::App* debug = all ? addDebugCommand(app) : nullptr;
    CLI::App* help = app.add_subcommand("help", "show the commands, or the options of COMMAND");
    std::string helpTopic;
    help->add_option("COMMAND", helpTopic, "run, check, test, explain")->type_name("COMMAND");
    bool manPage = false;
    help->add_flag("--man", manPage, "print the manual page strun.1 (roff), made from this help");

    if (int status = checkSubcommandName(app, argc, argv); status >= 0) return status;
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return reportParseError(app, e);
    }
    if (help->parsed()) return manPage ? printManPage(app, std::cout) : printHelp(app, helpTopic);
    if (run && run->parsed()) return runCommand(line);
    if (check && check->parsed()) return checkCommand(line);
    if (test && test->parsed()) return testCommand(line, testLine);
    if (explain && explain->parsed()) return explainCommand(explainCode);
    if (lsp && lsp->parsed()) return lspCommand();
    if (debug && debug->parsed()) return debugCommand();
    return kExitUsage;
}

// Ends the process once every command has closed its own files (VCD, JUnit,
// retain: their writers live inside the command). Static destructors are
// skipped: tearing down the cached standard library and ANTLR's DFA caches
// cost more than a one-line run (decision 0156). Sanitizer builds leave
// through exit() so that their end-of-process checks still run.
[[noreturn]] void leave(int status) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
#ifdef STRUN_SANITIZED
    std::exit(status);
#else
    _Exit(status);
#endif
}

}  // namespace

int main(int argc, char** argv) {
    // Before anything is read or written: may replace the process image.
    restartWithHugePagesForLargeInputs(argc, argv);
    // Two malloc arenas: the two halves of a large file are parsed at the
    // same time (decision 0159), and with one arena they took turns at its
    // lock. More would only cost mmap/mprotect calls: nothing on strun's hot
    // path allocates, so the real-clock threads lose nothing by sharing
    // (decision 0156).
    mallopt(M_ARENA_MAX, 2);
    mallopt(M_TOP_PAD, 4 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    mallopt(M_MMAP_THRESHOLD, 8 << 20);
    try {
        leave(runMain(argc, argv));
    } catch (const std::bad_alloc&) {
        std::cerr << "strun: out of memory\n";
        return kExitCompile;
    } catch (const std::exception& e) {
        // Never a raw exception text on the terminal: a short, stable message.
        std::cerr << "strun: internal error (" << (std::getenv("STRUN_DEBUG") ? e.what() : "set STRUN_DEBUG=1 for details") << ")\n";
        return kExitCompile;
    } catch (...) {
        std::cerr << "strun: internal error\n";
        return kExitCompile;
    }
}
