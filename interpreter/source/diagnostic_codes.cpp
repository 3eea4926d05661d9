// Lookup and the two page formats of the catalogue.
#include "interpreter/source/diagnostic_codes.h"

#include "stdlib/number_scan.h"

namespace strun::diagnostics {

namespace {

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
    const std::string wanted = stdlib::upperAscii(code);
    for (const CodeInfo& info : catalogue())
        if (info.code == wanted) return &info;
    return nullptr;
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
