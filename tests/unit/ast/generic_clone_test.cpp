// VAR_GENERIC CONSTANT and the values after a type name (decision 0312), and
// the deep copy of a POU that each specialisation is made from.
#include <catch2/catch.hpp>

#include "interpreter/ast/ast_clone.h"
#include "parse_test_support.h"

using namespace strun::ast;
using strun::ast::test::parse;

TEST_CASE("VAR_GENERIC CONSTANT and generic values parse", "[parser][decl][generic]") {
    auto p = parse(R"(
FUNCTION_BLOCK FB_Buf
VAR_GENERIC CONSTANT
    size, spare : UDINT := 1;
END_VAR
VAR
    data : ARRAY[0..size] OF INT;
END_VAR
data[0] := 1;
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Long EXTENDS FB_Buf<1000, -2>
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    a : FB_Buf<4, (2 * c)>;
    b : ARRAY[1..2] OF FB_Buf<Ns.cMax, 16#10>;
    c : FB_Buf<3, 1>(x := 1);
END_VAR
END_PROGRAM
)");
    REQUIRE(p->errors() == "");
    const auto& pous = p->unit.pous;
    REQUIRE(pous.size() == 3);
    REQUIRE(pous[0]->vars.size() == 2);
    CHECK(pous[0]->vars[0].generic);
    CHECK(pous[0]->vars[0].constant);
    CHECK_FALSE(pous[0]->vars[1].generic);
    CHECK(pous[1]->extends == "FB_Buf");
    REQUIRE(pous[1]->extendsGenericArgs.size() == 2);
    CHECK(dump(*pous[1]->extendsGenericArgs[1]) == "(neg 2)");
    const auto& vars = pous[2]->vars[0].vars;
    REQUIRE(vars[0].type->genericArgs.size() == 2);
    CHECK(dump(*vars[0].type->genericArgs[1]) == "(* 2 c)");
    REQUIRE(vars[1].type->elem);
    REQUIRE(vars[1].type->elem->genericArgs.size() == 2);
    CHECK(dump(*vars[1].type->elem->genericArgs[0]) == "(. Ns cMax)");
    // `FB<..>(x := 1)` arrives as an enumeration-like spec: the values go with the name.
    REQUIRE(vars[2].type->elem);
    CHECK(vars[2].type->elem->genericArgs.size() == 2);
}

TEST_CASE("clonePou copies deeply", "[ast][clone]") {
    auto p = parse(R"(
FUNCTION_BLOCK FB_A
VAR_GENERIC CONSTANT n : INT := 2; END_VAR
VAR x : ARRAY[1..n] OF INT := [2(7)]; END_VAR
METHOD M : INT
M := n;
END_METHOD
PROPERTY P : INT
GET
P := x[1];
END_GET
END_PROPERTY
IF x[1] > 0 THEN x[2] := 1; ELSE x[2] := 2; END_IF
CASE n OF 1..2: x[1] := 3; END_CASE
END_FUNCTION_BLOCK
)");
    REQUIRE(p->errors() == "");
    const Pou& original = *p->unit.pous[0];
    std::unique_ptr<Pou> copy = clonePou(original);
    CHECK(copy->name == original.name);
    CHECK(dump(copy->body) == dump(original.body));
    REQUIRE(copy->methods.size() == 1);
    CHECK(dump(copy->methods[0]->body) == dump(original.methods[0]->body));
    REQUIRE(copy->properties.size() == 1);
    REQUIRE(copy->properties[0].getter);
    CHECK(dump(copy->properties[0].getter->body) == dump(original.properties[0].getter->body));
    CHECK(copy->vars[0].generic);
    // Changing the copy leaves the original as it was.
    copy->vars[0].vars[0].names[0] = "m";
    copy->body.clear();
    CHECK(original.vars[0].vars[0].names[0] == "n");
    CHECK_FALSE(original.body.empty());
}
