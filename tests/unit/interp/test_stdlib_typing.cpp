// Type checking of the standard-library functions (interpreter/builtins): generic
// parameters resolved at check time, result types, constant folding of
// literal calls, and the errors for wrong arguments.
#include <catch2/catch.hpp>

#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

namespace {
// Compiles `body` in PROGRAM Main with a standard set of variables.
// With --strict: these tests pin the IEC typing of the library's results.
std::unique_ptr<Compiled> check(const std::string& body) {
    return compileMain(
        "i : INT; si : SINT; d : DINT; l : LINT; u : UINT; r : REAL; lr : LREAL; b : BOOL; bt : BYTE; w : WORD;"
        " t : TIME; lt : LTIME; s : STRING; ws : WSTRING; dt1 : DT; tod1 : TOD; d1 : DATE;",
        body, true);
}

void requireOk(const std::string& body) {
    auto c = check(body);
    INFO(body << "\n" << c->printed());
    REQUIRE(c->ok());
}

void requireError(const std::string& body, const std::string& text) {
    auto c = check(body);
    INFO(body << "\n" << c->printed());
    REQUIRE_FALSE(c->ok());
    CHECK(c->hasError(text));
}
}  // namespace

TEST_CASE("ABS, MAX, MIN, LIMIT keep the operand type", "[stdlib][typing]") {
    requireOk("i := ABS(i); si := ABS(si); r := ABS(r); t := MAX(t, T#1s); s := MIN(s, 'x');");
    requireOk("i := MAX(i, 3, -2); i := LIMIT(0, i, 100); d := MAX(i, d);");
    requireError("i := MAX(i, d);", "implicit conversion from DINT to INT");
    requireError("i := ABS(r);", "implicit conversion from REAL to INT");
}

TEST_CASE("ANY_REAL functions follow the implicit-conversion lattice", "[stdlib][typing]") {
    requireOk("r := SQRT(i); lr := SQRT(d); r := SIN(r); lr := EXPT(lr, 2); r := ATAN2(r, r);");
    requireError("r := SQRT(d);", "implicit conversion from LREAL to REAL");
    requireError("i := SQRT(i);", "implicit conversion from REAL to INT");
}

TEST_CASE("calls on literals fold to untyped constants", "[stdlib][typing]") {
    // An untyped result fits any variable its value fits, like an operator on literals.
    requireOk("si := MAX(1, 2); bt := ABS(-7); r := SQRT(2.0); u := ADD(200, 100);");
    requireError("si := MAX(1, 200);", "outside the range of SINT");
    // Non-constant selector over literals: the result takes the type it is
    // assigned to, like the literals themselves would.
    requireOk("i := SEL(b, 1, 2); bt := MUX(i, 1, 2, 255); u := SEL(b, 0, 65535); r := SEL(b, 1, 2); si := SEL(b, -1, 2);");
    requireOk("si := SEL(b, 1, 2); d := MUX(i, 1, 2, 3);");
}

TEST_CASE("string functions type their inputs and results", "[stdlib][typing]") {
    requireOk("i := LEN(s); s := CONCAT(s, 'a', 'b'); ws := LEFT(ws, 2); i := FIND(ws, \"x\");");
    requireError("i := LEN(5);", "LEN: the input must be a STRING or WSTRING");
    requireError("s := CONCAT(s, ws);", "CONCAT: the inputs must all be STRING");
    requireError("s := MID(s, 1.5, 1);", "lengths and positions must be integers");
    requireError("ws := CONCAT(s, s);", "cannot convert");
}

TEST_CASE("argument binding errors name the parameter", "[stdlib][typing]") {
    requireError("i := LIMIT(MN := 0, IN := i);", "'MX' is missing");
    requireError("i := LIMIT(0, i, 1, 2);", "too many arguments for 'LIMIT'");
    requireError("i := LEFT(IN := s, COUNT := 2);", "'LEFT' has no parameter 'COUNT'");
    requireError("i := MAX(i);", "needs at least 2 inputs");
    requireError("i := SEL(i, 1, 2);", "G must be BOOL");
    requireError("i := SHL(r, 1);", "IN must be a bit string or an integer");
}

TEST_CASE("time functions accept only the standard combinations", "[stdlib][typing]") {
    requireOk("t := ADD_TIME(t, T#1s); tod1 := ADD_TOD_TIME(tod1, t); dt1 := SUB_DT_TIME(dt1, t); t := SUB_DT_DT(dt1, dt1);");
    requireOk("lt := ADD(t, lt); t := MUL_TIME(t, 2.5); t := DIV(t, 4);");
    requireError("t := ADD(d1, t);", "ADD is not defined for DATE and TIME");
    requireError("t := SUB_DATE_DATE(d1, dt1);", "cannot convert");
    requireError("SPLIT_DATE(d1, YEAR => r);", "must be an integer variable");
}

TEST_CASE("conversions through STRING resolve both types", "[stdlib][typing]") {
    requireOk("s := INT_TO_STRING(i); i := STRING_TO_INT(s); ws := TO_WSTRING(r); t := WSTRING_TO_TIME(ws);");
    requireOk("bt := USINT_TO_BCD_BYTE(25); i := BYTE_BCD_TO_INT(bt); b := IS_VALID(r); w := TO_BIG_ENDIAN(w);");
    requireError("i := STRING_TO_INT(ws);", "the input must be STRING");
    requireError("s := INT_TO_STRING(d);", "implicit conversion from DINT to INT");
}
