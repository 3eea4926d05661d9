// The --dump value encodings of shared/contract.md, type by type, through
// project::programsJson / globalsJson / valueToJson.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;
using json = nlohmann::ordered_json;

TEST_CASE("dump of BOOL integers and bit strings", "[dump]") {
    auto r = runMain("b : BOOL := TRUE; si : SINT := -5; ul : ULINT := 18446744073709551615; lw : LWORD := 16#8000000000000000; w : WORD := 16#FFFF;", "");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "b").is_boolean());
    CHECK(r.var("Main", "b") == true);
    CHECK(r.var("Main", "si") == -5);
    CHECK(r.var("Main", "ul").is_number_unsigned());
    CHECK(r.var("Main", "ul") == std::numeric_limits<uint64_t>::max());
    CHECK(r.var("Main", "lw") == 9223372036854775808ULL);
    CHECK(r.var("Main", "w") == 65535);
}

TEST_CASE("dump of TIME and LTIME as IEC duration literals", "[dump]") {
    auto r = runMain("t : TIME := T#1s500ms; z : TIME; n : TIME := T#-250ms; big : TIME := T#1d2h3m4s5ms; "
                     "lt : LTIME := LTIME#1ms2us3ns; frac : TIME := T#1.5s;",
                     "");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "t") == "T#1s500ms");
    CHECK(r.var("Main", "z") == "T#0s");
    CHECK(r.var("Main", "n") == "T#-250ms");
    CHECK(r.var("Main", "big") == "T#1d2h3m4s5ms");
    CHECK(r.var("Main", "lt") == "T#1ms2us3ns");
    CHECK(r.var("Main", "frac") == "T#1s500ms");
}

TEST_CASE("dump of DATE TOD and DT with fractions only when non-zero", "[dump]") {
    auto r = runMain(R"(
d : DATE := D#2026-01-31; tod1 : TOD := TOD#13:05:00; tod2 : TOD := TOD#13:05:00.25;
dt1 : DT := DT#2026-01-31-13:05:00; ld : LDATE := LDATE#2026-01-31;
ltod : LTOD := LTOD#13:05:00.123456789; ldt : LDT := LDT#2026-01-31-13:05:00.5;)",
                     "");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "d") == "D#2026-01-31");
    CHECK(r.var("Main", "tod1") == "TOD#13:05:00");
    CHECK(r.var("Main", "tod2") == "TOD#13:05:00.25");
    CHECK(r.var("Main", "dt1") == "DT#2026-01-31-13:05:00");
    CHECK(r.var("Main", "ld") == "D#2026-01-31");
    CHECK(r.var("Main", "ltod") == "TOD#13:05:00.123456789");
    CHECK(r.var("Main", "ldt") == "DT#2026-01-31-13:05:00.5");
}

TEST_CASE("dump of strings and characters as JSON strings", "[dump]") {
    auto r = runMain(R"(s : STRING := 'Hello'; e : STRING; q : STRING := 'say $'hi$''; c : CHAR := CHAR#'A';
ws : WSTRING := "wide"; wc : WCHAR := WCHAR#"W"; nl : STRING := 'a$Nb';)",
                     "");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "s") == "Hello");
    CHECK(r.var("Main", "e") == "");
    CHECK(r.var("Main", "q") == "say 'hi'");
    CHECK(r.var("Main", "c") == "A");
    CHECK(r.var("Main", "ws") == "wide");
    CHECK(r.var("Main", "wc") == "W");
    CHECK(r.var("Main", "nl") == "a\nb");
}

TEST_CASE("dump of REAL uses the shortest text that reads back as the REAL", "[dump]") {
    auto r = runMain("r : REAL := 0.1; l : LREAL := 0.1; third : REAL := 1.0; big : REAL := 1.0E30; neg : LREAL := -2.5; whole : REAL := 3.0;",
                     "third := third / 3.0;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "r").is_number_float());
    CHECK(r.var("Main", "r").dump() == "0.1");
    CHECK(r.var("Main", "l").dump() == "0.1");
    CHECK(r.var("Main", "third").get<double>() == Approx(0.33333334).epsilon(1e-9));
    CHECK(r.var("Main", "third").get<double>() == 0.33333334);
    CHECK(r.var("Main", "big").get<double>() == 1e30);
    CHECK(r.var("Main", "neg") == -2.5);
    CHECK(r.var("Main", "whole") == 3.0);
}

TEST_CASE("dump of infinities and NaN as strings", "[dump]") {
    sema::TypeTable table;
    const sema::Type* real = table.elementary(sema::TK::Real);
    const sema::Type* lreal = table.elementary(sema::TK::LReal);
    uint8_t buf[8];
    float f = std::numeric_limits<float>::infinity();
    std::memcpy(buf, &f, 4);
    CHECK(project::valueToJson(real, buf) == "inf");
    f = -f;
    std::memcpy(buf, &f, 4);
    CHECK(project::valueToJson(real, buf) == "-inf");
    double d = std::nan("");
    std::memcpy(buf, &d, 8);
    CHECK(project::valueToJson(lreal, buf) == "nan");
    d = -std::numeric_limits<double>::infinity();
    std::memcpy(buf, &d, 8);
    CHECK(project::valueToJson(lreal, buf) == "-inf");
}

TEST_CASE("dump of enumerations by name and an unnamed value as its number", "[dump]") {
    auto r = runSt(R"(
TYPE Color : (RED, GREEN := 5, BLUE); END_TYPE
PROGRAM Main
VAR c : Color := BLUE; g : Color := GREEN; odd : Color; END_VAR
odd := Color#RED;
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "c") == "BLUE");
    CHECK(r.var("Main", "g") == "GREEN");
    CHECK(r.var("Main", "odd") == "RED");
    const sema::Type* color = r.compiled->typeOf("Main", "c");
    REQUIRE(color != nullptr);
    int16_t raw = 6;
    CHECK(project::valueToJson(color, reinterpret_cast<const uint8_t*>(&raw)) == "BLUE");
    raw = 3;  // not a declared value
    CHECK(project::valueToJson(color, reinterpret_cast<const uint8_t*>(&raw)) == 3);
}

TEST_CASE("dump of arrays lowest index first and multi-dimensional as nested arrays", "[dump]") {
    auto r = runMain("a : ARRAY[-1..1] OF INT := [1, 2, 3]; m : ARRAY[1..2, 0..2] OF SINT := [1, 2, 3, 4, 5, 6]; "
                     "cube : ARRAY[0..1, 0..1, 0..1] OF BOOL; s : ARRAY[1..2] OF STRING[3] := ['ab', 'cd'];",
                     "cube[1, 0, 1] := TRUE;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "a") == json::parse("[1,2,3]"));
    CHECK(r.var("Main", "m") == json::parse("[[1,2,3],[4,5,6]]"));
    CHECK(r.var("Main", "cube") == json::parse("[[[false,false],[false,false]],[[false,true],[false,false]]]"));
    CHECK(r.var("Main", "s") == json::parse(R"(["ab","cd"])"));
}

TEST_CASE("dump of structures and FB instances as objects in declaration order", "[dump]") {
    auto r = runSt(R"(
TYPE Inner : STRUCT v : INT; END_STRUCT; END_TYPE
TYPE Outer : STRUCT
    name : STRING[4];
    items : ARRAY[1..2] OF Inner;
    flag : BOOL;
END_STRUCT; END_TYPE
FUNCTION_BLOCK Fb
VAR_INPUT inp : INT; END_VAR
VAR_OUTPUT out : INT; END_VAR
VAR hidden : INT; p : POINTER TO INT; END_VAR
hidden := inp; out := inp * 2;
END_FUNCTION_BLOCK
PROGRAM Main
VAR o : Outer; f : Fb; END_VAR
o.name := 'ab'; o.items[2].v := 7; o.flag := TRUE;
f(inp := 3);
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "o").dump() == R"({"name":"ab","items":[{"v":0},{"v":7}],"flag":true})");
    // Every member of an instance appears, internal ones too; pointers do not.
    CHECK(r.var("Main", "f").dump() == R"({"inp":3,"out":6,"hidden":3})");
}

TEST_CASE("dump omits pointers references and interfaces of programs and globals", "[dump]") {
    auto good = runSt(R"(
INTERFACE I
END_INTERFACE
VAR_GLOBAL
    gp : POINTER TO INT;
    gv : INT := 1;
    garr : ARRAY[1..2] OF POINTER TO INT;
END_VAR
PROGRAM Main
VAR x : INT; p : POINTER TO INT; r : REFERENCE TO INT; i : I; ps : ARRAY[0..1] OF POINTER TO INT; END_VAR
p := ADR(x);
END_PROGRAM
)");
    INFO(good.compiled->printed());
    REQUIRE(good.ok());
    CHECK(good.programs["Main"].dump() == R"({"x":0})");
    CHECK(good.globals.dump() == R"({"gv":1})");
}

TEST_CASE("dump shows program inputs outputs and the instance name of a configuration", "[dump]") {
    auto r = runSt(R"(
VAR_GLOBAL level : INT := 3; END_VAR
PROGRAM Pump
VAR_INPUT setpoint : INT; END_VAR
VAR_OUTPUT running : BOOL; END_VAR
VAR speed : INT; END_VAR
speed := setpoint * 2;
running := speed > 0;
END_PROGRAM
CONFIGURATION Plant
    RESOURCE Cpu ON PLC
        TASK Fast (INTERVAL := T#5ms, PRIORITY := 1);
        PROGRAM P1 WITH Fast : Pump (setpoint := level);
    END_RESOURCE
END_CONFIGURATION
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    REQUIRE(r.programs.contains("P1"));
    CHECK(r.programs["P1"].dump() == R"({"setpoint":3,"running":true,"speed":6})");
    CHECK(r.globals["level"] == 3);
}
