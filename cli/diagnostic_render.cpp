#include "cli/diagnostic_render.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>
#include <tuple>

#include <nlohmann/json.hpp>

namespace strun::cli {

namespace {

// Past this many display columns a source line is shown as a window around the caret.
constexpr size_t kMaxShownColumns = 160;
constexpr size_t kWindowBefore = 60;

struct Style {
    bool on = false;
    std::string paint(const char* code, const std::string& text) const {
        if (!on || text.empty()) return text;
        return std::string("\x1b[") + code + "m" + text + "\x1b[0m";
    }
};
constexpr const char* kBold = "1";
constexpr const char* kRed = "1;31";
constexpr const char* kMagenta = "1;35";
constexpr const char* kCyan = "1;36";
constexpr const char* kGreen = "1;32";
constexpr const char* kBlue = "1;34";

// A position in the file the user has: path, line and column there.
struct Where {
    bool known = false;
    const SourceFile* file = nullptr;
    std::string path;
    int line = 1;
    int col = 1;
};

Where locate(const SourceSet& sources, const ast::Loc& loc) {
    Where w;
    if (loc.file < 0 || loc.file >= sources.size()) {
        w.path = "<unknown>";
        w.line = std::max(loc.line, 1);
        w.col = std::max(loc.col, 1);
        return w;
    }
    w.file = &sources.file(loc.file);
    w.path = w.file->path;
    auto [line, col] = w.file->original(loc.line, loc.col);
    w.line = std::max(line, 1);
    w.col = std::max(col, 1);
    w.known = true;
    return w;
}

// Line `line` (1-based) of `text`, without its line end; false if there is none.
bool sourceLine(const std::string& text, int line, std::string& out) {
    size_t start = 0;
    for (int l = 1; l < line; ++l) {
        size_t nl = text.find('\n', start);
        if (nl == std::string::npos) return false;
        start = nl + 1;
    }
    if (start > text.size() || (start == text.size() && line > 1 && text.empty())) return false;
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    out = text.substr(start, end - start);
    if (!out.empty() && out.back() == '\r') out.pop_back();
    return true;
}

bool isWordByte(unsigned char c) { return std::isalnum(c) || c == '_' || c >= 0x80; }

// Byte offset of code point `col` (1-based) in `line`, or line.size() past its end.
size_t byteOfColumn(const std::string& line, int col) {
    int cp = 1;
    for (size_t i = 0; i < line.size(); ++i) {
        if ((static_cast<unsigned char>(line[i]) & 0xC0) == 0x80) continue;
        if (cp == col) return i;
        ++cp;
    }
    return line.size();
}

// Length in bytes of the token that starts at byte `at`: the underline when a diagnostic has no explicit end.
size_t tokenLength(const std::string& line, size_t at) {
    if (at >= line.size()) return 0;
    const unsigned char c = static_cast<unsigned char>(line[at]);
    size_t end = at + 1;
    if (c == '\'' || c == '"') {
        size_t close = line.find(static_cast<char>(c), at + 1);
        return close == std::string::npos ? line.size() - at : close + 1 - at;
    }
    if (isWordByte(c) || c == '%') {
        const bool literal = std::isdigit(c) != 0;
        while (end < line.size()) {
            const unsigned char d = static_cast<unsigned char>(line[end]);
            if (isWordByte(d) || (c == '%' && d == '.') || (literal && (d == '#' || d == '.'))) ++end;
            else break;
        }
        // A typed literal continues after '#': T#1s, INT#5, 16#FF, E_Mode#Run.
        if (end < line.size() && line[end] == '#' && !literal) {
            ++end;
            while (end < line.size() && (isWordByte(static_cast<unsigned char>(line[end])) || line[end] == '.' || line[end] == ':' || line[end] == '-')) ++end;
        }
        return end - at;
    }
    static const char* const kPairs[] = {":=", "=>", "<=", ">=", "<>", "**", "==", "!=", "++", "--", "+=", "-=", "*=", "/=", "&&", "||", "..", "?="};
    for (const char* p : kPairs)
        if (line.compare(at, 2, p) == 0) return 2;
    return 1;
}

// Display form of a source line: tabs as spaces, control characters as '?';
// `columnOf[b]` is the display column of byte b (0-based).
std::string displayLine(const std::string& line, std::vector<size_t>& columnOf) {
    std::string shown;
    size_t column = 0;
    columnOf.assign(line.size() + 1, 0);
    for (size_t i = 0; i < line.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(line[i]);
        columnOf[i] = column;
        if (c == '\t') {
            size_t spaces = 4 - column % 4;
            shown.append(spaces, ' ');
            column += spaces;
        } else if (c < 0x20 || c == 0x7F) {
            shown += '?';
            ++column;
        } else {
            shown += static_cast<char>(c);
            if ((c & 0xC0) != 0x80) ++column;
        }
    }
    columnOf[line.size()] = column;
    return shown;
}

struct Excerpt {
    bool present = false;
    int line = 0;
    std::string text;   // the line as shown
    size_t from = 0;    // display columns of the underline
    size_t width = 1;
    int endLine = 0;    // for JSON: the span's end in the user's file
    int endCol = 0;
};

Excerpt excerptFor(const Where& w, const Diagnostic* d) {
    Excerpt e;
    e.endLine = w.line;
    e.endCol = w.col + 1;
    if (!w.known) return e;
    std::string raw;
    if (!sourceLine(w.file->shownText(), w.line, raw)) return e;
    std::vector<size_t> columnOf;
    std::string shown = displayLine(raw, columnOf);
    const size_t at = byteOfColumn(raw, w.col);
    size_t len = tokenLength(raw, at);
    if (d && d->endLine > 0 && w.file->origins.empty()) {
        // An explicit span (only in ST text: XML shifts are per line).
        if (d->endLine == d->loc.line && d->endCol > d->loc.col) len = byteOfColumn(raw, d->endCol) - at;
        else if (d->endLine > d->loc.line) len = raw.size() - at;
    }
    e.present = true;
    e.line = w.line;
    e.from = columnOf[at];
    e.width = std::max<size_t>(1, columnOf[std::min(at + len, raw.size())] - columnOf[at]);
    int cps = 0;
    for (size_t i = at; i < at + len && i < raw.size(); ++i)
        if ((static_cast<unsigned char>(raw[i]) & 0xC0) != 0x80) ++cps;
    e.endCol = w.col + std::max(cps, 1);
    if (shown.size() > kMaxShownColumns && e.from > kWindowBefore) {
        // A very long line: a window around the span.
        size_t cut = e.from - kWindowBefore;
        while (cut < shown.size() && (static_cast<unsigned char>(shown[cut]) & 0xC0) == 0x80) ++cut;
        shown = "..." + shown.substr(cut);
        e.from = e.from - cut + 3;
    }
    if (shown.size() > kMaxShownColumns) {
        size_t keep = kMaxShownColumns;
        while (keep < shown.size() && (static_cast<unsigned char>(shown[keep]) & 0xC0) == 0x80) ++keep;
        shown = shown.substr(0, keep) + "...";
        e.width = std::min(e.width, keep > e.from ? keep - e.from : 1);
    }
    e.text = std::move(shown);
    return e;
}

void printExcerpt(std::ostream& out, const Excerpt& e, const Style& style, const char* markColor, char mark, size_t gutter) {
    if (!e.present) return;
    const std::string number = std::to_string(e.line);
    out << std::string(gutter - number.size() + 1, ' ') << style.paint(kBlue, number + " |") << ' ' << e.text << '\n';
    out << std::string(gutter + 2, ' ') << style.paint(kBlue, "|") << ' ' << std::string(e.from, ' ')
        << style.paint(markColor, std::string(e.width, mark)) << '\n';
}

const char* severityWord(Severity s) { return s == Severity::Error ? "error" : "warning"; }

void printText(std::ostream& out, const Diagnostic& d, const SourceSet& sources, const Style& style) {
    const Where w = locate(sources, d.loc);
    const char* color = d.severity == Severity::Error ? kRed : kMagenta;
    const Excerpt main = excerptFor(w, &d);
    std::vector<std::pair<Where, Excerpt>> located;
    size_t gutter = std::to_string(main.line).size();
    for (const DiagnosticNote& n : d.notes) {
        if (!n.loc) continue;
        Where nw = locate(sources, *n.loc);
        Excerpt ne = excerptFor(nw, nullptr);
        gutter = std::max(gutter, std::to_string(ne.line).size());
        located.emplace_back(std::move(nw), std::move(ne));
    }
    out << style.paint(kBold, w.path + ':' + std::to_string(w.line) + ':' + std::to_string(w.col) + ':') << ' '
        << style.paint(color, std::string(severityWord(d.severity)) + ':') << ' ' << style.paint(kBold, d.message);
    if (!d.code.empty()) out << " [" << d.code << ']';
    out << '\n';
    printExcerpt(out, main, style, color, '^', gutter);
    size_t next = 0;
    for (const DiagnosticNote& n : d.notes) {
        if (n.loc) {
            const auto& [nw, ne] = located[next++];
            out << style.paint(kBold, nw.path + ':' + std::to_string(nw.line) + ':' + std::to_string(nw.col) + ':') << ' '
                << style.paint(kCyan, "note:") << ' ' << n.text << '\n';
            printExcerpt(out, ne, style, kCyan, '-', gutter);
        } else {
            out << style.paint(kCyan, "note:") << ' ' << n.text << '\n';
        }
    }
    for (const std::string& h : d.help) out << style.paint(kGreen, "help:") << ' ' << h << '\n';
}

}  // namespace

nlohmann::ordered_json diagnosticJson(const Diagnostic& d, const SourceSet& sources) {
    const Where w = locate(sources, d.loc);
    const Excerpt e = excerptFor(w, &d);
    nlohmann::ordered_json j;
    j["code"] = d.code;
    j["severity"] = severityWord(d.severity);
    j["file"] = w.path;
    j["line"] = w.line;
    j["column"] = w.col;
    j["end"] = {{"line", e.endLine}, {"column", e.endCol}};
    j["message"] = d.message;
    j["notes"] = nlohmann::ordered_json::array();
    for (const DiagnosticNote& n : d.notes) {
        nlohmann::ordered_json note;
        if (n.loc) {
            const Where nw = locate(sources, *n.loc);
            note["file"] = nw.path;
            note["line"] = nw.line;
            note["column"] = nw.col;
        }
        note["message"] = n.text;
        j["notes"].push_back(std::move(note));
    }
    j["suggestions"] = d.help;
    return j;
}

namespace {

void printJson(std::ostream& out, const Diagnostic& d, const SourceSet& sources) {
    out << diagnosticJson(d, sources).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
}

}  // namespace

void printRuntimeFault(std::ostream& out, const RuntimeFault& fault, const SourceSet& sources, DiagnosticFormat format,
                       bool color) {
    // Only plain ST text: a converted file's (XML) runtime positions are not mapped here.
    const bool st = fault.loc.file >= 0 && fault.loc.file < sources.size() && sources.file(fault.loc.file).origins.empty() &&
                    fault.loc.line > 0;
    // A fault in ST made from an LD/FBD/SFC element names the element (fault
    // positions are already those of the file the user has: the element at that line).
    std::string element;
    if (fault.loc.file >= 0 && fault.loc.file < sources.size())
        for (const LineOrigin& o : sources.file(fault.loc.file).origins)
            if (o.line == fault.loc.line && !o.element.empty()) {
                element = o.element;
                break;
            }
    if (format == DiagnosticFormat::Json) {
        nlohmann::ordered_json j;
        j["code"] = fault.code;
        j["severity"] = "runtime error";
        const Where w = st ? locate(sources, fault.loc) : Where{};
        j["file"] = st ? w.path : fault.where.substr(0, fault.where.find(':'));
        j["line"] = st ? w.line : std::max(fault.loc.line, 1);
        j["column"] = st ? w.col : std::max(fault.loc.col, 1);
        j["task"] = fault.task;
        j["message"] = fault.message;
        j["notes"] = nlohmann::ordered_json::array();
        if (!element.empty()) j["notes"].push_back({{"message", "in " + element}});
        j["suggestions"] = nlohmann::ordered_json::array();
        out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
        return;
    }
    Style style;
    style.on = color;
    out << style.paint(kBold, fault.where + ':') << ' ' << style.paint(kRed, "runtime error:") << ' '
        << style.paint(kBold, fault.code + " in " + fault.task + ": " + fault.message) << '\n';
    if (!element.empty()) out << style.paint(kCyan, "note:") << " in " << element << '\n';
    if (!st) return;
    const Where w = locate(sources, fault.loc);
    const Excerpt e = excerptFor(w, nullptr);
    printExcerpt(out, e, style, kRed, '^', std::to_string(e.line).size());
}

bool stderrWantsColor(ColorMode mode) { return fdWantsColor(mode, STDERR_FILENO); }

bool fdWantsColor(ColorMode mode, int fd) {
    if (mode == ColorMode::Always) return true;
    if (mode == ColorMode::Never) return false;
    const char* noColor = std::getenv("NO_COLOR");
    if (noColor && *noColor) return false;
    const char* term = std::getenv("TERM");
    if (term && std::strcmp(term, "dumb") == 0) return false;
    return isatty(fd) == 1;
}

std::vector<Diagnostic> shownDiagnostics(const CompileLog& log, const SourceSet& sources, const DiagnosticOptions& options) {
    std::vector<Diagnostic> shown;
    shown.reserve(log.messages().size());
    for (const Diagnostic& d : log.messages()) {
        Diagnostic copy = d;
        // ST made from an LD/FBD/SFC element: the note names the element (`rung 3, contact 'bStart'`).
        if (d.loc.file >= 0 && d.loc.file < sources.size()) {
            const std::string& element = sources.file(d.loc.file).element(d.loc.line);
            if (!element.empty()) copy.notes.insert(copy.notes.begin(), DiagnosticNote{std::nullopt, "in " + element});
        }
        if (copy.severity == Severity::Warning) {
            auto it = options.levels.find(copy.code);
            const WarningLevel level = it != options.levels.end() ? it->second
                                       : options.warningsAreErrors ? WarningLevel::Error
                                                                   : WarningLevel::Warning;
            if (level == WarningLevel::Off) continue;
            if (level == WarningLevel::Error) copy.severity = Severity::Error;
        }
        shown.push_back(std::move(copy));
    }
    // By file (in the order the project lists them) and position in the file the user has.
    auto key = [&](const Diagnostic& d) {
        const Where w = locate(sources, d.loc);
        return std::make_tuple(d.loc.file, w.line, w.col);
    };
    std::stable_sort(shown.begin(), shown.end(), [&](const Diagnostic& a, const Diagnostic& b) { return key(a) < key(b); });
    shown.erase(std::unique(shown.begin(), shown.end(),
                            [](const Diagnostic& a, const Diagnostic& b) {
                                return a.severity == b.severity && a.loc.file == b.loc.file && a.loc.line == b.loc.line &&
                                       a.loc.col == b.loc.col && a.message == b.message;
                            }),
                shown.end());
    return shown;
}

bool printDiagnostics(const CompileLog& log, const SourceSet& sources, const DiagnosticOptions& options, std::ostream& out,
                      bool colorTerminal) {
    const std::vector<Diagnostic> shown = shownDiagnostics(log, sources, options);
    Style style;
    style.on = colorTerminal;
    bool errors = false;
    for (const Diagnostic& d : shown) {
        errors = errors || d.severity == Severity::Error;
        if (options.format == DiagnosticFormat::Json) printJson(out, d, sources);
        else printText(out, d, sources, style);
    }
    if (log.droppedCount() > 0 && options.format == DiagnosticFormat::Text)
        out << "note: " << log.droppedCount() << " further messages suppressed\n";
    return errors || log.hasErrors();
}

}  // namespace strun::cli
