// Shared helpers of the unit_ast parser tests: parse a text, show the errors.
#pragma once

#include <memory>
#include <sstream>
#include <string>

#include "interpreter/ast/ast_dump.h"
#include "interpreter/ast/parse.h"

namespace strun::ast::test {

struct Parsed {
    SourceSet sources;
    CompileLog log;
    CompilationUnit unit;

    // "LINE:COL: MESSAGE" per message, newline-separated ("" when clean).
    std::string errors() const {
        std::ostringstream out;
        for (const auto& m : log.messages()) out << m.loc.line << ':' << m.loc.col << ": " << m.message << '\n';
        return out.str();
    }
};

inline std::unique_ptr<Parsed> parse(const std::string& text, const std::string& path = "test.st") {
    auto p = std::make_unique<Parsed>();
    int index = p->sources.add(path, text);
    p->unit = parseFile(p->sources, index, p->log);
    return p;
}

// Statements of `PROGRAM P <stmts> END_PROGRAM` as dump(StmtList); the text of
// the errors instead if there are any.
inline std::string stmts(const std::string& text) {
    auto p = parse("PROGRAM P\n" + text + "\nEND_PROGRAM\n");
    if (p->log.hasErrors()) return "ERRORS: " + p->errors();
    if (p->unit.pous.size() != 1) return "NO POU";
    return dump(p->unit.pous[0]->body);
}

// The expression `text` (as the right side of an assignment) as dump(Expr).
inline std::string ex(const std::string& text) {
    auto p = parse("PROGRAM P\nx := " + text + ";\nEND_PROGRAM\n");
    if (p->log.hasErrors()) return "ERRORS: " + p->errors();
    if (p->unit.pous.size() != 1 || p->unit.pous[0]->body.size() != 1) return "NO STATEMENT";
    const auto& s = *p->unit.pous[0]->body[0];
    return s.expr ? dump(*s.expr) : "NO EXPR";
}

}  // namespace strun::ast::test
