// Lookup, classification and the two page formats of the catalogue.
#include "interpreter/source/diagnostic_codes.h"

#include <regex>

#include "interpreter/source/diagnostic.h"

namespace strun::diagnostics {

namespace {

// A message's wording -> its code, first match wins. The sites that report
// a message of their own kind give the code themselves (Diagnostic::withCode);
// these rules cover the checker's many sites, grouped by kind of mistake.
struct Rule {
    const char* code;
    const char* pattern;
};

const Rule kErrorRules[] = {
    {"E0004", "^syntax error: ST has no"},
    {"E0005", "^syntax error: unterminated"},
    {"E0006", "^syntax error: unexpected (character|byte|control character)"},
    {"E0007", "^syntax error: (too many errors|.*nested more than|.*more than [0-9]+ (levels|tokens))"},
    {"E0003", "^syntax error: .*(expected 'END_[A-Z_]+'$|has no matching 'END_)"},
    {"E0002", "^syntax error: (expected ';'|.*, expected ';'$)"},
    {"E0001", "^syntax error: "},
    {"E0007", "more than [0-9]+ tokens|too complex|nested more than|too large|above 256 MiB|declarations nested"},
    {"E0008", "not well-formed XML|not a PLCopen|has a body in|^no (POU|PROGRAM)|XML|^task object|^in the (LD|FBD|SFC) (body|chart) of"},
    {"E0009", "^only VAR_GLOBAL is allowed|can only be declared in a TYPE|^ACTION '|access path|is not a simple name|"
              "^unknown assignment operator|has no body|accessor of property|has more than one (GET|SET)|"
              "READ_ONLY|READ_WRITE|cannot have an ACTION"},
    {"E0602", "exists only with --target|not available on|is not maintained"},
    {"E0101", "^undeclared identifier"},
    {"E0102", "^unknown type|^unknown function block '.*' in EXTENDS"},
    {"E0104", "is not a value of"},
    {"E0105", "^undeclared function"},
    {"E0106", "^duplicate (declaration|global|member|method|property|type|variable|enumeration|program instance)"},
    {"E0108", "is a value of several enumerations|qualified_only|declared in several global lists"},
    {"E0109", "is an internal variable of|is PRIVATE|is PROTECTED in|only available inside a function block"},
    {"E0304", "is a function-block instance: call it"},
    {"E0107", "is a POU, not a variable|is a function, not a type|is a variable, not a function|cannot be called|"
              "is not a PROGRAM|is not a global function-block instance|is a type and"},
    {"E0103", "has no member|is not a member|does not exist in|has no property|is not a method of"},
    {"E0303", "connect it with"},
    {"E0302", "has no parameter|has no output|given twice|either all by position or all by name"},
    {"E0301", "too (few|many) arguments|needs [0-9]+ input|is missing its input|needs the input|must be connected|"
              "needs at least|takes exactly|takes one|has no value|missing argument value|takes an array and|"
              "takes a source and"},
    {"E0501", "outside a loop"},
    {"E0502", "FOR control variable"},
    {"E0503", "CASE"},
    {"E0504", "label"},
    {"E0403", "contains itself|in terms of itself|inheritance cycle"},
    {"E0406", "VAR_EXTERNAL"},
    {"E0408", "direct address|system address"},
    {"E0407", "ARRAY\\[\\*\\]|upper bound|subrange needs|base type of an enumeration|can only extend a structure|"
              "string length|EXTENDS in a TYPE|would follow the largest LINT"},
    {"E0401", "must be a constant|needs an initial value|initial value must be a constant|cannot be initialised with"},
    {"E0402", "initialiser for a variable|too many initial values"},
    {"E0205", "is outside the range of"},
    {"E0203", "must be BOOL, not"},
    {"E0204", "subscript|dimension\\(s\\)|not an array"},
    {"E0207", "^bit |partial access|bit access"},
    {"E0206", "left side of ':='|not a statement|needs a variable|can be written|^REF= needs a REFERENCE|"
              "needs an interface variable|^'.*' is [A-Z_ ]+: it needs a variable"},
    {"E0202", "^operator |needs numbers|needs BOOL operands|needs BOOL or bit-string|cannot compare|^MOD |^NOT |"
              "^unary|is not defined for|both operands must be|need an explicit conversion|cannot mix|"
              "cannot be compared|multiplied or divided|of durations or dates|needs a BOOL input|needs a REAL|"
              "must be all BOOL|unsupported operator|needs integers"},
    {"E0601", "task|TASK|time event|CONFIGURATION|RESOURCE|EDGE must|REPEAT must|^AT needs|EXTERNAL|constant duration|"
              "global BOOL variable|program instance|interval|priority|watchdog|unknown input"},
    {"E0405", "EXTENDS|ABSTRACT|FINAL|IMPLEMENTS|SUPER|THIS|does not implement|signature|method|property|PROPERTY|"
              "interface|INTERFACE|SET accessor|__QUERYINTERFACE|\\?="},
    {"E0201", "cannot convert|no conversion|cannot assign|initial value of type|the argument is|expected an? |"
              "string lengths differ|needs an array|must be a STRING|, not |__ISVALIDREF|'\\^' needs"},
};

const Rule kWarningRules[] = {
    {"W0001", "^implicit conversion"},
    {"W0002", "does not fit .*; it wraps to"},
    {"W0003", "^variable '.*' is never used"},
    {"W0004", "never assigns its result"},
    {"W0005", "beyond the largest LTIME"},
    {"W0041", "beyond the largest TIME "},
    {"W0040", "^an empty declaration"},
    {"W0006", "not valid UTF-8"},
    {"W0007", "is fixed at .* is ignored"},
    {"W0008", "is larger than the [0-9]+-byte address"},
    {"W0009", "is not maintained by strun"},
};

struct Compiled {
    std::string code;
    std::regex pattern;
};

template <size_t N>
std::vector<Compiled> compileRules(const Rule (&rules)[N]) {
    std::vector<Compiled> out;
    for (const Rule& r : rules) out.push_back({r.code, std::regex(r.pattern, std::regex::ECMAScript | std::regex::optimize)});
    return out;
}

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    return out;
}

const char* kindWord(Kind k) {
    switch (k) {
        case Kind::Error: return "error";
        case Kind::Warning: return "warning";
        case Kind::Runtime: return "runtime fault";
    }
    return "";
}

std::string indent(std::string_view text, const char* prefix) {
    std::string out = prefix;
    for (char c : text) {
        out += c;
        if (c == '\n') out += prefix;
    }
    return out;
}

}  // namespace

const CodeInfo* find(std::string_view code) {
    const std::string wanted = upper(code);
    for (const CodeInfo& info : catalogue())
        if (info.code == wanted) return &info;
    return nullptr;
}

std::string classify(Severity severity, const std::string& message) {
    // Compile-time code only (never on the execution path): regexes are fine here.
    static const std::vector<Compiled> errorRules = compileRules(kErrorRules);
    static const std::vector<Compiled> warningRules = compileRules(kWarningRules);
    const bool isError = severity == Severity::Error;
    // A --strict error keeps the code of the warning it comes from.
    for (const Compiled& r : warningRules)
        if ((!isError || r.code == "W0001" || r.code == "W0002") && std::regex_search(message, r.pattern)) return r.code;
    if (!isError) return "W0999";
    for (const Compiled& r : errorRules)
        if (std::regex_search(message, r.pattern)) return r.code;
    return "E0999";
}

std::string markdownPage(const CodeInfo& info) {
    std::string out = "# " + std::string(info.code) + ": " + std::string(info.title) + "\n\n";
    out += "Kind: " + std::string(kindWord(info.kind));
    if (info.kind == Kind::Warning) out += " (silence it with `-W no-" + std::string(info.code) + "`, make it an error with `-W " + std::string(info.code) + "=error`)";
    out += "\n\n" + std::string(info.explanation) + "\n";
    if (!info.wrong.empty()) out += "\n## Wrong\n\n```\n" + std::string(info.wrong) + "\n```\n";
    if (!info.right.empty()) out += "\n## Right\n\n```\n" + std::string(info.right) + "\n```\n";
    out += "\nThis page is generated from `interpreter/source/diagnostic_catalogue.cpp`; `strun explain " +
           std::string(info.code) + "` prints it.\n";
    return out;
}

std::string textPage(const CodeInfo& info) {
    std::string out = std::string(info.code) + ": " + std::string(info.title) + " (" + kindWord(info.kind) + ")\n\n";
    out += std::string(info.explanation) + "\n";
    if (!info.wrong.empty()) out += "\nWrong:\n\n" + indent(info.wrong, "    ") + "\n";
    if (!info.right.empty()) out += "\nRight:\n\n" + indent(info.right, "    ") + "\n";
    return out;
}

std::string markdownIndex() {
    std::string out =
        "# Diagnostic codes\n\n"
        "Every compile diagnostic ends with its code, `m.st:4:5: error: undeclared identifier 'bButon' [E0101]`;\n"
        "runtime faults carry theirs in the diagnostic buffer. `strun explain CODE` prints a code's page.\n"
        "These pages are generated from `interpreter/source/diagnostic_catalogue.cpp` (the ctest\n"
        "`diagnostics.docs_in_sync` fails when they differ; `build/tests/diagnostic_docs --write docs/diagnostics`\n"
        "regenerates them).\n\n"
        "| code | kind | meaning |\n|---|---|---|\n";
    for (const CodeInfo& info : catalogue())
        out += "| [" + std::string(info.code) + "](" + std::string(info.code) + ".md) | " + kindWord(info.kind) + " | " +
               std::string(info.title) + " |\n";
    return out;
}

}  // namespace strun::diagnostics
