#include "interpreter/project/syntax_recovery.h"

namespace strun::project {

namespace {

// Syntax error codes after which the recovered tree is trustworthy.
bool isLocal(const std::string& code) { return code == "E0001" || code == "E0002" || code == "E0003" || code == "E0004" || code == "E0006"; }

bool isSyntaxError(const Diagnostic& d) { return d.severity == Severity::Error && d.message.rfind("syntax error: ", 0) == 0; }

// Past this many syntax errors a file is too broken for its checks to help.
constexpr size_t kMaxLocalErrors = 10;

}  // namespace

SyntaxDamage assessSyntaxErrors(const CompileLog& log) {
    SyntaxDamage damage;
    size_t count = 0;
    for (const Diagnostic& d : log.messages()) {
        if (d.severity != Severity::Error) continue;
        // Errors of the input stage (XML, file limits) or the AST builder's own: no semantic checks.
        if (d.code == "E0010") continue;  // an {error '...'} pragma: the source itself is fine
        if (!isSyntaxError(d) && d.code != "E0004" && d.code != "E0009") damage.checkable = false;
        if (isSyntaxError(d) && !isLocal(d.code)) damage.checkable = false;
        damage.lines.insert({d.loc.file, d.loc.line});
        for (const DiagnosticNote& n : d.notes) {
            if (n.loc) damage.lines.insert({n.loc->file, n.loc->line});
            // "the declaration of 'x' on the next line is skipped ...": x's uses are no news.
            const std::string marker = "the declaration of '";
            if (n.text.rfind(marker, 0) == 0) {
                const size_t end = n.text.find('\'', marker.size());
                if (end != std::string::npos) damage.skippedNames.insert(n.text.substr(marker.size(), end - marker.size()));
            }
        }
        damage.files.insert(d.loc.file);
        ++count;
    }
    if (count > kMaxLocalErrors || log.droppedCount() > 0) damage.checkable = false;
    return damage;
}

void dropSyntaxCascades(CompileLog& log, const SyntaxDamage& damage) {
    log.eraseIf([&](const Diagnostic& d) {
        if (isSyntaxError(d) || d.code == "E0004" || d.code == "E0009") return false;
        if (!damage.files.count(d.loc.file)) return false;
        if (d.loc.line <= 0 || damage.lines.count({d.loc.file, d.loc.line})) return true;
        for (const std::string& name : damage.skippedNames)
            if (d.message == "undeclared identifier '" + name + "'") return true;
        return d.code == "W0003" || d.code == "W0004";
    });
}

}  // namespace strun::project
