// Calls in the evaluator: functions and recursion, the CALL_DEPTH limit of
// 16 nested calls, VAR_IN_OUT aliasing, argument passing, string truncation
// and the ARRAY_BOUNDS fault.
#include <catch2/catch.hpp>

#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

namespace {

// Depth(n) nests n calls of itself (the program's call is the first).
const char* kDepthFunction = R"(
FUNCTION Depth : INT
VAR_INPUT n : INT; END_VAR
IF n > 1 THEN
    Depth := Depth(n - 1) + 1;
ELSE
    Depth := 1;
END_IF;
END_FUNCTION
)";

RunOutcome runDepth(int n) {
    return runSt(std::string(kDepthFunction) + "PROGRAM Main\nVAR r : INT := -1; after : BOOL; END_VAR\nr := Depth(" +
                 std::to_string(n) + ");\nafter := TRUE;\nEND_PROGRAM\n");
}

}  // namespace

TEST_CASE("a recursive function computes factorial", "[eval][calls]") {
    auto r = runSt(R"(
FUNCTION Fact : LINT
VAR_INPUT n : LINT; END_VAR
IF n <= 1 THEN Fact := 1; ELSE Fact := n * Fact(n - 1); END_IF;
END_FUNCTION
PROGRAM Main
VAR f10 : LINT; f15 : LINT; END_VAR
f10 := Fact(10);
f15 := Fact(15);
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "f10") == 3628800);
    CHECK(r.var("Main", "f15") == 1307674368000LL);
}

TEST_CASE("exactly 16 nested calls are allowed", "[eval][calls][depth]") {
    auto r = runDepth(16);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.state == rt::PlcState::Run);
    CHECK(r.var("Main", "r") == 16);
    CHECK(r.var("Main", "after") == true);
    CHECK(r.diagnostics.empty());
}

TEST_CASE("the 17th nested call reports CALL_DEPTH and stops the PLC", "[eval][calls][depth]") {
    auto r = runDepth(17);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.state == rt::PlcState::Stop);
    REQUIRE(r.count(rt::DiagCode::CallDepth) == 1);
    const rt::DiagEntry& d = r.diagnostics.front();
    CHECK(d.code == rt::DiagCode::CallDepth);
    CHECK(d.pou == "Depth");
    CHECK(d.line == 5);
    CHECK(r.var("Main", "after") == false);  // the activation was abandoned
}

TEST_CASE("a chain of function blocks counts toward the call depth", "[eval][calls][depth]") {
    // L1 calls L2 ... calls L17: each FB call is one nesting level.
    std::string src;
    const int levels = 17;
    for (int k = levels; k >= 1; --k) {
        src += "FUNCTION_BLOCK L" + std::to_string(k) + "\nVAR_OUTPUT done : BOOL; END_VAR\n";
        if (k < levels) src += "VAR inner : L" + std::to_string(k + 1) + "; END_VAR\ninner();\ndone := inner.done;\n";
        else src += "done := TRUE;\n";
        src += "END_FUNCTION_BLOCK\n";
    }
    auto deep = runSt(src + "PROGRAM Main\nVAR top : L1; ok : BOOL; END_VAR\ntop();\nok := top.done;\nEND_PROGRAM\n");
    INFO(deep.compiled->printed());
    REQUIRE(deep.ok());
    CHECK(deep.state == rt::PlcState::Stop);
    CHECK(deep.count(rt::DiagCode::CallDepth) == 1);
    // 16 levels are fine: start the chain at L2.
    auto fine = runSt(src + "PROGRAM Main\nVAR top : L2; ok : BOOL; END_VAR\ntop();\nok := top.done;\nEND_PROGRAM\n");
    INFO(fine.compiled->printed());
    REQUIRE(fine.ok());
    CHECK(fine.state == rt::PlcState::Run);
    CHECK(fine.var("Main", "ok") == true);
}

TEST_CASE("unbounded recursion stops at the depth limit without crashing", "[eval][calls][depth]") {
    auto r = runSt(R"(
FUNCTION Forever : DINT
VAR_INPUT n : DINT; END_VAR
Forever := Forever(n + 1);
END_FUNCTION
PROGRAM Main
VAR r : DINT; END_VAR
r := Forever(0);
END_PROGRAM
)", 3);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.state == rt::PlcState::Stop);
    CHECK(r.count(rt::DiagCode::CallDepth) == 1);
}

TEST_CASE("VAR_IN_OUT parameters alias the caller's variables", "[eval][calls][inout]") {
    auto r = runSt(R"(
FUNCTION Bump : BOOL
VAR_IN_OUT a, b : INT; END_VAR
a := a + 1;
b := b + 10;
Bump := a = b;
END_FUNCTION
FUNCTION_BLOCK Swapper
VAR_IN_OUT x, y : DINT; END_VAR
VAR t : DINT; END_VAR
t := x; x := y; y := t;
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    v : INT; same : BOOL; p : INT := 1; q : INT := 2; different : BOOL := TRUE;
    arr : ARRAY[1..3] OF DINT := [1, 2, 3];
    s : Swapper;
END_VAR
same := Bump(v, v);
different := Bump(p, q);
s(x := arr[1], y := arr[3]);
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "v") == 11);  // both parameters are the same variable
    CHECK(r.var("Main", "same") == true);
    CHECK(r.var("Main", "p") == 2);
    CHECK(r.var("Main", "q") == 12);
    CHECK(r.var("Main", "different") == false);
    CHECK(r.var("Main", "arr") == nlohmann::ordered_json::parse("[3,2,1]"));
}

TEST_CASE("VAR_IN_OUT needs a variable of the same type", "[eval][calls][inout]") {
    const std::string fn = "FUNCTION Inc : BOOL\nVAR_IN_OUT a : INT; END_VAR\na := a + 1;\nInc := TRUE;\nEND_FUNCTION\n";
    auto expr = compileSt(fn + "PROGRAM Main\nVAR x : INT; ok : BOOL; END_VAR\nok := Inc(x + 1);\nEND_PROGRAM\n");
    INFO(expr->printed());
    CHECK(expr->hasError("VAR_IN_OUT 'a' needs a variable, not an expression"));
    auto type = compileSt(fn + "PROGRAM Main\nVAR x : DINT; ok : BOOL; END_VAR\nok := Inc(x);\nEND_PROGRAM\n");
    INFO(type->printed());
    CHECK(type->hasError("VAR_IN_OUT 'a' is INT, the argument is DINT"));
}

TEST_CASE("function outputs locals and formal arguments", "[eval][calls]") {
    auto r = runSt(R"(
FUNCTION Split : BOOL
VAR_INPUT value : INT; divisor : INT := 10; END_VAR
VAR_OUTPUT quotient : INT; remainder : INT; END_VAR
VAR calls : INT; END_VAR
calls := calls + 1;
quotient := value / divisor;
remainder := value MOD divisor;
Split := calls = 1;
END_FUNCTION
PROGRAM Main
VAR q, m, q2, m2 : INT; fresh1, fresh2 : BOOL; END_VAR
fresh1 := Split(value := 47, quotient => q, remainder => m);
fresh2 := Split(divisor := 4, value := 47, quotient => q2, remainder => m2);
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "q") == 4);
    CHECK(r.var("Main", "m") == 7);
    CHECK(r.var("Main", "q2") == 11);
    CHECK(r.var("Main", "m2") == 3);
    CHECK(r.var("Main", "fresh1") == true);
    CHECK(r.var("Main", "fresh2") == true);  // function locals start fresh every call
}

TEST_CASE("FB state persists between calls and inputs keep their last value", "[eval][calls][fb]") {
    auto r = runSt(R"(
FUNCTION_BLOCK Acc
VAR_INPUT step : INT := 1; END_VAR
VAR_OUTPUT total : INT; END_VAR
total := total + step;
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Acc; seen : INT; END_VAR
a(step := 5);
a();
seen := a.total;
END_PROGRAM
)", 2);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "seen") == 20);
    CHECK(r.var("Main", "a")["step"] == 5);
}

TEST_CASE("assigning a longer string truncates to the declared length", "[eval][strings]") {
    auto r = runSt(R"(
FUNCTION Echo : STRING[4]
VAR_INPUT s : STRING[3]; END_VAR
Echo := CONCAT(s, '!!');
END_FUNCTION
PROGRAM Main
VAR
    short : STRING[5];
    init : STRING[3] := 'abcdef';
    wide : WSTRING[2];
    fromFn : STRING;
    copy : STRING[2];
    src : STRING := 'xyz';
END_VAR
short := 'Hello World';
wide := "wxyz";
fromFn := Echo('long');
copy := src;
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "short") == "Hello");
    CHECK(r.var("Main", "init") == "abc");
    CHECK(r.var("Main", "wide") == "wx");
    CHECK(r.var("Main", "fromFn") == "lon!");
    CHECK(r.var("Main", "copy") == "xy");
}

TEST_CASE("an array read out of bounds yields 0 reports ARRAY_BOUNDS and stops the PLC", "[eval][bounds]") {
    auto r = runSt(
        "PROGRAM Main\n"
        "VAR a : ARRAY[1..3] OF INT := [10, 20, 30]; i : INT := 4; v : INT := 99; after : BOOL; END_VAR\n"
        "v := a[i] + 5;\n"
        "after := TRUE;\n"
        "END_PROGRAM\n", 3);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "v") == 5);
    CHECK(r.state == rt::PlcState::Stop);
    REQUIRE(r.count(rt::DiagCode::ArrayBounds) == 1);
    CHECK(r.diagnostics.front().line == 3);
    CHECK(r.diagnostics.front().pou == "Main");
    CHECK(r.diagnostics.front().message.find("subscript 4 outside 1..3") != std::string::npos);
    CHECK(r.var("Main", "after") == false);
    CHECK(r.tasks[0]["cycles"] == 0);
}

TEST_CASE("an array write out of bounds is dropped", "[eval][bounds]") {
    auto r = runMain("a : ARRAY[0..2] OF DINT; before : ARRAY[0..1] OF DINT; i : INT := -1; j : INT := 3;",
                     "a[i] := 7;\na[j] := 8;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "a") == nlohmann::ordered_json::parse("[0,0,0]"));
    CHECK(r.var("Main", "before") == nlohmann::ordered_json::parse("[0,0]"));
    CHECK(r.state == rt::PlcState::Stop);
    CHECK(r.count(rt::DiagCode::ArrayBounds) >= 1);
}

TEST_CASE("the edges of an array are in bounds", "[eval][bounds]") {
    auto r = runMain("a : ARRAY[-2..2] OF INT; m : ARRAY[1..2, 5..6] OF INT; i : INT;",
                     "FOR i := -2 TO 2 DO a[i] := i * 10; END_FOR;\nm[1, 5] := 1; m[2, 6] := 4; m[1, 6] := 2;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.state == rt::PlcState::Run);
    CHECK(r.var("Main", "a") == nlohmann::ordered_json::parse("[-20,-10,0,10,20]"));
    CHECK(r.var("Main", "m") == nlohmann::ordered_json::parse("[[1,2],[0,4]]"));
    CHECK(r.diagnostics.empty());
}

TEST_CASE("an out of bounds second subscript is caught", "[eval][bounds]") {
    auto r = runMain("m : ARRAY[1..2, 1..2] OF INT; j : INT := 3; v : INT := 1;", "v := m[1, j];");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.count(rt::DiagCode::ArrayBounds) == 1);
    CHECK(r.var("Main", "v") == 0);
}

TEST_CASE("with a program-error task the PLC keeps running after ARRAY_BOUNDS", "[eval][bounds]") {
    auto r = runSt(R"(
PROGRAM Worker
VAR a : ARRAY[1..2] OF INT; i : INT := 5; v : INT := 1; cycles : INT; END_VAR
cycles := cycles + 1;
v := a[i];
END_PROGRAM
PROGRAM OnError
VAR calls : INT; END_VAR
calls := calls + 1;
END_PROGRAM
CONFIGURATION Plant
    RESOURCE Cpu ON PLC
        TASK Cyclic (INTERVAL := T#10ms, PRIORITY := 10);
        TASK ErrTask (EVENT := PROGRAM_ERROR, PRIORITY := 5);
        PROGRAM W WITH Cyclic : Worker;
        PROGRAM E WITH ErrTask : OnError;
    END_RESOURCE
END_CONFIGURATION
)", 3);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.state == rt::PlcState::Run);
    CHECK(r.var("W", "cycles") == 3);
    CHECK(r.var("W", "v") == 0);
    CHECK(r.count(rt::DiagCode::ArrayBounds) == 3);
    CHECK(r.var("E", "calls").get<int>() >= 2);
}

TEST_CASE("a structured function result is returned by value", "[eval][calls]") {
    auto r = runSt(R"(
TYPE P : STRUCT x, y : INT; END_STRUCT; END_TYPE
FUNCTION MakeP : P
VAR_INPUT a : INT; END_VAR
MakeP.x := a;
MakeP.y := a * 2;
END_FUNCTION
PROGRAM Main
VAR p : P; q : INT; END_VAR
p := MakeP(3);
q := MakeP(5).y;
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "p") == nlohmann::ordered_json::parse(R"({"x":3,"y":6})"));
    CHECK(r.var("Main", "q") == 10);
}
