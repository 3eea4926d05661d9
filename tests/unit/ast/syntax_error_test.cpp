// Syntax errors: location, wording, recovery, one message per line.
#include <catch2/catch.hpp>

#include "interpreter/ast/syntax_errors.h"
#include "parse_test_support.h"

using namespace strun::ast;
using strun::ast::test::parse;

TEST_CASE("syntax errors: what was found and what was expected", "[errors]") {
    // A missing ';' is reported right after the token it should follow (issue 13).
    CHECK(parse("PROGRAM P\nIF a THEN\n  x := 1\nEND_IF\nEND_PROGRAM")->errors() ==
          "3:9: syntax error: expected ';' after 'x := 1'\n");
    CHECK(parse("PROGRAM P\nx := ;\nEND_PROGRAM")->errors() ==
          "2:6: syntax error: unexpected ';', expected an expression\n");
    CHECK(parse("PROGRAM P\nWHILE x DO\n  x := 1;\nEND_FOR\nEND_PROGRAM")->errors() ==
          "4:1: syntax error: unexpected 'END_FOR', expected 'END_WHILE'\n");
    // A missing END_ is reported at what it should close, with a note where it was expected (issue 13).
    auto unclosed = parse("PROGRAM P\nx := 1;\n");
    CHECK(unclosed->errors() == "1:1: syntax error: 'PROGRAM' has no matching 'END_PROGRAM'\n");
    REQUIRE(unclosed->log.messages().size() == 1);
    REQUIRE(unclosed->log.messages()[0].notes.size() == 1);
    CHECK(unclosed->log.messages()[0].notes[0].text == "'END_PROGRAM' expected before end of file");
    CHECK(unclosed->log.messages()[0].notes[0].loc->line == 3);
    CHECK(parse("TYPE X : ; END_TYPE")->errors() == "1:10: syntax error: unexpected ';', expected a type\n");
    CHECK(parse("VAR_GLOBAL a INT; END_VAR")->errors() ==
          "1:14: syntax error: unexpected 'INT', expected 'AT', ',' or ':'\n");
    CHECK(parse("PROGRAM P\nFOR i := 1 TO DO END_FOR\nEND_PROGRAM")->errors() ==
          "2:15: syntax error: unexpected 'DO', expected an expression\n");
}

TEST_CASE("syntax errors: checks made while building the tree", "[errors]") {
    CHECK(parse("PROGRAM P\nx Q= 2;\nEND_PROGRAM")->errors() ==
          "2:3: syntax error: unknown assignment operator 'Q=', expected ':=', 'S=', 'R=', 'REF=' or '?='\n");
    CHECK(parse("PROGRAM P\n  x = 1;\nEND_PROGRAM")->errors() ==
          "2:3: syntax error: 'x = 1' is not a statement: expected ':=' or a call with '(...)' (for an "
          "assignment write ':=', not '=')\n");
    CHECK(parse("PROGRAM P\nfb;\nEND_PROGRAM")->errors() ==
          "2:1: syntax error: 'fb' is not a statement: expected ':=' or a call with '(...)'\n");
    CHECK(parse("PROGRAM P\nVAR a.b : INT; END_VAR\nEND_PROGRAM")->errors() ==
          "2:5: syntax error: 'a.b' is not a simple name; paths are only allowed in VAR_CONFIG\n");
    CHECK(parse("TYPE T EXTENDS B : INT; END_TYPE")->errors() ==
          "1:6: syntax error: EXTENDS in a TYPE is only allowed for a STRUCT ('T')\n");
}

TEST_CASE("syntax errors: parsing goes on and reports later errors", "[errors]") {
    auto p = parse(
        "PROGRAM P\n"
        "x := ;\n"
        "y := 1 + ;\n"
        "z := 3;\n"
        "IF a THEN b := 1 END_IF\n"
        "END_PROGRAM\n"
        "FUNCTION F : INT\n"
        "F := (1 + 2;\n"
        "END_FUNCTION\n");
    CHECK(p->errors() ==
          "2:6: syntax error: unexpected ';', expected an expression\n"
          "3:10: syntax error: unexpected ';', expected an expression\n"
          "5:18: syntax error: unexpected 'END_IF', expected ';'\n"
          "8:12: syntax error: unexpected ';', expected ')'\n");
    // The good parts are still there.
    REQUIRE(p->unit.pous.size() == 2);
    CHECK(p->unit.pous[1]->name == "F");
    bool sawZ = false;
    for (const auto& s : p->unit.pous[0]->body)
        if (s->kind == StmtKind::Assign && s->target->name == "z") sawZ = true;
    CHECK(sawZ);
}

TEST_CASE("syntax errors: at most one per line, and a cap per file", "[errors]") {
    auto p = parse("PROGRAM P\nx := ) ) ) ) ;\nEND_PROGRAM");
    CHECK(p->log.errorCount() == 1);

    std::string many = "PROGRAM P\n";
    for (int i = 0; i < 300; ++i) many += "x := ;\n";
    many += "END_PROGRAM\n";
    auto m = parse(many);
    CHECK(m->log.errorCount() == SyntaxErrorReporter::kMaxErrorsPerFile + 1);
    CHECK(m->log.messages().back().message == "syntax error: too many errors in this file, the rest are not reported");
}

TEST_CASE("syntax errors: lexical errors at their opening location", "[errors]") {
    CHECK(parse("PROGRAM P\nx := 1;\n  (* open (* nested *) never closed\nEND_PROGRAM\n")->errors() ==
          "3:3: syntax error: unterminated comment: '(*' has no matching '*)'\n");  // and nothing it swallowed (issue 13)
    CHECK(parse("PROGRAM P\n/* open\nEND_PROGRAM\n")->errors().rfind(
              "2:1: syntax error: unterminated comment: '/*' has no matching '*/'\n", 0) == 0);
    CHECK(parse("{attribute 'x'\nPROGRAM P END_PROGRAM")->errors().rfind(
              "1:1: syntax error: unterminated pragma: '{' has no matching '}'\n", 0) == 0);
    CHECK(parse("PROGRAM P\nx := 'abc;\nEND_PROGRAM")->errors().rfind(
              "2:6: syntax error: unterminated string literal: missing closing ' on this line\n", 0) == 0);
    CHECK(parse("PROGRAM P\nx := \"abc;\nEND_PROGRAM")->errors().rfind(
              "2:6: syntax error: unterminated string literal: missing closing \" on this line\n", 0) == 0);
    CHECK(parse("PROGRAM P\nx := 1 ` 2;\nEND_PROGRAM")->errors().rfind(
              "2:8: syntax error: unexpected character '`'\n", 0) == 0);
    CHECK(parse(std::string("PROGRAM P\nx := 1;\x01\nEND_PROGRAM"))->errors() ==
          "2:8: syntax error: unexpected control character (code 1)\n");
}

TEST_CASE("syntax errors: the location names the file being parsed", "[errors]") {
    strun::SourceSet sources;
    sources.add("a.st", "PROGRAM A END_PROGRAM");
    int second = sources.add("b.st", "PROGRAM B\nx := ;\nEND_PROGRAM");
    strun::CompileLog log;
    auto unit = parseFile(sources, second, log);
    CHECK(unit.file == 1);
    REQUIRE(log.messages().size() == 1);
    CHECK(log.messages()[0].loc.file == 1);
    std::ostringstream out;
    log.print(out, sources);
    CHECK(out.str() == "b.st:2:6: error: syntax error: unexpected ';', expected an expression\n");
    CHECK(unit.pous.at(0)->loc.file == 1);
}

TEST_CASE("syntax errors: invalid UTF-8 is a warning, a byte-order mark is fine", "[errors]") {
    auto latin1 = parse("PROGRAM P\nx := 'caf\xE9';\nEND_PROGRAM");
    CHECK_FALSE(latin1->log.hasErrors());
    REQUIRE(latin1->log.messages().size() == 1);
    CHECK(latin1->log.messages()[0].severity == strun::Severity::Warning);
    CHECK(latin1->log.messages()[0].loc.line == 2);
    CHECK(latin1->log.messages()[0].loc.col == 10);
    auto bom = parse("\xEF\xBB\xBFPROGRAM P\nEND_PROGRAM");
    CHECK(bom->errors() == "");
    CHECK(bom->unit.pous.at(0)->loc.col == 1);
}

TEST_CASE("syntax errors: the code says the kind of mistake, not the wording", "[errors]") {
    auto codeOf = [](const char* source) {
        auto parsed = parse(source);
        return parsed->log.messages().empty() ? std::string() : parsed->log.messages()[0].code;
    };
    CHECK(codeOf("PROGRAM P\nIF a THEN\n  x := 1\nEND_IF\nEND_PROGRAM") == "E0002");  // missing ';' after a statement
    CHECK(codeOf("PROGRAM P\nx := 1 y := 2;\nEND_PROGRAM") == "E0002");             // only ';' could follow
    CHECK(codeOf("PROGRAM P\nWHILE x DO\n  x := 1;\nEND_FOR\nEND_PROGRAM") == "E0003");  // only END_WHILE could
    CHECK(codeOf("PROGRAM P\nx := 1;\n") == "E0003");                                 // PROGRAM never closed
    CHECK(codeOf("PROGRAM P\nx := ;\nEND_PROGRAM") == "E0001");
    CHECK(codeOf("PROGRAM P\nx++;\nEND_PROGRAM") == "E0004");
    CHECK(codeOf("PROGRAM P\nx := 'abc\nEND_PROGRAM") == "E0005");
    CHECK(codeOf("PROGRAM P\nx := 1 ` 2;\nEND_PROGRAM") == "E0006");
    // Built while making the tree: declarations in the wrong place are E0009, whatever the wording.
    CHECK(codeOf("VAR x : INT; END_VAR") == "E0009");
    CHECK(codeOf("PROGRAM P\nVAR a.b : INT; END_VAR\nEND_PROGRAM") == "E0009");
    CHECK(codeOf("TYPE T EXTENDS U : INT; END_TYPE") == "E0407");
}
