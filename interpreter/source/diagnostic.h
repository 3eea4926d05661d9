// One compile diagnostic: a code (docs/diagnostics/<CODE>.md), a severity, the
// primary location (optionally with the end of its span), the message, and
// the notes (secondary locations) and help lines a renderer prints under the
// source excerpt (cli/diagnostic_render.*). The first line of every rendering
// stays `FILE:LINE:COL: error: MESSAGE [CODE]`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "interpreter/ast/ast.h"

namespace strun {

enum class Severity { Error, Warning };

struct DiagnosticNote {
    std::optional<ast::Loc> loc;  // none: a note about the message as a whole
    std::string text;
};

struct Diagnostic {
    Severity severity = Severity::Error;
    ast::Loc loc;
    std::string message;
    std::string code;  // E0101, W0003, ...: the one the reporting site gave (diagnostic_code.h)
    // The span's end (same file), exclusive column; 0: the renderer underlines
    // the token at `loc`.
    int endLine = 0;
    int endCol = 0;
    std::vector<DiagnosticNote> notes;
    std::vector<std::string> help;

    // Chained by the reporting sites: log.error(diag::E0101, loc, msg).note(at, "...").withHelp("...").
    Diagnostic& note(const ast::Loc& at, std::string text) {
        notes.push_back({at, std::move(text)});
        return *this;
    }
    Diagnostic& note(std::string text) {
        notes.push_back({std::nullopt, std::move(text)});
        return *this;
    }
    Diagnostic& withHelp(std::string text) {
        help.push_back(std::move(text));
        return *this;
    }
    Diagnostic& spanTo(int line, int col) {
        endLine = line;
        endCol = col;
        return *this;
    }
};

// The older name, kept for the many places that only read loc/message/severity.
using CompileMessage = Diagnostic;

}  // namespace strun
