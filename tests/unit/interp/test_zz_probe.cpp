#include <catch2/catch.hpp>
#include <iostream>
#include "tests/unit/interp/st_run.h"
using namespace strun::test;
static void show(const char* vars, const char* body) {
    auto r = runMain(vars, body);
    std::cout << "---- " << body << "\n" << r.compiled->printed();
    if (r.ok()) {
        std::cout << r.stateName() << " " << r.programs.dump() << "\n";
        for (auto& d : r.diagnostics) std::cout << "  diag " << strun::rt::diagCodeName(d.code) << " " << d.message << "\n";
    }
}
TEST_CASE("probe", "[.probe]") {
    show("u : ULINT := 18446744073709551615; lw : LWORD := 16#FFFFFFFFFFFFFFFF; a,b,c,d,e : BOOL; q : ULINT; m : ULINT;",
         "a := u > 0; b := u > 5; c := lw > 16#1; d := u = 18446744073709551615; q := u / 2; m := u MOD 10; e := u > ULINT#1;");
    show("t : TIME := T#1s; z : DINT; lt : LTIME := LTIME#1s; r : TIME; r2 : LTIME;", "r := t / z; r2 := lt / z;");
    show("x : DINT;", "x := 10 / 0;");
    show("d : DINT := -2147483648; q : DINT; l : LINT := -9223372036854775808; ql : LINT;", "q := d / -1; ql := l / -1;");
    show("r : REAL; z : REAL; i : INT := 5; n : DINT := 5;", "r := z / z; i := REAL_TO_INT(r); n := TRUNC(r);");
    show("u : ULINT := 18446744073709551615; r : LREAL; f : REAL;", "r := ULINT_TO_LREAL(u); f := ULINT_TO_REAL(u);");
    show("s1 : STRING := 'abc'; s2 : STRING := 'abd'; lt, eq : BOOL;", "lt := s1 < s2; eq := s1 = 'abc';");
    show("u : ULINT := 18446744073709551615; k : INT;", "CASE u OF 18446744073709551615: k := 1; ELSE k := 2; END_CASE;");
    show("t : TIME := T#24d20h31m23s647ms;", "t := t + T#1ms;");
    show("x : SINT := 10;", "x := x * 200;");
    show("b : BOOL; i : INT := 3;", "b := i.0;");
    show("e : REAL := 2.0; p : REAL; li : DINT := 2; lp : DINT;", "p := e ** 10.0; lp := li ** 3;");
    show("ud : UDINT := 4294967295; r : BOOL; s : DINT;", "r := ud > 0; s := UDINT_TO_DINT(ud);");
    show("w : WORD := 16#8000; i : INT; d : DINT;", "i := WORD_TO_INT(w); d := w;");
}
