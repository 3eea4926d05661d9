#include "cli/stimulus_args.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "cli/option_types.h"

namespace strun::cli {

namespace {

// The last '@' outside a quoted string, or npos.
size_t timeSeparator(const std::string& value) {
    char quote = 0;
    size_t found = std::string::npos;
    for (size_t i = 0; i < value.size(); ++i) {
        char c = value[i];
        if (quote) {
            if (c == '$') ++i;  // an escape: $' does not close the string
            else if (c == quote) quote = 0;
        } else if (c == '\'' || c == '"') {
            quote = c;
        } else if (c == '@') {
            found = i;
        }
    }
    return found;
}

std::string lowered(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

bool parseSetOption(const std::string& text, project::StimulusEntry& entry, std::string& error) {
    entry.origin = "--set " + text;
    size_t eq = text.find('=');
    if (eq == std::string::npos || trimmed(text.substr(0, eq)).empty()) {
        error = entry.origin + ": expected NAME=VALUE[@TIME] (e.g. Main.start=TRUE@T#2s)";
        return false;
    }
    entry.name = trimmed(text.substr(0, eq));
    std::string value = text.substr(eq + 1);
    entry.at = 0;
    if (size_t at = timeSeparator(value); at != std::string::npos) {
        std::string why;
        auto time = parseDuration(value.substr(at + 1), why);
        if (!time) {
            error = entry.origin + ": the time after '@' " + why;
            return false;
        }
        entry.at = *time;
        value.resize(at);
    }
    entry.value = trimmed(value);
    if (entry.value.empty()) {
        error = entry.origin + ": no value after '='";
        return false;
    }
    return true;
}

bool readStimulusFile(const std::string& path, std::vector<project::StimulusEntry>& entries, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "--stimulus: cannot read '" + path + "'";
        return false;
    }
    std::string line;
    bool headerAllowed = true;
    for (int number = 1; std::getline(in, line); ++number) {
        // Spreadsheets save "CSV UTF-8" with a byte-order mark: it is not part of the first field.
        if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
        std::string where = path + ":" + std::to_string(number);
        std::string t = trimmed(line);
        if (t.empty() || t[0] == '#') continue;
        size_t c1 = t.find(',');
        size_t c2 = c1 == std::string::npos ? c1 : t.find(',', c1 + 1);
        if (c2 == std::string::npos) {
            error = where + ": expected TIME,NAME,VALUE";
            return false;
        }
        std::string time = trimmed(t.substr(0, c1));
        std::string name = trimmed(t.substr(c1 + 1, c2 - c1 - 1));
        std::string value = trimmed(t.substr(c2 + 1));
        bool header = lowered(time) == "time" && lowered(name) == "name" && lowered(value) == "value";
        if (std::exchange(headerAllowed, false) && header) continue;
        std::string why;
        auto at = parseDuration(time, why);
        if (!at) {
            error = where + ": the time " + why;
            return false;
        }
        if (name.empty() || value.empty()) {
            error = where + ": expected TIME,NAME,VALUE (" + std::string(name.empty() ? "no name" : "no value") + ")";
            return false;
        }
        entries.push_back({*at, name, value, where});
    }
    if (in.bad()) {
        error = "--stimulus: cannot read '" + path + "'";
        return false;
    }
    return true;
}

bool buildCommandLineStimulus(const CommandLine& line, sema::ProgramModel& model, const rt::PlcProfile& profile,
                              rt::Stimulus& stimulus, std::string& error) {
    std::vector<project::StimulusEntry> entries;
    for (const std::string& text : line.sets) {
        project::StimulusEntry entry;
        if (!parseSetOption(text, entry, error)) return false;
        entries.push_back(std::move(entry));
    }
    for (const std::string& file : line.stimulusFiles)
        if (!readStimulusFile(file, entries, error)) return false;
    return project::buildStimulus(model, entries, stimulus, error, profile);
}

}  // namespace strun::cli
