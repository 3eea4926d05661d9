// A large file parsed in two halves on two threads (parse_in_halves.h) gives
// the AST and the messages of the parse in one piece (decision 0159).
#include <catch2/catch.hpp>

#include <cstdint>
#include <sstream>
#include <string>

#include "interpreter/ast/action_keyword.h"
#include "interpreter/ast/ast_dump.h"
#include "interpreter/ast/parse.h"
#include "interpreter/ast/parse_in_halves.h"

namespace {

using namespace strun;
using namespace strun::ast;

// A project of `blocks` function blocks (with pragmas, comments, an action
// after each, a method), functions, types, a namespace and a program.
// `breakAt` goes into the code of block `breakBlock`.
std::string project(int blocks, const std::string& breakAt = "", int breakBlock = -1) {
    std::ostringstream out;
    out << "NAMESPACE Lib\nFUNCTION Half : INT VAR_INPUT x : INT; END_VAR Half := x / 2; END_FUNCTION\nEND_NAMESPACE\n";
    for (int k = 0; k < blocks; ++k) {
        out << "(* block " << k << " *)\n{attribute 'block'}\nFUNCTION_BLOCK Block" << k << "\n"
            << "VAR_INPUT go : BOOL; END_VAR VAR_OUTPUT n : INT; END_VAR VAR s : INT; h : ARRAY[0..3] OF INT; END_VAR\n"
            << "CASE s OF 0: IF go THEN s := 1; END_IF; 1, 2: n := n + 1; s := " << (k == breakBlock ? breakAt : "") << "0; ELSE s := 0; END_CASE\n"
            << "FOR s := 0 TO 2 DO h[s] := h[s + 1] * 2; END_FOR;\n"
            << "METHOD Reset : BOOL n := 0; Reset := TRUE; END_METHOD\n"
            << "END_FUNCTION_BLOCK\n"
            << "ACTION Clear: n := 0; END_ACTION\n"
            << "TYPE Pair" << k << " : STRUCT a, b : INT := " << k << "; END_STRUCT END_TYPE\n"
            << "FUNCTION Scale" << k << " : DINT VAR_INPUT raw : DINT; END_VAR Scale" << k << " := raw * " << k << " / 100; END_FUNCTION\n";
    }
    out << "PROGRAM Main VAR b0 : Block0; t : INT; END_VAR b0(go := TRUE); t := Lib.Half(x := t); END_PROGRAM\n";
    return out.str();
}

std::string summary(const CompilationUnit& unit) {
    std::ostringstream out;
    for (const auto& p : unit.pous) {
        out << static_cast<int>(p->kind) << ' ' << p->nameSpace << '.' << p->name << " @" << p->loc.line << ':' << p->loc.col
            << " pragmas " << p->pragmas.size() << " vars " << p->vars.size() << ' ' << dump(p->body) << '\n';
        for (const auto& m : p->methods) out << "  " << m->name << (m->isAction ? " action " : " ") << dump(m->body) << '\n';
    }
    for (const auto& t : unit.types) out << "type " << t.name << " @" << t.loc.line << ' ' << (t.spec ? dump(*t.spec) : "") << '\n';
    out << unit.globals.size() << ' ' << unit.configurations.size() << ' ' << unit.usings.size();
    return out.str();
}

struct Result {
    std::string unit, messages;
};

Result parseWith(const std::string& text, std::size_t halvesFrom) {
    SourceSet sources;
    CompileLog log;
    const int file = sources.add("big.st", text);
    const CompilationUnit unit = parseFile(sources, file, log, halvesFrom);
    std::ostringstream messages;
    for (const auto& m : log.messages()) messages << m.loc.line << ':' << m.loc.col << ' ' << m.message << '\n';
    return {summary(unit), messages.str()};
}

}  // namespace

TEST_CASE("a file parsed in two halves gives the AST of one piece", "[parser][halves]") {
    const std::string text = project(40);
    ScanResult scan = scanSource(text, kMaxTokensPerFile);
    resolveActionKeyword(scan.tokens);
    const auto halves = parseInHalves(text, scan.tokens, 0);
    REQUIRE(halves.has_value());  // the file does split
    CHECK(halves->pous.size() == 1 + 40 * 2 + 1);
    const Result whole = parseWith(text, SIZE_MAX);
    const Result split = parseWith(text, 1);
    CHECK(whole.messages.empty());
    CHECK(split.messages.empty());
    CHECK(split.unit == whole.unit);
    CHECK(summary(*halves) == whole.unit);
}

TEST_CASE("a syntax error in either half gives the messages of the parse in one piece", "[parser][halves]") {
    for (const std::string& mistake : {std::string(" := "), std::string("1 + ; x "), std::string("IF ")})
    for (int block : {1, 38}) {
        const std::string text = project(40, mistake, block);
        const Result whole = parseWith(text, SIZE_MAX);
        const Result split = parseWith(text, 1);
        CHECK_FALSE(whole.messages.empty());
        CHECK(split.messages == whole.messages);
        CHECK(split.unit == whole.unit);
    }
}

TEST_CASE("a file without a split point between declarations is parsed in one piece", "[parser][halves]") {
    std::string text = "PROGRAM Main VAR x : INT; END_VAR\n";
    for (int i = 0; i < 3000; ++i) text += "x := x + 1;\n";
    text += "END_PROGRAM\n";
    ScanResult scan = scanSource(text, kMaxTokensPerFile);
    CHECK_FALSE(parseInHalves(text, scan.tokens, 0).has_value());
    CHECK(parseWith(text, 1).unit == parseWith(text, SIZE_MAX).unit);
}
