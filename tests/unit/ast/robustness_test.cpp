// Robustness: pathological input gets errors, never a crash, hang or throw.
#include <catch2/catch.hpp>

#include <chrono>
#include <random>

#include "interpreter/ast/nesting_guard.h"
#include "interpreter/ast/syntax_errors.h"
#include "parse_test_support.h"

using namespace strun::ast;
using strun::ast::test::parse;

namespace {

std::string repeat(const std::string& s, size_t n) {
    std::string out;
    out.reserve(s.size() * n);
    for (size_t i = 0; i < n; ++i) out += s;
    return out;
}

bool mentions(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

}  // namespace

TEST_CASE("robustness: 100 000 nested parentheses", "[robust]") {
    auto p = parse("PROGRAM P\nx := " + repeat("(", 100000) + "1" + repeat(")", 100000) + ";\nEND_PROGRAM\n");
    REQUIRE(p->log.errorCount() == 1);
    CHECK(mentions(p->errors(), "2:506: syntax error: nesting too deep"));
}

TEST_CASE("robustness: 10 000 nested IFs", "[robust]") {
    auto p = parse("PROGRAM P\n" + repeat("IF a THEN\n", 10000) + "x := 1;\n" + repeat("END_IF\n", 10000) +
                   "END_PROGRAM\n");
    REQUIRE(p->log.errorCount() == 1);
    CHECK(mentions(p->errors(), "502:1: syntax error: nesting too deep"));
}

TEST_CASE("robustness: deep but reasonable nesting still parses", "[robust]") {
    const int depth = 200;
    auto p = parse("PROGRAM P\n" + repeat("IF a THEN\n", depth) + "x := " + repeat("(", depth) + "1" +
                   repeat(")", depth) + ";\n" + repeat("END_IF\n", depth) + "END_PROGRAM\n");
    REQUIRE(p->errors() == "");
    const Stmt* s = p->unit.pous.at(0)->body.at(0).get();
    for (int i = 1; i < depth; ++i) s = s->blocks.at(0).at(0).get();
    CHECK(dump(*s) == "(if a {(:= x 1)})");
}

TEST_CASE("robustness: long operator chains", "[robust]") {
    auto unary = parse("PROGRAM P\nx := " + repeat("- ", 200000) + "1;\nEND_PROGRAM\n");
    CHECK(mentions(unary->errors(), "nesting too deep"));

    auto sum = parse("PROGRAM P\nx := 1" + repeat(" + 1", 100000) + ";\nEND_PROGRAM\n");
    CHECK(sum->errors() == "2:6: syntax error: expression too complex: more than 2000 nested operations\n");

    auto chain = parse("PROGRAM P\nx := a" + repeat(".b", 100000) + ";\nEND_PROGRAM\n");
    CHECK(chain->errors() == "2:6: syntax error: expression too complex: more than 2000 nested operations\n");

    auto types = parse("TYPE T : " + repeat("ARRAY[1..2] OF ", 100000) + "INT; END_TYPE\n");
    CHECK(mentions(types->errors(), "nesting too deep"));

    auto ok = parse("PROGRAM P\nx := 1" + repeat(" + 1", 1000) + ";\nEND_PROGRAM\n");
    CHECK(ok->errors() == "");
}

TEST_CASE("robustness: random bytes and random tokens", "[robust]") {
    std::mt19937 rng(12345);
    for (int round = 0; round < 5; ++round) {
        std::string bytes(20000, '\0');
        for (char& c : bytes) c = static_cast<char>(rng() & 0xFF);
        auto p = parse(bytes);
        CHECK(p->log.hasErrors());
        CHECK(p->log.errorCount() <= SyntaxErrorReporter::kMaxErrorsPerFile + 1);
    }
    const std::vector<std::string> words = {"IF", "THEN", "(", ")", ":=", "x", "1", ";", "END_IF", "PROGRAM",
                                            "VAR", "END_VAR", "CASE", "OF", ":", "[", "]", "FOR", "TO", "'s'",
                                            "T#1s", "{p}", "(*c*)", "METHOD", "END_PROGRAM", ".", "^", "=>"};
    for (int round = 0; round < 5; ++round) {
        std::string text;
        for (int i = 0; i < 5000; ++i) text += words[rng() % words.size()] + (rng() % 8 == 0 ? "\n" : " ");
        auto p = parse(text);
        CHECK(p->log.hasErrors());
    }
}

TEST_CASE("robustness: empty and trivial files", "[robust]") {
    auto empty = parse("");
    CHECK(empty->errors() == "");
    CHECK(empty->unit.pous.empty());
    CHECK(parse("   \n\t\n")->errors() == "");
    CHECK(parse("(* only a comment *)")->errors() == "");
    CHECK(parse(std::string("\0\0", 2))->log.hasErrors());
}

// 3 MB: under the limit of 2 000 000 tokens per file (issue 12, docs/limits.md).
TEST_CASE("robustness: 3 MB of valid statements parse in reasonable time", "[robust][slow]") {
    const std::vector<std::string> statements = {
        "x := x + 1;",
        "IF x > 10 THEN x := 0; ELSE y := y * 2 + a[3]; END_IF",
        "a[i MOD 10] := f(x, y, IN := 3);",
        "FOR i := 0 TO 9 DO a[i] := i * i; END_FOR",
        "CASE x OF 1: y := 1; 2..5: y := 2; ELSE y := 0; END_CASE",
    };
    std::string text = "PROGRAM Big\nVAR x, y, i : INT; a : ARRAY[0..9] OF INT; END_VAR\n";
    size_t count = 0;
    while (text.size() < 3'000'000) {
        text += statements[count % statements.size()] + "\n";
        ++count;
    }
    text += "END_PROGRAM\n";
    const auto start = std::chrono::steady_clock::now();
    auto p = parse(text);
    const auto seconds =
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start).count();
    CHECK(p->errors() == "");
    REQUIRE(p->unit.pous.size() == 1);
    CHECK(p->unit.pous[0]->body.size() == count);
    CHECK(seconds < 60);  // typically 5 s on a loaded 2-core machine
}

TEST_CASE("robustness: a 5000-digit literal parses (its range is the checker's business)", "[robust]") {
    auto p = parse("PROGRAM P\nx := " + std::string(5000, '9') + ";\nEND_PROGRAM\n");
    CHECK(p->errors() == "");
    CHECK(p->unit.pous.at(0)->body.at(0)->expr->text.size() == 5000);
}

TEST_CASE("robustness: an invalid file index is an error, not an exception", "[robust]") {
    strun::SourceSet sources;
    strun::CompileLog log;
    auto unit = parseFile(sources, 3, log);
    CHECK(log.hasErrors());
    CHECK(unit.pous.empty());
}
