// Control statements in the evaluator: FOR (end value of the control
// variable, negative steps), CASE with ranges and lists, JMP, WHILE and
// REPEAT with EXIT and CONTINUE, RETURN.
#include <catch2/catch.hpp>

#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

TEST_CASE("FOR leaves the control variable one step past the end value", "[eval][for]") {
    auto r = runMain("i : INT; sum : INT; j : DINT; n : INT;",
                     "FOR i := 1 TO 10 DO sum := sum + i; END_FOR;\n"
                     "FOR j := 1 TO 10 BY 4 DO n := n + 1; END_FOR;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "sum") == 55);
    CHECK(r.var("Main", "i") == 11);
    CHECK(r.var("Main", "n") == 3);  // 1, 5, 9
    CHECK(r.var("Main", "j") == 13);
}

TEST_CASE("FOR with a negative step counts down", "[eval][for]") {
    auto r = runMain("i : INT; sum : INT; k : SINT; visits : INT; last : SINT;",
                     "FOR i := 10 TO 1 BY -1 DO sum := sum + i; END_FOR;\n"
                     "FOR k := 5 TO -5 BY -3 DO visits := visits + 1; last := k; END_FOR;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "sum") == 55);
    CHECK(r.var("Main", "i") == 0);
    CHECK(r.var("Main", "visits") == 4);  // 5, 2, -1, -4
    CHECK(r.var("Main", "last") == -4);
    CHECK(r.var("Main", "k") == -7);
}

TEST_CASE("FOR runs no iteration when the start is already past the end", "[eval][for]") {
    auto r = runMain("i : INT; n : INT; k : INT; m : INT;",
                     "FOR i := 5 TO 1 DO n := n + 1; END_FOR;\n"
                     "FOR k := 1 TO 5 BY -1 DO m := m + 1; END_FOR;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "n") == 0);
    CHECK(r.var("Main", "i") == 5);
    CHECK(r.var("Main", "m") == 0);
    CHECK(r.var("Main", "k") == 1);
}

TEST_CASE("FOR bounds and step are expressions evaluated before the loop", "[eval][for]") {
    auto r = runMain("i : INT; lo : INT := 2; hi : INT := 4; st : INT := 1; n : INT;",
                     "FOR i := lo * 2 TO hi * 3 BY st + 1 DO n := n + 1; hi := 100; END_FOR;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "n") == 5);  // 4, 6, 8, 10, 12: the end value was taken once
    CHECK(r.var("Main", "i") == 14);
}

TEST_CASE("EXIT leaves only the innermost loop and CONTINUE skips the rest of the body", "[eval][loops]") {
    auto r = runMain("i : INT; j : INT; outer : INT; inner : INT; odd : INT;",
                     "FOR i := 1 TO 3 DO\n"
                     "  outer := outer + 1;\n"
                     "  FOR j := 1 TO 10 DO IF j = 3 THEN EXIT; END_IF; inner := inner + 1; END_FOR;\n"
                     "END_FOR;\n"
                     "FOR i := 1 TO 9 DO IF i MOD 2 = 0 THEN CONTINUE; END_IF; odd := odd + i; END_FOR;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "outer") == 3);
    CHECK(r.var("Main", "inner") == 6);
    CHECK(r.var("Main", "j") == 3);
    CHECK(r.var("Main", "odd") == 25);
}

TEST_CASE("WHILE and REPEAT with EXIT and CONTINUE", "[eval][loops]") {
    auto r = runMain("n : INT; w : INT; skipped : INT; m : INT; once : INT; stop : INT;",
                     "WHILE TRUE DO n := n + 1; IF n >= 7 THEN EXIT; END_IF; END_WHILE;\n"
                     "WHILE w < 10 DO w := w + 1; IF w < 5 THEN CONTINUE; END_IF; skipped := skipped + 1; END_WHILE;\n"
                     "REPEAT m := m + 1; IF m = 2 THEN CONTINUE; END_IF; stop := stop + 1; UNTIL m >= 4 END_REPEAT;\n"
                     "REPEAT once := once + 1; UNTIL TRUE END_REPEAT;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "n") == 7);
    CHECK(r.var("Main", "w") == 10);
    CHECK(r.var("Main", "skipped") == 6);
    CHECK(r.var("Main", "m") == 4);
    CHECK(r.var("Main", "stop") == 3);
    CHECK(r.var("Main", "once") == 1);
}

TEST_CASE("CASE selects single values lists and ranges with ELSE", "[eval][case]") {
    auto r = runMain("k : INT; hits : ARRAY[0..25] OF INT;",
                     "FOR k := 0 TO 25 DO\n"
                     "  CASE k OF\n"
                     "    1: hits[k] := 1;\n"
                     "    2, 4, 6: hits[k] := 2;\n"
                     "    10..12, 20: hits[k] := 3;\n"
                     "    -5..0: hits[k] := 4;\n"
                     "  ELSE\n"
                     "    hits[k] := 9;\n"
                     "  END_CASE;\n"
                     "END_FOR;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    const auto& h = r.var("Main", "hits");
    CHECK(h[0] == 4);
    CHECK(h[1] == 1);
    CHECK(h[2] == 2);
    CHECK(h[3] == 9);
    CHECK(h[6] == 2);
    CHECK(h[9] == 9);
    CHECK(h[10] == 3);
    CHECK(h[12] == 3);
    CHECK(h[13] == 9);
    CHECK(h[20] == 3);
    CHECK(h[25] == 9);
}

TEST_CASE("CASE on an enumeration and without a matching label", "[eval][case]") {
    auto r = runSt(R"(
TYPE Mode : (IDLE, RUNNING, FAULT); END_TYPE
PROGRAM Main
VAR m : Mode := RUNNING; code : INT := -1; untouched : INT := 7; END_VAR
CASE m OF
    IDLE: code := 0;
    RUNNING: code := 1;
    FAULT: code := 2;
END_CASE;
CASE code OF
    5..9: untouched := 0;
END_CASE;
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "code") == 1);
    CHECK(r.var("Main", "untouched") == 7);
}

TEST_CASE("JMP jumps forward over statements and backward to form a loop", "[eval][jmp]") {
    auto r = runMain("skipped : BOOL; n : INT; reached : BOOL;",
                     "JMP over;\n"
                     "skipped := TRUE;\n"
                     "over:\n"
                     "again: n := n + 1;\n"
                     "IF n < 5 THEN JMP again; END_IF;\n"
                     "reached := TRUE;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "skipped") == false);
    CHECK(r.var("Main", "n") == 5);
    CHECK(r.var("Main", "reached") == true);
}

TEST_CASE("RETURN in a program ends this cycle of the program only", "[eval][return]") {
    auto r = runMain("cycles : INT; after : INT;", "cycles := cycles + 1;\nIF cycles > 0 THEN RETURN; END_IF;\nafter := after + 1;", 3);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "cycles") == 3);
    CHECK(r.var("Main", "after") == 0);
}

TEST_CASE("program state persists across cycles and temporaries do not", "[eval][cycles]") {
    auto r = runSt(R"(
PROGRAM Main
VAR count : INT; seenTemp : INT; END_VAR
VAR_TEMP t : INT; END_VAR
t := t + 1;
seenTemp := t;
count := count + 1;
END_PROGRAM
)", 5);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "count") == 5);
    CHECK(r.var("Main", "seenTemp") == 1);
    CHECK_FALSE(r.programs["Main"].contains("t"));  // VAR_TEMP is not dumped
}

TEST_CASE("S= and R= set and reset a BOOL only when the condition is TRUE", "[eval][assign]") {
    auto r = runMain("a : BOOL; b : BOOL := TRUE; c : BOOL := TRUE; t : BOOL := TRUE; f : BOOL;",
                     "a S= t; b R= t; c S= f;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "a") == true);
    CHECK(r.var("Main", "b") == false);
    CHECK(r.var("Main", "c") == true);
}
