// Object orientation and indirection in the evaluator: methods, virtual
// dispatch through THIS^ and SUPER^, interfaces, properties, pointers and
// references.
#include <catch2/catch.hpp>

#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

namespace {

// A base FB whose Describe calls the virtual Code through THIS^, and a
// derived FB that overrides Code.
const char* kShapes = R"(
FUNCTION_BLOCK Shape
VAR_OUTPUT lastCode : INT; END_VAR
METHOD Code : INT
Code := 1;
END_METHOD
METHOD Describe : INT
lastCode := THIS^.Code();
Describe := lastCode * 100;
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK Square EXTENDS Shape
METHOD Code : INT
Code := 4;
END_METHOD
METHOD BaseCode : INT
BaseCode := SUPER^.Code();
END_METHOD
END_FUNCTION_BLOCK
)";

}  // namespace

TEST_CASE("a method call runs on the instance and changes its state", "[eval][oop]") {
    auto r = runSt(R"(
FUNCTION_BLOCK Counter
VAR_OUTPUT value : INT; END_VAR
METHOD Add : INT
VAR_INPUT amount : INT; END_VAR
value := value + amount;
Add := value;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR c1, c2 : Counter; last : INT; END_VAR
c1.Add(3);
last := c1.Add(amount := 4);
c2.Add(1);
END_PROGRAM
)", 2);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "c1")["value"] == 14);
    CHECK(r.var("Main", "c2")["value"] == 2);
    CHECK(r.var("Main", "last") == 14);
}

TEST_CASE("THIS^ dispatches to the override of the instance's actual type", "[eval][oop]") {
    auto r = runSt(std::string(kShapes) + R"(
PROGRAM Main
VAR s : Shape; q : Square; ds, dq, base : INT; END_VAR
ds := s.Describe();
dq := q.Describe();
base := q.BaseCode();
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "ds") == 100);
    CHECK(r.var("Main", "dq") == 400);    // inherited Describe calls Square.Code
    CHECK(r.var("Main", "base") == 1);    // SUPER^ binds statically to the parent
    CHECK(r.var("Main", "q")["lastCode"] == 4);
}

TEST_CASE("a pointer to the base type dispatches virtually", "[eval][oop]") {
    auto r = runSt(std::string(kShapes) + R"(
PROGRAM Main
VAR q : Square; p : POINTER TO Shape; viaPointer : INT; END_VAR
p := ADR(q);
viaPointer := p^.Code();
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "viaPointer") == 4);
}

TEST_CASE("calls through an interface reach the implementing instance", "[eval][oop]") {
    auto r = runSt(R"(
INTERFACE IValue
METHOD Get : DINT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Two IMPLEMENTS IValue
METHOD Get : DINT
Get := 2;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Seven IMPLEMENTS IValue
VAR_OUTPUT asked : INT; END_VAR
METHOD Get : DINT
asked := asked + 1;
Get := 7;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION SumOf : DINT
VAR_INPUT a, b : IValue; END_VAR
SumOf := a.Get() + b.Get();
END_FUNCTION
PROGRAM Main
VAR two : Two; seven : Seven; i : IValue; one, sum : DINT; END_VAR
i := seven;
one := i.Get();
sum := SumOf(two, seven);
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "one") == 7);
    CHECK(r.var("Main", "sum") == 9);
    CHECK(r.var("Main", "seven")["asked"] == 2);
    CHECK_FALSE(r.programs["Main"].contains("i"));  // interfaces are not dumped
}

TEST_CASE("an FB that does not implement the interface cannot be assigned to it", "[eval][oop]") {
    auto c = compileSt(R"(
INTERFACE IValue
METHOD Get : DINT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Plain
END_FUNCTION_BLOCK
PROGRAM Main
VAR p : Plain; i : IValue; END_VAR
i := p;
END_PROGRAM
)");
    INFO(c->printed());
    CHECK(c->hasError("Plain does not implement IValue"));
}

TEST_CASE("calling through an unbound interface is a runtime fault not a crash", "[eval][oop]") {
    auto r = runSt(R"(
INTERFACE IValue
METHOD Get : DINT
END_METHOD
END_INTERFACE
PROGRAM Main
VAR i : IValue; v : DINT := 5; END_VAR
v := i.Get();
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.count(rt::DiagCode::NullPointer) == 1);
    CHECK(r.var("Main", "v") == 0);
}

TEST_CASE("properties run their GET and SET accessors", "[eval][oop]") {
    auto r = runSt(R"(
FUNCTION_BLOCK Tank
VAR stored : INT; writes : INT; END_VAR
VAR_OUTPUT shown : INT; END_VAR
PROPERTY Level : INT
GET
    Level := stored;
END_GET
SET
    writes := writes + 1;
    IF Level > 100 THEN stored := 100; ELSE stored := Level; END_IF;
    shown := stored;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR t : Tank; a, b : INT; END_VAR
t.Level := 40;
a := t.Level;
t.Level := 250;
b := t.Level + 1;
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "a") == 40);
    CHECK(r.var("Main", "b") == 101);
    CHECK(r.var("Main", "t")["shown"] == 100);
    CHECK(r.var("Main", "t")["writes"] == 2);
}

TEST_CASE("pointers read and write their target through ^", "[eval][pointers]") {
    auto run = runMain("x : INT := 5; y : INT; p : POINTER TO INT; arr : ARRAY[0..3] OF DINT; pa : POINTER TO DINT; sz : DINT;",
                       "p := ADR(x);\n"
                       "p^ := p^ * 3;\n"
                       "y := p^ + 1;\n"
                       "pa := ADR(arr[2]);\n"
                       "pa^ := 42;\n"
                       "sz := SIZEOF(arr);");
    INFO(run.compiled->printed());
    REQUIRE(run.ok());
    CHECK(run.var("Main", "x") == 15);
    CHECK(run.var("Main", "y") == 16);
    CHECK(run.var("Main", "arr") == nlohmann::ordered_json::parse("[0,0,42,0]"));
    CHECK(run.var("Main", "sz") == 16);
    CHECK_FALSE(run.programs["Main"].contains("p"));  // pointers are not dumped
}

TEST_CASE("dereferencing a null pointer is a runtime fault", "[eval][pointers]") {
    auto r = runMain("p : POINTER TO INT; v : INT := 3;", "v := p^;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.count(rt::DiagCode::NullPointer) == 1);
    CHECK(r.var("Main", "v") == 0);
}

TEST_CASE("a reference is bound with REF= and then used like its target", "[eval][references]") {
    auto r = runSt(R"(
TYPE Pair : STRUCT a, b : INT; END_STRUCT; END_TYPE
PROGRAM Main
VAR
    x : INT := 1; y : INT := 2;
    r : REFERENCE TO INT;
    pr : REFERENCE TO Pair;
    pair : Pair;
    readBack : INT;
    valid : BOOL;
END_VAR
r REF= x;
r := 10;
r REF= y;
r := r + 5;
readBack := r;
pr REF= pair;
pr.b := 9;
valid := __ISVALIDREF(r);
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "x") == 10);
    CHECK(r.var("Main", "y") == 7);
    CHECK(r.var("Main", "readBack") == 7);
    CHECK(r.var("Main", "pair")["b"] == 9);
    CHECK(r.var("Main", "valid") == true);
    CHECK_FALSE(r.programs["Main"].contains("r"));
}

TEST_CASE("an unbound reference is a runtime fault", "[eval][references]") {
    auto r = runMain("r : REFERENCE TO INT; v : INT := 3; valid : BOOL := TRUE;", "valid := __ISVALIDREF(r);\nv := r;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "valid") == false);
    CHECK(r.count(rt::DiagCode::NullPointer) == 1);
    CHECK(r.var("Main", "v") == 0);
}
