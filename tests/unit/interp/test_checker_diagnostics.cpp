// Compile errors and warnings of the checker: each one names a file, line
// and column, and the rules about what may be assigned, read and declared.
#include <catch2/catch.hpp>

#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

namespace {

// Checks that `text` is reported once as an error at line:col of the user file.
void requireErrorAt(const Compiled& c, const std::string& text, int line, int col) {
    INFO(c.printed());
    REQUIRE_FALSE(c.ok());
    auto m = c.find(text);
    REQUIRE(m.has_value());
    CHECK(m->severity == Severity::Error);
    CHECK(m->loc.file == c.userFile);
    CHECK(m->loc.line == line);
    CHECK(m->loc.col == col);
}

}  // namespace

TEST_CASE("an error carries the file line and column of the offending text", "[checker][location]") {
    auto c = compileSt(
        "PROGRAM Main\n"
        "VAR x : INT; END_VAR\n"
        "x := 1;\n"
        "    x := undefinedThing + 1;\n"
        "END_PROGRAM\n");
    requireErrorAt(*c, "undeclared identifier 'undefinedThing'", 4, 10);
    std::ostringstream printed;
    c->log.print(printed, c->sources);
    CHECK(printed.str() == "test.st:4:10: error: undeclared identifier 'undefinedThing'\n");
}

TEST_CASE("a type mismatch is reported at the assigned value", "[checker][location]") {
    auto c = compileSt(
        "PROGRAM Main\n"
        "VAR i : INT; d : DINT; END_VAR\n"
        "  i := d;\n"
        "END_PROGRAM\n",
        true);
    requireErrorAt(*c, "implicit conversion from DINT to INT", 3, 8);
}

TEST_CASE("several errors are all reported in source order", "[checker][location]") {
    auto c = compileSt(
        "PROGRAM Main\n"
        "VAR i : INT; END_VAR\n"
        "i := a;\n"
        "i := b;\n"
        "i := TRUE;\n"
        "END_PROGRAM\n");
    INFO(c->printed());
    REQUIRE(c->errors().size() == 3);
    CHECK(c->errors()[0].loc.line == 3);
    CHECK(c->errors()[1].loc.line == 4);
    CHECK(c->errors()[2].loc.line == 5);
}

TEST_CASE("an unused variable of a function block is a warning and the project still compiles", "[checker][warning]") {
    auto c = compileSt(
        "FUNCTION_BLOCK Counter\n"
        "VAR_OUTPUT n : INT; END_VAR\n"
        "VAR spare : INT; END_VAR\n"
        "n := n + 1;\n"
        "END_FUNCTION_BLOCK\n"
        "PROGRAM Main\n"
        "VAR c : Counter; END_VAR\n"
        "c();\n"
        "END_PROGRAM\n");
    INFO(c->printed());
    REQUIRE(c->ok());
    REQUIRE(c->warnings().size() == 1);
    CHECK(c->warnings()[0].message == "variable 'spare' is never used");
    CHECK(c->warnings()[0].loc.line == 3);
    CHECK(c->warnings()[0].loc.col == 5);
    CHECK(c->errors().empty());
}

TEST_CASE("an unused local of a function is a warning", "[checker][warning]") {
    auto c = compileSt(
        "FUNCTION Twice : INT\n"
        "VAR_INPUT v : INT; END_VAR\n"
        "VAR scratch : INT; END_VAR\n"
        "Twice := v * 2;\n"
        "END_FUNCTION\n"
        "PROGRAM Main\n"
        "VAR r : INT; END_VAR\n"
        "r := Twice(4);\n"
        "END_PROGRAM\n");
    INFO(c->printed());
    REQUIRE(c->ok());
    CHECK(c->hasWarning("variable 'scratch' is never used"));
}

TEST_CASE("a function that never assigns its result gets a warning", "[checker][warning]") {
    auto c = compileSt(
        "FUNCTION Forgetful : INT\n"
        "VAR_INPUT v : INT; END_VAR\n"
        "v := v + 1;\n"
        "END_FUNCTION\n"
        "PROGRAM Main\n"
        "VAR r : INT; END_VAR\n"
        "r := Forgetful(4);\n"
        "END_PROGRAM\n");
    INFO(c->printed());
    REQUIRE(c->ok());
    auto m = c->find("function 'Forgetful' never assigns its result");
    REQUIRE(m.has_value());
    CHECK(m->severity == Severity::Warning);
    CHECK(m->loc.line == 1);
}

TEST_CASE("a clean project has neither errors nor warnings", "[checker][warning]") {
    auto c = compileSt(
        "FUNCTION Add : INT\n"
        "VAR_INPUT a, b : INT; END_VAR\n"
        "Add := a + b;\n"
        "END_FUNCTION\n"
        "PROGRAM Main\n"
        "VAR r : INT; unusedButDumped : INT; END_VAR\n"
        "r := Add(1, 2);\n"
        "END_PROGRAM\n");
    INFO(c->printed());
    REQUIRE(c->ok());
    CHECK(c->log.messages().empty());
}

TEST_CASE("duplicate names are errors", "[checker][names]") {
    auto var = compileMain("x : INT; x : DINT;", "");
    INFO(var->printed());
    CHECK(var->hasError("duplicate variable 'x' in 'Main'"));

    auto pou = compileSt("PROGRAM Main\nEND_PROGRAM\nFUNCTION_BLOCK Main\nEND_FUNCTION_BLOCK\n");
    INFO(pou->printed());
    CHECK(pou->hasError("duplicate declaration of 'Main'"));

    auto type = compileSt("TYPE T : INT; END_TYPE\nTYPE T : DINT; END_TYPE\nPROGRAM Main\nEND_PROGRAM\n");
    INFO(type->printed());
    CHECK(type->hasError("duplicate type name 'T'"));

    auto member = compileSt("TYPE S : STRUCT a : INT; a : INT; END_STRUCT; END_TYPE\nPROGRAM Main\nEND_PROGRAM\n");
    INFO(member->printed());
    CHECK(member->hasError("duplicate member 'a' in structure 'S'"));

    auto enumValue = compileSt("TYPE E : (A, B, A); END_TYPE\nPROGRAM Main\nEND_PROGRAM\n");
    INFO(enumValue->printed());
    CHECK(enumValue->hasError("duplicate enumeration value 'A'"));

    auto global = compileSt("VAR_GLOBAL g : INT; g : BOOL; END_VAR\nPROGRAM Main\nEND_PROGRAM\n");
    INFO(global->printed());
    CHECK(global->hasError("duplicate global variable 'g'"));

    auto label = compileMain("", "L1: ;\nL1: ;");
    INFO(label->printed());
    CHECK(label->hasError("duplicate label 'L1'"));

    auto caseLabel = compileMain("x : INT;", "CASE x OF 1: x := 2; 1: x := 3; END_CASE;");
    INFO(caseLabel->printed());
    CHECK(caseLabel->hasError("CASE label 1 is already used"));
}

TEST_CASE("names are case insensitive so differing case is still a duplicate", "[checker][names]") {
    auto c = compileMain("Speed : INT; SPEED : INT;", "");
    INFO(c->printed());
    CHECK(c->hasError("duplicate variable 'SPEED' in 'Main'"));
}

TEST_CASE("EXIT and CONTINUE outside a loop are errors", "[checker][statements]") {
    auto exitStmt = compileSt("PROGRAM Main\nVAR x : INT; END_VAR\nIF x = 0 THEN\n  EXIT;\nEND_IF;\nEND_PROGRAM\n");
    requireErrorAt(*exitStmt, "EXIT outside a loop", 4, 3);
    auto cont = compileMain("", "CONTINUE;");
    INFO(cont->printed());
    CHECK(cont->hasError("CONTINUE outside a loop"));
    auto inLoop = compileMain("i : INT;", "FOR i := 1 TO 3 DO IF i = 2 THEN EXIT; END_IF; END_FOR;");
    INFO(inLoop->printed());
    CHECK(inLoop->ok());
}

TEST_CASE("CASE labels must be constants of the selector type", "[checker][statements]") {
    auto wrongType = compileSt(R"(
TYPE Color : (RED, GREEN); END_TYPE
PROGRAM Main
VAR x : INT; c : Color; END_VAR
CASE x OF
    RED: x := 1;
END_CASE;
CASE c OF
    1: x := 2;
END_CASE;
END_PROGRAM
)");
    INFO(wrongType->printed());
    // An enumeration value labelling an integer selector counts as its integer, as
    // in CODESYS/TwinCAT (decision 0302; an error with --strict:
    // conformance any_inputs/type_class_compared_with_integers_strict); an
    // integer labelling an enumeration selector stays an error.
    CHECK(wrongType->errors().size() == 1);
    CHECK_FALSE(wrongType->hasError("CASE label of type Color does not match the selector type INT"));
    CHECK(wrongType->hasError("does not match the selector type Color"));

    auto notConstant = compileMain("x, y : INT;", "CASE x OF y: x := 1; END_CASE;");
    INFO(notConstant->printed());
    CHECK(notConstant->hasError("a CASE label must be a constant"));

    auto badSelector = compileMain("r : REAL; x : INT;", "CASE r OF 1: x := 1; END_CASE;");
    INFO(badSelector->printed());
    CHECK(badSelector->hasError("the CASE selector must be an integer or an enumeration, not REAL"));

    auto emptyRange = compileMain("x : INT;", "CASE x OF 5..1: x := 1; END_CASE;");
    INFO(emptyRange->printed());
    CHECK(emptyRange->hasError("empty CASE range 5..1"));

    auto overlap = compileMain("x : INT;", "CASE x OF 1..5: x := 1; 3: x := 2; END_CASE;");
    INFO(overlap->printed());
    CHECK_FALSE(overlap->ok());
}

TEST_CASE("assigning to a CONSTANT is an error", "[checker][access]") {
    auto local = compileSt(
        "PROGRAM Main\n"
        "VAR CONSTANT LIMIT : INT := 10; END_VAR\n"
        "LIMIT := 11;\n"
        "END_PROGRAM\n");
    INFO(local->printed());
    REQUIRE_FALSE(local->ok());
    auto m = local->find("cannot assign: 'LIMIT' is a CONSTANT");
    REQUIRE(m.has_value());
    CHECK(m->loc.line == 3);

    auto global = compileSt(
        "VAR_GLOBAL CONSTANT MAXV : INT := 5; END_VAR\n"
        "PROGRAM Main\n"
        "VAR_EXTERNAL MAXV : INT; END_VAR\n"
        "MAXV := 6;\n"
        "END_PROGRAM\n");
    INFO(global->printed());
    CHECK(global->hasError("'MAXV' is a CONSTANT"));

    auto forVar = compileSt(
        "PROGRAM Main\n"
        "VAR CONSTANT K : INT := 1; END_VAR\n"
        "FOR K := 1 TO 3 DO END_FOR;\n"
        "END_PROGRAM\n");
    INFO(forVar->printed());
    CHECK(forVar->hasError("cannot use 'K' as FOR control variable"));

    auto missing = compileSt("PROGRAM Main\nVAR CONSTANT C : INT; END_VAR\nEND_PROGRAM\n");
    INFO(missing->printed());
    CHECK(missing->hasError("CONSTANT 'C' needs an initial value"));
}

const char* kTimerFb = R"(
FUNCTION_BLOCK Timer
VAR_INPUT preset : INT; END_VAR
VAR_OUTPUT done : BOOL; END_VAR
VAR elapsed : INT; END_VAR
elapsed := elapsed + 1;
done := elapsed >= preset;
END_FUNCTION_BLOCK
)";

// Decision 0072 (revised by issue 8): CODESYS and TwinCAT let a program set an
// input before the call; the value stays until the next call or assignment.
TEST_CASE("assigning an FB input from outside is allowed, as is passing it in the call", "[checker][access]") {
    auto set = runSt(std::string(kTimerFb) + "PROGRAM Main\nVAR t : Timer; d : BOOL; END_VAR\nt.preset := 1;\nt();\nd := t.done;\nEND_PROGRAM\n", 1);
    INFO(set.compiled->printed());
    REQUIRE(set.ok());
    CHECK(set.var("Main", "d") == true);

    auto good = runSt(std::string(kTimerFb) +
                      "PROGRAM Main\nVAR t : Timer; p : INT; d : BOOL; END_VAR\nt(preset := 2);\np := t.preset;\nd := t.done;\nEND_PROGRAM\n", 2);
    INFO(good.compiled->printed());
    REQUIRE(good.ok());
    CHECK(good.var("Main", "p") == 2);  // reading an input from outside is allowed
    CHECK(good.var("Main", "d") == true);
}

// IEC 61131-3 (2nd ed. 2.5.2.1, 3rd ed. 6.6.3.2): outputs of an instance are
// read-only outside it (inputs, unlike them, may be set before the call: decision 0072).
TEST_CASE("assigning an FB output from outside is an error", "[checker][access]") {
    auto c = compileSt(std::string(kTimerFb) + "PROGRAM Main\nVAR t : Timer; END_VAR\nt.done := TRUE;\nEND_PROGRAM\n");
    INFO(c->printed());
    CHECK_FALSE(c->ok());
}

// TwinCAT/CODESYS read it (decision 0206); IEC 61131-3, strun's --strict, does not.
TEST_CASE("reading an FB internal variable from outside: allowed, an error with --strict", "[checker][access]") {
    auto lenient = compileSt(std::string(kTimerFb) + "PROGRAM Main\nVAR t : Timer; n : INT; END_VAR\nn := t.elapsed;\nEND_PROGRAM\n");
    INFO(lenient->printed());
    CHECK(lenient->ok());
    auto written = compileSt(std::string(kTimerFb) + "PROGRAM Main\nVAR t : Timer; END_VAR\nt.elapsed := 1;\nEND_PROGRAM\n");
    CHECK_FALSE(written->ok());
    auto c = compileSt(std::string(kTimerFb) + "PROGRAM Main\nVAR t : Timer; n : INT; END_VAR\nn := t.elapsed;\nEND_PROGRAM\n", true);
    INFO(c->printed());
    REQUIRE_FALSE(c->ok());
    auto m = c->find("'elapsed' is an internal variable of 'Timer'; only its inputs and outputs are visible outside");
    REQUIRE(m.has_value());
    CHECK(m->loc.line == 11);
}

TEST_CASE("VAR_EXTERNAL must name a declared global of the same type", "[checker][globals]") {
    auto unknown = compileSt("PROGRAM Main\nVAR_EXTERNAL missing : INT; END_VAR\nEND_PROGRAM\n");
    requireErrorAt(*unknown, "VAR_EXTERNAL 'missing' names no global variable", 2, 14);

    auto wrongType = compileSt("VAR_GLOBAL g : INT; END_VAR\nPROGRAM Main\nVAR_EXTERNAL g : DINT; END_VAR\nEND_PROGRAM\n");
    INFO(wrongType->printed());
    CHECK(wrongType->hasError("VAR_EXTERNAL 'g' is declared DINT but the global is INT"));

    auto good = runSt("VAR_GLOBAL g : INT := 4; END_VAR\nPROGRAM Main\nVAR_EXTERNAL g : INT; END_VAR\ng := g * 10;\nEND_PROGRAM\n");
    INFO(good.compiled->printed());
    REQUIRE(good.ok());
    CHECK(good.globals["g"] == 40);
}

TEST_CASE("unknown types and POUs used as variables are errors", "[checker][names]") {
    auto type = compileMain("x : NoSuchType;", "");
    INFO(type->printed());
    CHECK(type->hasError("unknown type 'NoSuchType'"));
    auto call = compileMain("x : INT;", "x := NoSuchFunction(1);");
    INFO(call->printed());
    CHECK(call->hasError("undeclared function 'NoSuchFunction'"));
    auto selfRef = compileSt("TYPE A : B; END_TYPE\nTYPE B : A; END_TYPE\nPROGRAM Main\nVAR x : A; END_VAR\nEND_PROGRAM\n");
    INFO(selfRef->printed());
    CHECK(selfRef->hasError("is defined in terms of itself"));
}

TEST_CASE("conditions must be BOOL and JMP needs a defined label", "[checker][statements]") {
    auto cond = compileMain("x : INT;", "IF x THEN x := 1; END_IF;");
    INFO(cond->printed());
    CHECK(cond->hasError("must be BOOL, not INT"));
    auto jump = compileMain("", "JMP nowhere;");
    INFO(jump->printed());
    CHECK(jump->hasError("JMP to undefined label 'nowhere'"));
}

TEST_CASE("a constant subscript outside the bounds is a compile error", "[checker][arrays]") {
    auto c = compileMain("a : ARRAY[1..3] OF INT;", "a[4] := 1;");
    INFO(c->printed());
    CHECK(c->hasError("subscript 4 is outside the array bounds 1..3"));
    auto dims = compileMain("a : ARRAY[1..3] OF INT;", "a[1, 1] := 1;");
    INFO(dims->printed());
    CHECK(dims->hasError("2 subscript(s) given, the array has 1 dimension(s)"));
}

TEST_CASE("calls with wrong arguments are errors", "[checker][calls]") {
    const std::string fn = "FUNCTION Add : INT\nVAR_INPUT a, b : INT; END_VAR\nAdd := a + b;\nEND_FUNCTION\n";
    auto tooMany = compileSt(fn + "PROGRAM Main\nVAR r : INT; END_VAR\nr := Add(1, 2, 3);\nEND_PROGRAM\n");
    INFO(tooMany->printed());
    CHECK(tooMany->hasError("too many arguments for 'Add'"));
    auto noParam = compileSt(fn + "PROGRAM Main\nVAR r : INT; END_VAR\nr := Add(a := 1, c := 2);\nEND_PROGRAM\n");
    INFO(noParam->printed());
    CHECK(noParam->hasError("'Add' has no parameter 'c'"));
    // Named twice: a warning as TwinCAT compiles it, an error with --strict (decision 0350).
    auto twice = compileSt(fn + "PROGRAM Main\nVAR r : INT; END_VAR\nr := Add(a := 1, a := 2);\nEND_PROGRAM\n", true);
    INFO(twice->printed());
    CHECK(twice->hasError("parameter 'a' given twice"));
    auto twiceDefault = compileSt(fn + "PROGRAM Main\nVAR r : INT; END_VAR\nr := Add(a := 1, a := 2, b := 3);\nEND_PROGRAM\n");
    INFO(twiceDefault->printed());
    CHECK(twiceDefault->hasWarning("parameter 'a' given twice; the last value is the one passed"));
}

// A function whose result is a structure may assign it member by member.
TEST_CASE("assigning members of a structured function result counts as assigning it", "[checker][warning]") {
    auto c = compileSt(
        "TYPE P : STRUCT x, y : INT; END_STRUCT; END_TYPE\n"
        "FUNCTION MakeP : P\n"
        "VAR_INPUT a : INT; END_VAR\n"
        "MakeP.x := a;\n"
        "MakeP.y := a * 2;\n"
        "END_FUNCTION\n"
        "PROGRAM Main\n"
        "VAR p : P; END_VAR\n"
        "p := MakeP(3);\n"
        "END_PROGRAM\n");
    INFO(c->printed());
    REQUIRE(c->ok());
    CHECK_FALSE(c->hasWarning("never assigns its result"));
}
