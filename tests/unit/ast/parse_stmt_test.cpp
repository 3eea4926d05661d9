// Statements: assignments of every kind, calls, control flow, labels.
#include <catch2/catch.hpp>

#include "parse_test_support.h"

using namespace strun::ast;
using strun::ast::test::parse;
using strun::ast::test::stmts;

TEST_CASE("statements: assignments", "[parser][stmt]") {
    CHECK(stmts("x := 1;") == "{(:= x 1)}");
    CHECK(stmts("a.b[1] := c;") == "{(:= ([] (. a b) 1) c)}");
    CHECK(stmts("p^ := 5;") == "{(:= (^ p) 5)}");
    CHECK(stmts("q S= a;") == "{(S= q a)}");
    CHECK(stmts("q R= a;") == "{(R= q a)}");
    CHECK(stmts("q s= a; q r= b;") == "{(S= q a) (R= q b)}");
    CHECK(stmts("itf ?= obj;") == "{(?= itf obj)}");
    CHECK(stmts("r REF= x;") == "{(REF= r x)}");
    // Variables called S and R still work everywhere else.
    CHECK(stmts("IF S=1 THEN R := S; END_IF") == "{(if (= S 1) {(:= R S)})}");
    CHECK(stmts("S := R = 2;") == "{(:= S (= R 2))}");
    CHECK(stmts("x.3 := TRUE;") == "{(:= (. x 3) TRUE)}");
    CHECK(stmts("%QX0.1 := TRUE;") == "{(:= %QX0.1 TRUE)}");
}

TEST_CASE("statements: calls", "[parser][stmt]") {
    CHECK(stmts("f();") == "{(call-stmt (call f))}");
    CHECK(stmts("fb(IN := x, PT := T#5s, Q => done);") == "{(call-stmt (call fb IN:=x PT:=T#5s Q=>done))}");
    CHECK(stmts("obj.m(1);") == "{(call-stmt (call (. obj m) 1))}");
    CHECK(stmts("THIS^.m();") == "{(call-stmt (call (. (^ THIS) m)))}");
    CHECK(stmts("SUPER^();") == "{(call-stmt (call (^ SUPER)))}");
    CHECK(stmts("arr[i].m();") == "{(call-stmt (call (. ([] arr i) m)))}");
    CHECK(stmts("fb(NOT q => x);") == "{(call-stmt (call fb NOT q=>x))}");
}

TEST_CASE("statements: IF / ELSIF / ELSE", "[parser][stmt]") {
    CHECK(stmts("IF a THEN x := 1; END_IF;") == "{(if a {(:= x 1)})}");
    CHECK(stmts("IF a THEN x := 1; ELSIF b THEN x := 2; ELSIF c THEN ELSE x := 3; END_IF") ==
          "{(if a {(:= x 1)} b {(:= x 2)} c {} else {(:= x 3)})}");
    CHECK(stmts("if a then if b then x := 1; end_if end_if") == "{(if a {(if b {(:= x 1)})})}");
    CHECK(stmts("IF a THEN ELSE END_IF") == "{(if a {} else {})}");
}

TEST_CASE("statements: CASE", "[parser][stmt]") {
    CHECK(stmts("CASE x OF 1, 2: y := 1; 3..5: y := 2; z := 3; Red: y := 4; Color.Red: ; ELSE y := 0; END_CASE") ==
          "{(case x [1,2: {(:= y 1)}] [3..5: {(:= y 2) (:= z 3)}] [Red: {(:= y 4)}] [(. Color Red): {;}] else "
          "{(:= y 0)})}");
    CHECK(stmts("CASE x OF -1: y := 1; 10, 20..30, k: END_CASE") == "{(case x [(neg 1): {(:= y 1)}] [10,20..30,k: {}])}");
    CHECK(stmts("CASE s OF Idle: IF go THEN s := Run; END_IF Run: s := Idle; END_CASE") ==
          "{(case s [Idle: {(if go {(:= s Run)})}] [Run: {(:= s Idle)}])}");
    CHECK(stmts("CASE x OF 1: CASE y OF 2: z := 1; END_CASE 3: z := 2; END_CASE") ==
          "{(case x [1: {(case y [2: {(:= z 1)}])}] [3: {(:= z 2)}])}");
    CHECK(stmts("CASE x OF ELSE y := 1; END_CASE") == "{(case x else {(:= y 1)})}");
    CHECK(stmts("CASE x OF INT#1: y := 1; END_CASE") == "{(case x [INT#1: {(:= y 1)}])}");
}

TEST_CASE("statements: loops and jumps", "[parser][stmt]") {
    CHECK(stmts("FOR i := 1 TO 10 DO s := s + i; END_FOR") == "{(for i 1 10 {(:= s (+ s i))})}");
    CHECK(stmts("FOR i := n TO 0 BY -1 DO EXIT; END_FOR;") == "{(for i n 0 (neg 1) {EXIT})}");
    CHECK(stmts("WHILE a < 10 DO a := a + 1; CONTINUE; END_WHILE") == "{(while (< a 10) {(:= a (+ a 1)) CONTINUE})}");
    CHECK(stmts("REPEAT a := a + 1; UNTIL a > 5 END_REPEAT") == "{(repeat {(:= a (+ a 1))} (> a 5))}");
    CHECK(stmts("RETURN;") == "{RETURN}");
    CHECK(stmts("JMP done; x := 1; done: x := 2;") == "{(jmp done) (:= x 1) (label done) (:= x 2)}");
    CHECK(stmts("lbl: ; ;") == "{(label lbl) ; ;}");
    CHECK(stmts("x := 1; ;") == "{(:= x 1) ;}");
    CHECK(stmts(";") == "{}");  // right after the header: the header's ';' (TwinCAT `PROGRAM P;`, decision 0200)
    CHECK(stmts("") == "{}");
}

// Since decision 0158 a jump label is an expression statement ending in ':'
// and the ';' after END_IF and the like an empty statement the builder drops.
TEST_CASE("statements: labels, CASE labels and the ';' after END_xxx", "[parser][stmt]") {
    CHECK(stmts("IF a THEN x := 1; END_IF;;") == "{(if a {(:= x 1)}) ;}");
    CHECK(stmts("WHILE a DO END_WHILE; FOR i := 1 TO 2 DO END_FOR; REPEAT UNTIL a END_REPEAT; x := 1;") ==
          "{(while a {}) (for i 1 2 {}) (repeat {} a) (:= x 1)}");
    CHECK(stmts("CASE x OF 1: IF a THEN lbl: y := 1; END_IF; 2, 3: JMP lbl; END_CASE;") ==
          "{(case x [1: {(if a {(label lbl) (:= y 1)})}] [2,3: {(jmp lbl)}])}");
    CHECK(stmts("CASE x OF 1: y := 1; -2: y := 2; 3..4, 16#FF: y := 3; Color.Red: y := 4; END_CASE") ==
          "{(case x [1: {(:= y 1)}] [(neg 2): {(:= y 2)}] [3..4,16#FF: {(:= y 3)}] [(. Color Red): {(:= y 4)}])}");
    CHECK(stmts("a.b: x := 1;") == "ERRORS: 2:1: syntax error: 'a.b' cannot be a label: a jump label is a name followed by ':'\n");
    CHECK(stmts("f(1):") == "ERRORS: 2:1: syntax error: 'f(1)' cannot be a label: a jump label is a name followed by ':'\n");
}

// Since decision 0159 the labels of a CASE branch are a statement ending in
// ':' too (with `..` and `,`), and the builder splits the CASE's statement
// list into branches at them.
TEST_CASE("statements: CASE labels are statements the builder groups", "[parser][stmt]") {
    CHECK(stmts("CASE x OF 1..2, 5: a := 1; b := 2; 3: ; 4: END_CASE") ==
          "{(case x [1..2,5: {(:= a 1) (:= b 2)}] [3: {;}] [4: {}])}");
    CHECK(stmts("CASE x OF lbl: y := 1; END_CASE") == "{(case x [lbl: {(:= y 1)}])}");  // a label of the CASE, not a jump label
    CHECK(stmts("CASE x OF y := 1; 1: y := 2; END_CASE") ==
          "ERRORS: 2:11: syntax error: expected a CASE label ('value:') before the first statement of a CASE\n");
    CHECK(stmts("1, 2: y := 1;") ==
          "ERRORS: 2:1: syntax error: '1, 2:' are CASE labels outside a CASE: a jump label is a name followed by ':'\n");
    CHECK(stmts("5..9: y := 1;") ==
          "ERRORS: 2:1: syntax error: '5..9:' are CASE labels outside a CASE: a jump label is a name followed by ':'\n");
    // The word after a label without its ':' reads as the S of `x S= y`: the message names the word.
    CHECK(stmts("CASE x OF 1 y := 2; END_CASE") == "ERRORS: 2:13: syntax error: unexpected 'y', expected ':=', ';' or ':'\n");
    CHECK(stmts("x y;") == "ERRORS: 2:3: syntax error: unexpected 'y', expected ':=', ';' or ':'\n");
}

TEST_CASE("statements: locations", "[parser][stmt]") {
    auto p = parse("PROGRAM P\nIF a THEN\n    x := 1;\nELSIF b THEN\n  y := 2;\nEND_IF\nEND_PROGRAM");
    REQUIRE(p->errors() == "");
    const Pou& pou = *p->unit.pous[0];
    const Stmt& s = *pou.body.at(0);
    CHECK(s.loc.line == 2);
    CHECK(s.loc.col == 1);
    CHECK(s.blocks.at(0).at(0)->loc.line == 3);
    CHECK(s.blocks.at(0).at(0)->loc.col == 5);
    CHECK(s.conds.at(1)->loc.line == 4);
    CHECK(s.conds.at(1)->loc.col == 7);
    CHECK(pou.endLoc.line == 7);
}

TEST_CASE("statements: the error-recovery parse gives the same tree", "[parser][stmt]") {
    // A syntax error anywhere makes the whole file go through the slower
    // full-LL parse; the parts without errors must come out the same.
    const std::string caseText =
        "CASE s OF Idle: x := 1; Color.Red, 3..4: y S= z; ELSE lbl: JMP lbl; END_CASE\n"
        "IF S=1 THEN R := S; END_IF\n";
    auto clean = parse("PROGRAM P\n" + caseText + "END_PROGRAM\n");
    auto broken = parse("PROGRAM P\n" + caseText + "END_PROGRAM\nPROGRAM Q\nx := ;\nEND_PROGRAM\n");
    REQUIRE(clean->errors() == "");
    REQUIRE(broken->errors() == "6:6: syntax error: unexpected ';', expected an expression\n");
    CHECK(dump(broken->unit.pous.at(0)->body) == dump(clean->unit.pous.at(0)->body));
    CHECK(dump(clean->unit.pous.at(0)->body) ==
          "{(case s [Idle: {(:= x 1)}] [(. Color Red),3..4: {(S= y z)}] else {(label lbl) (jmp lbl)}) "
          "(if (= S 1) {(:= R S)})}");
}
