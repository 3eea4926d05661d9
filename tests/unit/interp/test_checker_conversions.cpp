// The checker's implicit conversions: which widenings an assignment accepts
// silently, which it rejects, how untyped literals adopt a type, and
// constant folding.
#include <catch2/catch.hpp>

#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

namespace {

// `dst := src;` with src of type `from` and dst of type `to`.
std::unique_ptr<Compiled> assignBetween(const std::string& from, const std::string& to, bool strict = false) {
    return compileMain("src : " + from + "; dst : " + to + ";", "dst := src;", strict);
}

}  // namespace

TEST_CASE("implicit widenings are accepted, silently, also with --strict", "[checker][conversion]") {
    const std::pair<const char*, const char*> allowed[] = {
        {"INT", "DINT"},    {"USINT", "INT"},   {"SINT", "LREAL"}, {"REAL", "LREAL"}, {"BYTE", "WORD"},
        {"SINT", "INT"},    {"INT", "LINT"},    {"UINT", "UDINT"}, {"UINT", "DINT"},  {"WORD", "DWORD"},
        {"DWORD", "LWORD"}, {"INT", "REAL"},    {"DINT", "LREAL"}, {"TIME", "LTIME"}, {"BOOL", "BYTE"},
        {"USINT", "LINT"},  {"UDINT", "LINT"},
    };
    for (const auto& [from, to] : allowed) {
        auto c = assignBetween(from, to, true);
        INFO(from << " -> " << to << "\n" << c->printed());
        CHECK(c->ok());
        CHECK(c->errors().empty());
        CHECK(c->warnings().empty());
    }
}

TEST_CASE("with --strict, narrowing and unrelated implicit conversions are rejected", "[checker][conversion]") {
    const std::pair<const char*, const char*> rejected[] = {
        {"DINT", "INT"},    {"REAL", "INT"},   {"BOOL", "INT"},    {"INT", "BOOL"},   {"STRING", "INT"},
        {"INT", "UINT"},    {"SINT", "USINT"}, {"DINT", "UDINT"},  {"LINT", "ULINT"}, {"LREAL", "REAL"},
        {"WORD", "BYTE"},   {"INT", "STRING"}, {"TIME", "DINT"},   {"DINT", "TIME"},  {"LTIME", "TIME"},
        {"UINT", "INT"},    {"REAL", "DINT"},  {"DATE", "DT"},     {"CHAR", "WCHAR"}, {"LREAL", "LINT"},
    };
    for (const auto& [from, to] : rejected) {
        auto c = assignBetween(from, to, true);
        INFO(from << " -> " << to << "\n" << c->printed());
        CHECK_FALSE(c->ok());
        CHECK(c->errors().size() == 1);
    }
}

TEST_CASE("a rejected conversion names both types and suggests the conversion function", "[checker][conversion]") {
    auto c = assignBetween("DINT", "INT", true);
    INFO(c->printed());
    REQUIRE_FALSE(c->ok());
    CHECK(c->hasError("implicit conversion from DINT to INT: possible loss of data; use DINT_TO_INT"));
    auto d = assignBetween("DATE", "DT");
    INFO(d->printed());
    CHECK(d->hasError("cannot convert DATE to DATE_AND_TIME implicitly; use DATE_TO_DT"));
}

// Contract "Implicit conversions" / decision 0090: what CODESYS accepts.
TEST_CASE("by default, numeric narrowing compiles with a warning; other kinds stay errors", "[checker][conversion]") {
    const std::pair<const char*, const char*> warned[] = {
        {"DINT", "INT"}, {"REAL", "INT"}, {"INT", "UINT"}, {"LREAL", "REAL"}, {"WORD", "BYTE"},
        {"UINT", "INT"}, {"LREAL", "LINT"}, {"INT", "WORD"}, {"DWORD", "REAL"},
    };
    for (const auto& [from, to] : warned) {
        auto c = assignBetween(from, to);
        INFO(from << " -> " << to << "\n" << c->printed());
        CHECK(c->ok());
        CHECK(c->hasWarning(std::string("implicit conversion from ") + from + " to " + to + ": possible loss of data"));
    }
    const std::pair<const char*, const char*> rejected[] = {
        {"BOOL", "INT"}, {"INT", "BOOL"}, {"STRING", "INT"}, {"INT", "STRING"}, {"TIME", "DINT"},
        {"DINT", "TIME"}, {"LTIME", "TIME"}, {"DATE", "DT"}, {"CHAR", "WCHAR"},
    };
    for (const auto& [from, to] : rejected) {
        auto c = assignBetween(from, to);
        INFO(from << " -> " << to << "\n" << c->printed());
        CHECK_FALSE(c->ok());
    }
}

TEST_CASE("a constant expression that does not fit wraps with a warning, an error with --strict", "[checker][literal]") {
    auto r = runMain("x : SINT;", "x := 127 + 1;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "x") == -128);
    CHECK(r.compiled->hasWarning("constant 128 does not fit SINT; it wraps to -128"));
    auto s = compileMain("x : SINT;", "x := 127 + 1;", true);
    CHECK(s->hasError("constant 128 does not fit SINT"));
}

TEST_CASE("the explicit conversion function makes a rejected assignment legal", "[checker][conversion]") {
    auto r = runMain("src : DINT := 70000; dst : INT; f : REAL := 2.5; g : INT;",
                     "dst := DINT_TO_INT(src); g := REAL_TO_INT(f);");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "dst") == 4464);  // 70000 wraps to 16 bits
    CHECK(r.var("Main", "g") == 2);       // 2.5 rounds half to even
}

TEST_CASE("an untyped integer literal adopts the type of the other operand", "[checker][literal]") {
    auto r = runMain("x : SINT := 127; y : USINT := 255; w : WORD := 16#FFFF;",
                     "x := x + 1; y := y + 1; w := w + 1;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    // Computed in SINT / USINT / WORD: wraps at their width rather than growing.
    CHECK(r.var("Main", "x") == -128);
    CHECK(r.var("Main", "y") == 0);
    CHECK(r.var("Main", "w") == 0);
    auto c = compileMain("x : SINT;", "x := x + 1;");
    CHECK(c->ok());
    CHECK(c->errors().empty());
}

TEST_CASE("an integer literal outside the target type is an error", "[checker][literal]") {
    auto c = compileMain("x : SINT;", "x := 300;");
    INFO(c->printed());
    REQUIRE_FALSE(c->ok());
    CHECK(c->hasError("constant 300 is outside the range of SINT"));
    auto u = compileMain("x : USINT;", "x := -1;");
    INFO(u->printed());
    CHECK_FALSE(u->ok());
    auto init = compileMain("x : INT := 40000;", "");
    INFO(init->printed());
    CHECK_FALSE(init->ok());
    auto fits = compileMain("x : SINT; y : INT;", "x := -128; y := -32768;");
    INFO(fits->printed());
    CHECK(fits->ok());
}

TEST_CASE("an untyped real literal adopts REAL or LREAL and is not an integer", "[checker][literal]") {
    auto bad = compileMain("i : INT;", "i := 1.5;", true);
    INFO(bad->printed());
    CHECK_FALSE(bad->ok());
    auto warned = runMain("i : INT;", "i := 2.6;");  // the default converts like REAL_TO_INT, with a warning
    INFO(warned.compiled->printed());
    REQUIRE(warned.ok());
    CHECK(warned.var("Main", "i") == 3);
    CHECK(warned.compiled->hasWarning("implicit conversion from LREAL to INT"));
    auto r = runMain("r : REAL; l : LREAL;", "r := 0.1; l := 0.1;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "r") == 0.1);  // the dump prints the shortest REAL text
    CHECK(r.var("Main", "l") == 0.1);
}

TEST_CASE("constant expressions are folded", "[checker][constant]") {
    auto r = runSt(R"(
PROGRAM Main
VAR CONSTANT
    N : INT := 2 + 3 * 4;
    HALF : INT := N / 2;
END_VAR
VAR
    folded : DINT := 2 + 3 * 4;
    arr : ARRAY[1..N] OF INT;
    shifted : ARRAY[N - 10..N] OF BYTE;
    size : DINT;
END_VAR
size := N + HALF;
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "N") == 14);
    CHECK(r.var("Main", "HALF") == 7);
    CHECK(r.var("Main", "folded") == 14);
    CHECK(r.var("Main", "arr").size() == 14);
    CHECK(r.var("Main", "shifted").size() == 11);
    CHECK(r.var("Main", "size") == 21);
    const sema::VarSym* n = r.compiled->var("Main", "N");
    REQUIRE(n != nullptr);
    CHECK(n->hasConstValue);
    CHECK(n->constInt == 14);
    const sema::Type* arr = r.compiled->typeOf("Main", "shifted");
    CHECK(arr->dims[0].lo == 4);
    CHECK(arr->dims[0].hi == 14);
}

TEST_CASE("a global CONSTANT can size an array in another POU", "[checker][constant]") {
    auto r = runSt(R"(
VAR_GLOBAL CONSTANT
    SIZE : UINT := 4;
END_VAR
FUNCTION_BLOCK Buffer
VAR_OUTPUT data : ARRAY[0..SIZE - 1] OF INT; END_VAR
data[SIZE - 1] := 9;
END_FUNCTION_BLOCK
PROGRAM Main
VAR b : Buffer; END_VAR
b();
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "b")["data"] == nlohmann::ordered_json::parse("[0,0,0,9]"));
    CHECK(r.globals["SIZE"] == 4);
}

TEST_CASE("an array bound that is not constant is an error", "[checker][constant]") {
    auto c = compileMain("n : INT := 3; arr : ARRAY[1..n] OF INT;", "");
    INFO(c->printed());
    CHECK_FALSE(c->ok());
    CHECK(c->hasError("an array bound must be a constant integer expression"));
}

TEST_CASE("mixed signed and unsigned operands widen to a signed type", "[checker][conversion]") {
    auto r = runMain("u : USINT := 200; s : SINT := -100; d : INT;", "d := u + s;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "d") == 100);
}
