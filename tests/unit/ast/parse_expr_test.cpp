// Expressions: precedence, associativity, postfix chains, literals, calls.
#include <catch2/catch.hpp>

#include "parse_test_support.h"

using namespace strun::ast;
using strun::ast::test::ex;
using strun::ast::test::parse;

TEST_CASE("expressions: IEC precedence", "[parser][expr]") {
    CHECK(ex("a + b * c") == "(+ a (* b c))");
    CHECK(ex("a * b + c") == "(+ (* a b) c)");
    CHECK(ex("a - b - c") == "(- (- a b) c)");
    CHECK(ex("a / b MOD c * d") == "(* (MOD (/ a b) c) d)");
    CHECK(ex("a ** b ** c") == "(** (** a b) c)");  // left-associative
    CHECK(ex("a * b ** c") == "(* a (** b c))");
    CHECK(ex("-a ** 2") == "(** (neg a) 2)");  // unary binds tighter than **
    CHECK(ex("a ** -b") == "(** a (neg b))");
    CHECK(ex("NOT a AND b") == "(AND (not a) b)");
    CHECK(ex("NOT (a AND b)") == "(not (AND a b))");
    CHECK(ex("a < b = c > d") == "(= (< a b) (> c d))");
    CHECK(ex("a <= b <> c >= d") == "(<> (<= a b) (>= c d))");
    CHECK(ex("a + 1 < b * 2") == "(< (+ a 1) (* b 2))");
    CHECK(ex("a = b AND c <> d") == "(AND (= a b) (<> c d))");
    CHECK(ex("a OR b AND c") == "(OR a (AND b c))");
    CHECK(ex("a OR b XOR c AND d") == "(OR a (XOR b (AND c d)))");
    CHECK(ex("a XOR b OR c") == "(OR (XOR a b) c)");
    CHECK(ex("a & b OR c") == "(OR (AND a b) c)");
    CHECK(ex("a AND_THEN b OR_ELSE c") == "(OR_ELSE (AND_THEN a b) c)");
    CHECK(ex("a OR_ELSE b AND_THEN c") == "(OR_ELSE a (AND_THEN b c))");
    CHECK(ex("(a + b) * c") == "(* (+ a b) c)");
    CHECK(ex("- - a") == "(neg (neg a))");
    CHECK(ex("+a") == "(plus a)");
    CHECK(ex("a and b or not c") == "(OR (AND a b) (not c))");
}

TEST_CASE("expressions: member, index, dereference, bit access", "[parser][expr]") {
    CHECK(ex("a.b.c") == "(. (. a b) c)");
    CHECK(ex("a[i, j]") == "([] a i j)");
    CHECK(ex("a[i][j]") == "([] ([] a i) j)");
    CHECK(ex("a[i + 1].b[2]") == "([] (. ([] a (+ i 1)) b) 2)");
    CHECK(ex("x.3") == "(. x 3)");
    CHECK(ex("s.w.15") == "(. (. s w) 15)");
    CHECK(ex("w.%X3") == "(. w %X3)");
    CHECK(ex("p^") == "(^ p)");
    CHECK(ex("p^.f") == "(. (^ p) f)");
    CHECK(ex("pp^^") == "(^ (^ pp))");
    CHECK(ex("THIS^") == "(^ THIS)");
    CHECK(ex("THIS^.x") == "(. (^ THIS) x)");
    CHECK(ex("SUPER^.m()") == "(call (. (^ SUPER) m))");
    CHECK(ex("%IW2") == "%IW2");
    CHECK(ex("%IX0.1 AND b") == "(AND %IX0.1 b)");
    CHECK(ex("-x.3") == "(neg (. x 3))");
}

TEST_CASE("expressions: calls with formal and positional arguments", "[parser][expr]") {
    CHECK(ex("f()") == "(call f)");
    CHECK(ex("f(1, a + b)") == "(call f 1 (+ a b))");
    CHECK(ex("f(IN := 1, PT := T#1s)") == "(call f IN:=1 PT:=T#1s)");
    CHECK(ex("f(a := 1, q => out, NOT nq => out2)") == "(call f a:=1 q=>out NOT nq=>out2)");
    CHECK(ex("f(a :=, q =>)") == "(call f a:= q=>)");
    CHECK(ex("f(NOT b)") == "(call f (not b))");
    CHECK(ex("obj.m(1)") == "(call (. obj m) 1)");
    CHECK(ex("arr[i].m()") == "(call (. ([] arr i) m))");
    CHECK(ex("THIS^.m()") == "(call (. (^ THIS) m))");
    CHECK(ex("f(g(h(1)))") == "(call f (call g (call h 1)))");
    CHECK(ex("getObj().x") == "(. (call getObj) x)");
    CHECK(ex("MAX(a, b) + 1") == "(+ (call MAX a b) 1)");
    CHECK(ex("REF(x)") == "(call REF x)");
    CHECK(ex("rs(SET := a, RESET1 := b)") == "(call rs SET:=a RESET1:=b)");
}

TEST_CASE("expressions: a parameter is named by a plain name", "[parser][expr]") {
    CHECK(ex("f(NOT a => b, c => d)") == "(call f NOT a=>b c=>d)");
    auto dotted = parse("PROGRAM P\nx := f(a.b := 1);\nEND_PROGRAM");
    CHECK(dotted->errors() == "2:8: syntax error: 'a.b' cannot name a parameter: expected 'name := ...'\n");
    auto negatedInput = parse("PROGRAM P\nx := f(NOT a := 1);\nEND_PROGRAM");
    CHECK(negatedInput->errors() == "2:8: syntax error: 'NOT a' cannot name a parameter: expected 'name := ...'\n");
}

TEST_CASE("expressions: a chain deeper than the limit is refused before it is built", "[parser][expr]") {
    std::string chain = "x := 1";
    for (int i = 0; i < 2000; ++i) chain += " * 2";  // the limit, kMaxExpressionDepth
    auto p = parse("PROGRAM P\n" + chain + ";\nEND_PROGRAM");
    CHECK(p->errors() == "2:6: syntax error: expression too complex: more than 2000 nested operations\n");
    // 2000 operators whose tree is only 1001 deep (each product is a leaf of the sum chain) are fine.
    std::string sums = "x := 1";
    for (int i = 0; i < 1000; ++i) sums += " + 2 * 3";
    CHECK(parse("PROGRAM P\n" + sums + ";\nEND_PROGRAM")->errors() == "");
}

TEST_CASE("expressions: literals keep their whole text", "[parser][expr]") {
    auto lit = [](const std::string& text) {
        auto p = parse("PROGRAM P\nx := " + text + ";\nEND_PROGRAM");
        REQUIRE(p->errors() == "");
        REQUIRE(p->unit.pous.size() == 1);
        const Expr& e = *p->unit.pous[0]->body.at(0)->expr;
        REQUIRE(e.kind == ExprKind::Literal);
        CHECK(e.text == text);
        return std::make_tuple(e.lit, e.typePrefix, e.valueText);
    };
    CHECK(std::get<0>(lit("123")) == LitKind::Integer);
    CHECK(std::get<0>(lit("16#FF")) == LitKind::Integer);
    CHECK(std::get<0>(lit("2#1010_1010")) == LitKind::Integer);
    CHECK(std::get<0>(lit("8#17")) == LitKind::Integer);
    CHECK(std::get<0>(lit("1_000")) == LitKind::Integer);
    CHECK(std::get<0>(lit("1.5E-3")) == LitKind::Real);
    CHECK(std::get<0>(lit("1.0")) == LitKind::Real);
    CHECK(std::get<0>(lit("3e5")) == LitKind::Real);
    CHECK(std::get<0>(lit("TRUE")) == LitKind::Bool);
    CHECK(std::get<0>(lit("false")) == LitKind::Bool);
    CHECK(std::get<0>(lit("'a$Nb'")) == LitKind::String);
    CHECK(std::get<0>(lit("\"abc\"")) == LitKind::WString);
    CHECK(std::get<0>(lit("T#1h2m3s4ms")) == LitKind::Duration);
    CHECK(std::get<0>(lit("TIME#-5s")) == LitKind::Duration);
    CHECK(std::get<0>(lit("LT#1us")) == LitKind::Duration);
    CHECK(std::get<0>(lit("LTIME#1.5s")) == LitKind::Duration);
    CHECK(std::get<0>(lit("t#1d_2h")) == LitKind::Duration);
    CHECK(std::get<0>(lit("D#2026-01-31")) == LitKind::Date);
    CHECK(std::get<0>(lit("LDATE#2026-01-31")) == LitKind::Date);
    CHECK(std::get<0>(lit("TOD#13:05:00.25")) == LitKind::TimeOfDay);
    CHECK(std::get<0>(lit("LTOD#13:05:00")) == LitKind::TimeOfDay);
    CHECK(std::get<0>(lit("DT#2026-01-31-13:05:00")) == LitKind::DateTime);
    CHECK(std::get<0>(lit("LDT#2026-01-31-13:05:00")) == LitKind::DateTime);
    CHECK(lit("INT#-5") == std::make_tuple(LitKind::Typed, std::string("INT"), std::string("-5")));
    CHECK(lit("WORD#16#FFFF") == std::make_tuple(LitKind::Typed, std::string("WORD"), std::string("16#FFFF")));
    CHECK(lit("REAL#1.0") == std::make_tuple(LitKind::Typed, std::string("REAL"), std::string("1.0")));
    CHECK(lit("BOOL#1") == std::make_tuple(LitKind::Typed, std::string("BOOL"), std::string("1")));
    CHECK(lit("Color#Red") == std::make_tuple(LitKind::Typed, std::string("Color"), std::string("Red")));
    CHECK(lit("STRING#'x'") == std::make_tuple(LitKind::Typed, std::string("STRING"), std::string("'x'")));
    // A negative number is a unary minus applied to the literal.
    CHECK(ex("-5") == "(neg 5)");
    CHECK(ex(std::string(5000, '7')) == std::string(5000, '7'));
}

TEST_CASE("expressions: every node has the location of its first character", "[parser][expr]") {
    auto p = parse("PROGRAM P\n  x :=  a +\n   b[1].c(2);\nEND_PROGRAM", "f.st");
    REQUIRE(p->errors() == "");
    const Stmt& s = *p->unit.pous[0]->body.at(0);
    CHECK(s.loc.line == 2);
    CHECK(s.loc.col == 3);
    CHECK(s.loc.file == 0);
    const Expr& sum = *s.expr;
    CHECK(sum.loc.line == 2);
    CHECK(sum.loc.col == 9);
    const Expr& call = *sum.kids[1];
    CHECK(call.kind == ExprKind::Call);
    CHECK(call.loc.line == 3);
    CHECK(call.loc.col == 4);
    CHECK(call.args.at(0).loc.col == 11);
}
