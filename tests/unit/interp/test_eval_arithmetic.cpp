// The evaluator's arithmetic: wrap-around at every integer width, division
// and MOD by zero (DIV_BY_ZERO, divisor 1), MIN / -1, REAL computed in 32
// bits, REAL -> integer rounding (decision 0031) and REAL overflow.
#include <catch2/catch.hpp>

#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;
using json = nlohmann::ordered_json;

TEST_CASE("signed integers wrap at their width on addition", "[eval][wrap]") {
    auto r = runMain(R"(
si : SINT := 127; i : INT := 32767; d : DINT := 2147483647; l : LINT := 9223372036854775807;
nsi : SINT := -128; ni : INT := -32768; nd : DINT := -2147483648; nl : LINT := -9223372036854775808;)",
                     R"(
si := si + 1; i := i + 1; d := d + 1; l := l + 1;
nsi := nsi - 1; ni := ni - 1; nd := nd - 1; nl := nl - 1;)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "si") == -128);
    CHECK(r.var("Main", "i") == -32768);
    CHECK(r.var("Main", "d") == -2147483648LL);
    CHECK(r.var("Main", "l") == std::numeric_limits<int64_t>::min());
    CHECK(r.var("Main", "nsi") == 127);
    CHECK(r.var("Main", "ni") == 32767);
    CHECK(r.var("Main", "nd") == 2147483647);
    CHECK(r.var("Main", "nl") == std::numeric_limits<int64_t>::max());
    CHECK(r.diagnostics.empty());  // overflow is silent
}

TEST_CASE("unsigned integers and bit strings wrap at their width", "[eval][wrap]") {
    auto r = runMain(R"(
us : USINT := 255; ui : UINT := 65535; ud : UDINT := 4294967295; ul : ULINT := 18446744073709551615;
b : BYTE := 255; w : WORD := 65535; dw : DWORD := 4294967295; lw : LWORD := 18446744073709551615;
zus : USINT; zui : UINT; zud : UDINT; zul : ULINT;)",
                     R"(
us := us + 1; ui := ui + 1; ud := ud + 1; ul := ul + 1;
b := b + 1; w := w + 1; dw := dw + 1; lw := lw + 1;
zus := zus - 1; zui := zui - 1; zud := zud - 1; zul := zul - 1;)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    for (const char* name : {"us", "ui", "ud", "ul", "b", "w", "dw", "lw"}) {
        INFO(name);
        CHECK(r.var("Main", name) == 0);
    }
    CHECK(r.var("Main", "zus") == 255);
    CHECK(r.var("Main", "zui") == 65535);
    CHECK(r.var("Main", "zud") == 4294967295ULL);
    CHECK(r.var("Main", "zul") == std::numeric_limits<uint64_t>::max());
}

TEST_CASE("multiplication and negation wrap too", "[eval][wrap]") {
    auto r = runMain("i : INT := 300; m : INT; s : SINT := -128; neg : SINT; d : DINT := 65536; dm : DINT;",
                     "m := i * i; neg := -s; dm := d * d;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "m") == 24464);  // 90000 mod 65536
    CHECK(r.var("Main", "neg") == -128);
    CHECK(r.var("Main", "dm") == 0);
}

TEST_CASE("integer division truncates toward zero and MOD takes the dividend sign", "[eval][division]") {
    auto r = runMain("a : DINT := -7; b : DINT := 2; q : DINT; m : DINT; q2 : DINT; m2 : DINT;",
                     "q := a / b; m := a MOD b; q2 := 7 / b; m2 := 7 MOD -2;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "q") == -3);
    CHECK(r.var("Main", "m") == -1);
    CHECK(r.var("Main", "q2") == 3);
    CHECK(r.var("Main", "m2") == 1);
}

TEST_CASE("division by zero uses divisor 1 and reports DIV_BY_ZERO", "[eval][division]") {
    auto r = runSt(
        "PROGRAM Main\n"
        "VAR a : DINT := 10; z : DINT; q : DINT; m : DINT; u : UINT := 9; uq : UINT; after : BOOL; END_VAR\n"
        "q := a / z;\n"
        "m := a MOD z;\n"
        "uq := u / 0;\n"
        "after := TRUE;\n"
        "END_PROGRAM\n");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "q") == 10);
    CHECK(r.var("Main", "m") == 0);
    CHECK(r.var("Main", "uq") == 9);
    CHECK(r.var("Main", "after") == true);  // execution continues
    CHECK(r.state == rt::PlcState::Run);
    REQUIRE(r.count(rt::DiagCode::DivByZero) == 3);
    const rt::DiagEntry& d = r.diagnostics.front();
    CHECK(d.code == rt::DiagCode::DivByZero);
    CHECK(d.pou == "Main");
    CHECK(d.line == 3);
    CHECK(d.task == "MainTask");
    CHECK(r.diagnostics[1].line == 4);
    CHECK(r.diagnostics[2].line == 5);
}

TEST_CASE("division by zero is reported every cycle it happens", "[eval][division]") {
    auto r = runMain("z : INT; q : INT := 5;", "q := q / z;", 4);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.count(rt::DiagCode::DivByZero) == 4);
    CHECK(r.var("Main", "q") == 5);
}

TEST_CASE("the most negative value divided by -1 wraps to itself", "[eval][division]") {
    auto r = runMain(R"(
si : SINT := -128; i : INT := -32768; d : DINT := -2147483648; l : LINT := -9223372036854775808;
m1 : DINT := -1; ml : LINT := -1;
qsi : SINT; qi : INT; qd : DINT; ql : LINT; md : DINT; mlm : LINT; lit : DINT;)",
                     R"(
qsi := si / DINT_TO_SINT(m1); qi := i / DINT_TO_INT(m1); qd := d / m1; ql := l / ml;
md := d MOD m1; mlm := l MOD ml; lit := d / -1;)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "qsi") == -128);
    CHECK(r.var("Main", "qi") == -32768);
    CHECK(r.var("Main", "qd") == -2147483648LL);
    CHECK(r.var("Main", "ql") == std::numeric_limits<int64_t>::min());
    CHECK(r.var("Main", "md") == 0);
    CHECK(r.var("Main", "mlm") == 0);
    CHECK(r.var("Main", "lit") == -2147483648LL);
    CHECK(r.diagnostics.empty());
}

TEST_CASE("REAL arithmetic is done in 32-bit float and LREAL in 64-bit", "[eval][real]") {
    auto r = runMain(R"(
r : REAL := 16777216.0; l : LREAL := 16777216.0; rd : REAL; ld : LREAL;
tenth : REAL := 0.1; widened : LREAL;)",
                     R"(
r := r + 1.0; l := l + 1.0;
rd := (r + 1.0) - r; ld := (l + 1.0) - l;
widened := tenth;)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "r") == 16777216.0);
    CHECK(r.var("Main", "l") == 16777217.0);
    CHECK(r.var("Main", "rd") == 0.0);
    CHECK(r.var("Main", "ld") == 1.0);
    // A REAL widened to LREAL keeps its float value, which is not 0.1.
    CHECK(r.var("Main", "widened") == static_cast<double>(0.1f));
}

TEST_CASE("REAL to integer conversion rounds half to even", "[eval][real]") {
    auto r = runMain(R"(
a : INT; b : INT; c : INT; d : INT; e : INT; f : INT; g : DINT; h : DINT; k : SINT;
x : REAL := 2.5;)",
                     R"(
a := REAL_TO_INT(0.5); b := REAL_TO_INT(1.5); c := REAL_TO_INT(x);
d := REAL_TO_INT(-2.5); e := REAL_TO_INT(-1.5); f := REAL_TO_INT(2.6);
g := LREAL_TO_DINT(3.5); h := LREAL_TO_DINT(-0.4); k := REAL_TO_SINT(-0.5);)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "a") == 0);
    CHECK(r.var("Main", "b") == 2);
    CHECK(r.var("Main", "c") == 2);
    CHECK(r.var("Main", "d") == -2);
    CHECK(r.var("Main", "e") == -2);
    CHECK(r.var("Main", "f") == 3);
    CHECK(r.var("Main", "g") == 4);
    CHECK(r.var("Main", "h") == 0);
    CHECK(r.var("Main", "k") == 0);
}

TEST_CASE("REAL to integer outside the range wraps to the width", "[eval][real]") {
    auto r = runMain("big : REAL := 40000.0; i : INT; us : USINT; neg : REAL := -1.0; ui : UINT;",
                     "i := REAL_TO_INT(big); us := REAL_TO_USINT(300.0); ui := REAL_TO_UINT(neg);");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "i") == -25536);
    CHECK(r.var("Main", "us") == 44);
    CHECK(r.var("Main", "ui") == 65535);
}

TEST_CASE("REAL overflow gives infinity and zero over zero gives NaN without diagnostics", "[eval][real]") {
    auto r = runMain(R"(
big : REAL := 3.0E38; up : REAL; down : REAL; z : REAL; n : REAL; lz : LREAL; linf : LREAL; one : LREAL := 1.0;)",
                     "up := big * 10.0; down := -big * 10.0; n := z / z; linf := one / lz;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "up") == "inf");
    CHECK(r.var("Main", "down") == "-inf");
    CHECK(r.var("Main", "n") == "nan");
    CHECK(r.var("Main", "linf") == "inf");
    CHECK(r.diagnostics.empty());
}

TEST_CASE("bit string operators work at the width of the type", "[eval][bits]") {
    auto r = runMain("b : BYTE := 16#0F; nb : BYTE; w : WORD := 16#F0F0; a : WORD; o : WORD; x : WORD; flag : BOOL;",
                     "nb := NOT b; a := w AND 16#FF00; o := w OR 16#000F; x := w XOR 16#FFFF; flag := w.4;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "nb") == 0xF0);
    CHECK(r.var("Main", "a") == 0xF000);
    CHECK(r.var("Main", "o") == 0xF0FF);
    CHECK(r.var("Main", "x") == 0x0F0F);
    CHECK(r.var("Main", "flag") == true);
}

TEST_CASE("comparisons across widths compare values", "[eval][compare]") {
    auto r = runMain("s : SINT := -1; u : USINT := 255; d : DINT := 255; lt : BOOL; eq : BOOL; r : REAL := 0.5; gt : BOOL;",
                     "lt := s < u; eq := u = d; gt := r > 0.25;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "lt") == true);
    CHECK(r.var("Main", "eq") == true);
    CHECK(r.var("Main", "gt") == true);
}

TEST_CASE("time arithmetic and negative durations", "[eval][time]") {
    auto r = runMain("t : TIME := T#1s; d : TIME; n : TIME; lt : LTIME := LTIME#1ms;",
                     "d := t + T#500ms; n := T#250ms - t; lt := lt * 3;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "d") == "T#1s500ms");
    CHECK(r.var("Main", "n") == "T#-750ms");
    CHECK(r.var("Main", "lt") == "T#3ms");
}

// Literal operands only: the checker leaves the division for run time (so
// that it reports DIV_BY_ZERO) but then gives it the type LINT, which no
// longer fits the DINT it is assigned to.
TEST_CASE("a division of literals by zero compiles and reports DIV_BY_ZERO at run time", "[eval][division]") {
    auto r = runMain("x : DINT; y : DINT;", "x := 10 / 0;\ny := 7 MOD 0;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "x") == 10);
    CHECK(r.var("Main", "y") == 0);
    CHECK(r.count(rt::DiagCode::DivByZero) == 2);
}

TEST_CASE("a literal divisor keeps the type of the variable operand", "[eval][division]") {
    auto r = runMain("x : DINT := 10; q : DINT; m : SINT := -7; mm : SINT;", "q := x / 4;\nmm := m MOD 4;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "q") == 2);
    CHECK(r.var("Main", "mm") == -3);
}

TEST_CASE("REAL raised to a REAL power stays REAL", "[eval][real]") {
    auto r = runMain("e : REAL := 2.0; p : REAL; l : LREAL := 2.0; lp : LREAL;", "p := e ** e;\nlp := l ** 3.0;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "p") == 4.0);
    CHECK(r.var("Main", "lp") == 8.0);
}

// An untyped real literal adopts REAL with every other operator (r * 10.0 is
// REAL); with ** it settles to LREAL and the REAL assignment is rejected.
TEST_CASE("REAL raised to a real literal stays REAL", "[eval][real]") {
    auto r = runMain("e : REAL := 2.0; p : REAL;", "p := e ** 10.0;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "p") == 1024.0);
}

TEST_CASE("ULINT values above the LINT range compare and divide as unsigned", "[eval][wrap]") {
    auto r = runMain("u : ULINT := 18446744073709551615; gt : BOOL; eq : BOOL; half : ULINT; rest : ULINT; asReal : LREAL;",
                     "gt := u > 5;\neq := u = 18446744073709551615;\nhalf := u / 2;\nrest := u MOD 10;\nasReal := ULINT_TO_LREAL(u);");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "gt") == true);
    CHECK(r.var("Main", "eq") == true);
    CHECK(r.var("Main", "half") == 9223372036854775807ULL);
    CHECK(r.var("Main", "rest") == 5);
    CHECK(r.var("Main", "asReal") == 18446744073709551616.0);
}

TEST_CASE("TIME wraps at its 32-bit millisecond range", "[eval][time]") {
    auto r = runMain("t : TIME := T#24d20h31m23s647ms; z : DINT; d : TIME := T#1s;", "t := t + T#1ms;\nd := d / z;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "t") == "T#-24d20h31m23s648ms");
    CHECK(r.var("Main", "d") == "T#1s");
    CHECK(r.count(rt::DiagCode::DivByZero) == 1);
}
