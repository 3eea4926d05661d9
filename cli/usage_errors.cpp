#include "cli/usage_errors.h"

#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/exit_codes.h"
#include "interpreter/source/closest_name.h"

namespace strun::cli {

namespace {

std::vector<std::string> subcommandNames(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
    return names;
}

std::vector<std::string> optionNames(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::Option* opt : command.get_options()) {
        for (const std::string& n : opt->get_lnames()) names.push_back("--" + n);
    }
    return names;
}

std::string didYouMean(const std::string& closest) { return closest.empty() ? std::string() : "; did you mean '" + closest + "'?"; }

int unknownCommand(const CLI::App& app, const std::string& word) {
    std::cerr << "strun: unknown command '" << word << "'" << didYouMean(closestName(word, subcommandNames(app)))
              << " (the commands: run, check, help)\n";
    return kExitUsage;
}

}  // namespace

int checkSubcommandName(const CLI::App& app, int argc, char** argv) {
    if (argc < 2) return -1;
    std::string first = argv[1];
    if (first.empty()) return -1;
    if (first[0] == '-') {
        if (first == "-h" || first == "--help" || first == "--version") return -1;
        // A command's option before the command: say where it goes.
        std::string option = first.substr(0, first.find('='));
        for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
            for (const std::string& name : optionNames(*sub))
                if (name == option) {
                    std::cerr << "strun: " << option << " is an option of '" << sub->get_name() << "'; it goes after the command: strun "
                              << sub->get_name() << " " << option << " ...\n";
                    return kExitUsage;
                }
        std::cerr << "strun: unknown option '" << option << "'" << didYouMean(closestName(option, optionNames(app))) << "\n";
        return kExitUsage;
    }
    for (const std::string& name : subcommandNames(app))
        if (name == first) return -1;
    return unknownCommand(app, first);
}

int reportParseError(CLI::App& app, const CLI::ParseError& error) {
    // The command whose options apply: the subcommand given, if any.
    const CLI::App* command = &app;
    for (const CLI::App* sub : app.get_subcommands())
        if (sub->parsed()) command = sub;
    std::string where = command == &app ? "strun" : "strun " + command->get_name();
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
        for (const std::string& extra : app.remaining(true)) {
            if (extra.rfind("-", 0) != 0) continue;
            std::string name = extra.substr(0, extra.find('='));
            std::cerr << where << ": unknown option '" << name << "'" << didYouMean(closestName(name, optionNames(*command))) << "\n";
            return kExitUsage;
        }
    }
    std::string what = error.what();
    if (what.empty()) what = error.get_name();
    if (dynamic_cast<const CLI::RequiredError*>(&error) && command == &app) what += " (strun help lists them)";
    std::cerr << where << ": " << what << "\n";
    return kExitUsage;
}

int printHelp(const CLI::App& app, const std::string& topic) {
    if (topic.empty()) {
        // Not app.help(): it shows the selected subcommand (here `help` itself).
        std::cout << app.get_formatter()->make_help(&app, "strun", CLI::AppFormatMode::Normal);
        return kExitOk;
    }
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if (sub->get_name() == topic) {
            std::cout << sub->help("strun");
            return kExitOk;
        }
    return unknownCommand(app, topic);
}

int usage(const std::string& message) {
    std::cerr << "strun: " << message << "\n";
    return kExitUsage;
}

}  // namespace strun::cli
