// The checker builds the fused node shapes of decisions 0154 and 0155 where
// they apply (and the general ones where they do not): the conformance tests
// check the results, these check that the fast forms are really chosen.
#include <catch2/catch.hpp>

#include "interpreter/exec/call_nodes.h"
#include "interpreter/exec/else_nodes.h"
#include "interpreter/exec/fused_nodes.h"
#include "interpreter/exec/string_append_nodes.h"
#include "interpreter/exec/swap_nodes.h"
#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

namespace {

// The statements of POU `name`'s body, in order.
std::vector<exec::Stmt*> bodyOf(const Compiled& c, const std::string& name) {
    for (const auto& code : c.model->codes)
        if (sema::upper(code.name) == sema::upper(name) && code.body) return code.body->stmts;
    FAIL("no POU " << name);
    return {};
}

template <class T>
bool is(exec::Stmt* s) {
    return dynamic_cast<T*>(s) != nullptr;
}

}  // namespace

TEST_CASE("IF and WHILE on a compared variable read it themselves; ELSIF chains are links", "[fused]") {
    auto c = compileSt(R"(
PROGRAM Main
VAR x : DINT; y : INT; z : DINT; END_VAR
IF x > 5 THEN z := 1; END_IF;
WHILE x < 10 DO x := x + 1; END_WHILE;
IF y > 5 THEN z := 2; ELSIF x = 3 THEN z := 3; ELSE z := 4; END_IF;
END_PROGRAM
)");
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    REQUIRE(body.size() == 3);
    CHECK(is<exec::IfCompare<int32_t, exec::BinOp::Gt, exec::OpVar<int32_t, exec::BaseKind::Self>, exec::OpConst<int32_t>>>(body[0]));
    CHECK(is<exec::WhileCompare<int32_t, exec::BinOp::Lt, exec::OpVar<int32_t, exec::BaseKind::Self>, exec::OpConst<int32_t>>>(body[1]));
    // An INT in DINT arithmetic is no fused operand: a general link, whose ELSE is the fused ELSIF.
    auto* first = dynamic_cast<exec::If1Stmt*>(body[2]);
    REQUIRE(first);
    CHECK(is<exec::IfCompare<int32_t, exec::BinOp::Eq, exec::OpVar<int32_t, exec::BaseKind::Self>, exec::OpConst<int32_t>>>(first->otherwise));
}

TEST_CASE("calls bind scalar arguments directly and assign their result without a value node", "[fused]") {
    // Not inlined (decision 0317), so that the call binds all four arguments.
    auto c = compileSt(R"(
FUNCTION F : DINT
VAR_INPUT a : DINT; b : REAL; c : BOOL; d : INT; END_VAR
F := a;
END_FUNCTION
FUNCTION G : DINT
VAR_IN_OUT a : DINT; END_VAR
G := a;
END_FUNCTION
PROGRAM Main
VAR x : DINT; r : REAL; n : DINT; END_VAR
x := F(7, r, TRUE, 3 + 4);
n := G(x);
END_PROGRAM
)", false, false);
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    REQUIRE(body.size() == 2);
    auto* assign = dynamic_cast<exec::AssignCallLocal<int32_t, false>*>(body[0]);
    REQUIRE(assign);
    CHECK(assign->sameType);
    REQUIRE(assign->call->directInputs);
    const auto& binds = assign->call->binds;
    REQUIRE(binds.size() == 4);
    using H = exec::ArgBind::How;
    CHECK(binds[0].how == H::Const4);
    CHECK(binds[0].bits == 7);
    CHECK(binds[1].how == H::CopySelf4);
    CHECK(binds[2].how == H::Const1);
    CHECK(binds[3].how == H::Const2);  // 3 + 4 is folded
    // A VAR_IN_OUT keeps its statement node.
    auto* byRef = dynamic_cast<exec::AssignCallLocal<int32_t, false>*>(body[1]);
    REQUIRE(byRef);
    CHECK_FALSE(byRef->call->directInputs);
    auto r = runSt(R"(
FUNCTION F : DINT
VAR_INPUT a : DINT; b : REAL; c : BOOL; d : INT; END_VAR
F := a * 1000 + REAL_TO_DINT(b) * 100 + BOOL_TO_DINT(c) * 10 + d;
END_FUNCTION
PROGRAM Main
VAR x : DINT; r : REAL := 2.0; END_VAR
x := F(7, r, TRUE, 3 + 4);
END_PROGRAM
)");
    REQUIRE(r.ok());
    CHECK(r.var("Main", "x") == 7217);
}

TEST_CASE("x := a OP b and a[i] := v store without a separate value or place node", "[fused]") {
    auto c = compileSt(R"(
PROGRAM Main
VAR x : DINT; y : DINT; a : ARRAY[0..3] OF DINT; f : ARRAY[0..3] OF BOOL; s : INT; END_VAR
x := x * y;
a[y] := x;
f[y] := TRUE;
s := s * s;
END_PROGRAM
)");
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    REQUIRE(body.size() == 4);
    using Self = exec::OpVar<int32_t, exec::BaseKind::Self>;
    CHECK(is<exec::AssignBinLocal<int32_t, exec::BinOp::Mul, Self, Self, false>>(body[0]));
    CHECK(is<exec::AssignIndex1<int32_t, exec::BaseKind::Self, exec::IndexFrom::Self32>>(body[1]));
    CHECK(is<exec::AssignConstIndex1<uint8_t, exec::BaseKind::Self, exec::IndexFrom::Self32>>(body[2]));
    CHECK_FALSE(is<exec::AssignBinLocal<int32_t, exec::BinOp::Mul, Self, Self, false>>(body[3]));  // INT target: general form
}

TEST_CASE("s := CONCAT(s, ...) appends in place only when the pieces cannot touch s", "[fused]") {
    auto c = compileSt(R"(
FUNCTION P : STRING
P := 'p';
END_FUNCTION
PROGRAM Main
VAR s : STRING[20]; t : STRING[5] := 'ab'; END_VAR
s := CONCAT(s, 'x', t);
s := CONCAT(s, s);
s := CONCAT(s, P());
t := CONCAT(s, 'x');
END_PROGRAM
)");
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    REQUIRE(body.size() == 4);
    auto* append = dynamic_cast<exec::AppendInPlace<char, exec::BaseKind::Self>*>(body[0]);
    REQUIRE(append);
    CHECK(append->limit == 20);
    CHECK(append->pieces.size() == 2);
    CHECK_FALSE(is<exec::AppendInPlace<char, exec::BaseKind::Self>>(body[1]));
    CHECK_FALSE(is<exec::AppendInPlace<char, exec::BaseKind::Self>>(body[2]));
    CHECK_FALSE(is<exec::AppendInPlace<char, exec::BaseKind::Self>>(body[3]));
}

TEST_CASE("nested arithmetic, MOD tests, element comparisons, BOOL elements and conversions over arithmetic are fused", "[fused]") {
    // decision 0262: the shapes of issue 28 item 4, with the operand kinds as data.
    auto c = compileSt(R"(
FUNCTION F : DINT
VAR_INPUT n : DINT; END_VAR
VAR k : DINT; END_VAR
k := 3 * n + 1;
F := k;
END_FUNCTION
PROGRAM Main
VAR x : LINT; a : ARRAY[1..4] OF DINT; j : DINT := 1; flags : ARRAY[0..3] OF BOOL; i : DINT; r : REAL; d : DINT; b : BOOL; s : INT; END_VAR
x := 3 * x + 1;
IF x MOD 2 = 0 THEN x := x / 2; END_IF;
IF a[j] > a[j + 1] THEN j := 0; END_IF;
IF flags[i] THEN i := 1; ELSIF b THEN i := 2; END_IF;
d := REAL_TO_DINT(r * 10.0);
WHILE a[i] < a[i + 1] DO i := i + 1; END_WHILE;
s := 3 * s + 1;
d := F(d);
END_PROGRAM
)");
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    REQUIRE(body.size() == 8);
    using Node64 = exec::OpNode<int64_t>;
    using K64 = exec::OpConst<int64_t>;
    CHECK(is<exec::AssignBinLocal<int64_t, exec::BinOp::Add, Node64, K64, false>>(body[0]));
    CHECK(is<exec::IfCompare<int64_t, exec::BinOp::Eq, Node64, K64>>(body[1]));
    CHECK(is<exec::IfCompare<int32_t, exec::BinOp::Gt, exec::OpElem<int32_t>, exec::OpElem<int32_t>>>(body[2]));
    auto* flag = dynamic_cast<exec::IfBool<exec::OpElem<uint8_t>>*>(body[3]);
    REQUIRE(flag);
    CHECK(is<exec::IfBool<exec::OpVar<uint8_t, exec::BaseKind::Self>>>(flag->otherwise));
    auto* conv = dynamic_cast<exec::AssignLocal<int32_t, false>*>(body[4]);
    REQUIRE(conv);
    CHECK(dynamic_cast<exec::RealBinToInt<float, exec::BinOp::Mul, exec::OpVar<float, exec::BaseKind::Self>, exec::OpConst<float>>*>(conv->value));
    CHECK(is<exec::WhileCompare<int32_t, exec::BinOp::Lt, exec::OpElem<int32_t>, exec::OpElem<int32_t>>>(body[5]));
    // An INT target is no fused destination; its DINT arithmetic stays general.
    CHECK_FALSE(is<exec::AssignBinLocal<int32_t, exec::BinOp::Add, exec::OpNode<int32_t>, exec::OpConst<int32_t>, false>>(body[6]));
    // In a function the same shapes read the frame.
    auto fbody = bodyOf(*c, "F");
    REQUIRE(fbody.size() == 2);
    CHECK(is<exec::AssignBinLocal<int32_t, exec::BinOp::Add, exec::OpNode<int32_t>, exec::OpConst<int32_t>, true>>(fbody[0]));
}

TEST_CASE("a short ELSE runs without its Block; a longer one, one with labels and an ELSIF stay as they were", "[fused]") {
    auto c = compileSt(R"(
PROGRAM Main
VAR x : DINT; y : INT; f : BOOL; z : DINT; END_VAR
IF x > 5 THEN z := 1; ELSE z := 2; END_IF;
IF f THEN z := 1; ELSE z := 2; x := 3; END_IF;
IF y > 5 THEN z := 1; ELSE z := 2; x := 3; y := 4; END_IF;
IF x > 5 THEN z := 1; ELSIF f THEN z := 2; ELSE END_IF;
IF x > 5 THEN z := 1; ELSE JMP l; l: z := 2; END_IF;
END_PROGRAM
)");
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    REQUIRE(body.size() == 5);
    using IfX = exec::IfCompare<int32_t, exec::BinOp::Gt, exec::OpVar<int32_t, exec::BaseKind::Self>, exec::OpConst<int32_t>>;
    using IfF = exec::IfBool<exec::OpVar<uint8_t, exec::BaseKind::Self>>;
    auto* one = dynamic_cast<IfX*>(body[0]);
    REQUIRE(one);
    auto* oneElse = dynamic_cast<exec::ElseStmts*>(one->otherwise);
    REQUIRE(oneElse);
    CHECK(oneElse->s0);
    CHECK_FALSE(oneElse->s1);
    auto* two = dynamic_cast<IfF*>(body[1]);
    REQUIRE(two);
    auto* twoElse = dynamic_cast<exec::ElseStmts*>(two->otherwise);
    REQUIRE(twoElse);
    CHECK(twoElse->s1);
    auto* three = dynamic_cast<exec::If1Stmt*>(body[2]);  // an INT in DINT arithmetic: the general link
    REQUIRE(three);
    CHECK(is<exec::Block>(three->otherwise));
    auto* chain = dynamic_cast<IfX*>(body[3]);
    REQUIRE(chain);
    auto* link = dynamic_cast<IfF*>(chain->otherwise);
    REQUIRE(link);
    CHECK_FALSE(link->otherwise);  // an empty ELSE is none
    auto* labelled = dynamic_cast<IfX*>(body[4]);
    REQUIRE(labelled);
    CHECK(is<exec::Block>(labelled->otherwise));
}

TEST_CASE("t := a[i]; a[i] := a[i + 1]; a[i + 1] := t is one swap node, only where it computes the same", "[fused]") {
    auto c = compileSt(R"(
PROGRAM Main
VAR a : ARRAY[1..8] OF DINT; b : ARRAY[1..8] OF LREAL; t : DINT; r : LREAL; i : DINT; s : INT; END_VAR
t := a[i]; a[i] := a[i + 1]; a[i + 1] := t;
r := b[i + 1]; b[i + 1] := b[i - 1]; b[i - 1] := r;
i := a[i]; a[i] := a[i + 1]; a[i + 1] := i;
t := a[i]; a[i] := a[i + 1]; a[i + 2] := t;
s := 1;
END_PROGRAM
)");
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    // 1 + 1 fused; the temporary that is the subscript and the mismatched
    // third statement stay three statements each; then s := 1.
    REQUIRE(body.size() == 9);
    CHECK(is<exec::SwapElems<int32_t>>(body[0]));
    CHECK(body[0]->line == 4);
    CHECK(is<exec::SwapElems<double>>(body[1]));
    for (size_t k = 2; k < 9; ++k) CHECK_FALSE(is<exec::SwapElems<int32_t>>(body[k]));
}

TEST_CASE("IF a OR b, a AND b, a XOR b on BOOL operands evaluate both operands in the IF node", "[fused]") {
    auto c = compileSt(R"(
PROGRAM Main
VAR x : DINT; f : BOOL; g : BOOL; z : DINT; w : WORD; END_VAR
IF x > 5 OR x = 1 THEN z := 1; END_IF;
IF f AND g THEN z := 2; ELSE z := 3; END_IF;
IF f XOR x < 0 THEN z := 4; END_IF;
IF x = 2 THEN z := 5; ELSIF f OR g THEN z := 6; END_IF;
IF (w OR 16#10) = 16#10 THEN z := 7; END_IF;
END_PROGRAM
)");
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    REQUIRE(body.size() == 5);
    auto* either = dynamic_cast<exec::IfLogic<exec::BinOp::Or>*>(body[0]);
    REQUIRE(either);
    CHECK(dynamic_cast<exec::FusedCompare*>(either->l));
    CHECK(dynamic_cast<exec::FusedCompare*>(either->r));
    CHECK_FALSE(either->otherwise);
    auto* both = dynamic_cast<exec::IfLogic<exec::BinOp::And>*>(body[1]);
    REQUIRE(both);
    CHECK(is<exec::ElseStmts>(both->otherwise));
    CHECK(is<exec::IfLogic<exec::BinOp::Xor>>(body[2]));
    auto* link = dynamic_cast<exec::IfCompare<int32_t, exec::BinOp::Eq, exec::OpVar<int32_t, exec::BaseKind::Self>, exec::OpConst<int32_t>>*>(body[3]);
    REQUIRE(link);
    CHECK(is<exec::IfLogic<exec::BinOp::Or>>(link->otherwise));
    // A bit-string OR inside a comparison is no BOOL condition: not an IfLogic.
    CHECK_FALSE(is<exec::IfLogic<exec::BinOp::Or>>(body[4]));
}

TEST_CASE("general integer operators are operands of fused nodes, so that the store and the IF absorb the last one", "[fused]") {
    auto c = compileSt(R"(
PROGRAM Main
VAR x : DINT; y : DINT; d : DINT; l : LINT; m : LINT; s : INT; z : DINT; END_VAR
y := (y * 31 + (x MOD 97) * 3 + 1) MOD 1000003;
IF (x / d + 1) MOD 3 = 0 THEN z := 1; END_IF;
l := (l / m + 1) MOD 7;
s := s + 1;
END_PROGRAM
)");
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    REQUIRE(body.size() == 4);
    using N32 = exec::OpNode<int32_t>;
    using K32 = exec::OpConst<int32_t>;
    auto* store = dynamic_cast<exec::AssignBinLocal<int32_t, exec::BinOp::Mod, N32, K32, false>*>(body[0]);
    REQUIRE(store);
    // y * 31 + ... + 1: the + 1 over the general AddI is a fused node too.
    auto* plusOne = dynamic_cast<exec::FusedBin<int32_t, exec::BinOp::Add, N32, K32>*>(store->l.e);
    REQUIRE(plusOne);
    CHECK(dynamic_cast<exec::AddI<int32_t>*>(plusOne->l.e));
    auto* test = dynamic_cast<exec::IfCompare<int32_t, exec::BinOp::Eq, N32, K32>*>(body[1]);
    REQUIRE(test);
    CHECK(dynamic_cast<exec::FusedBin<int32_t, exec::BinOp::Mod, N32, K32>*>(test->l.e));
    CHECK(is<exec::AssignBinLocal<int64_t, exec::BinOp::Mod, exec::OpNode<int64_t>, exec::OpConst<int64_t>, false>>(body[2]));
    // An INT variable in DINT arithmetic is no operator: x := x + 1 keeps its own node.
    CHECK(is<exec::AddConstLocal<int16_t, exec::BaseKind::Self>>(body[3]));
}

// Decision 0490: a constant divisor +-2^k is a shift operand of the fused
// node and a DivPow2K/ModPow2K of the general ones; any other constant keeps
// OpConst and DivIK/ModIK.
TEST_CASE("a power-of-two constant divisor divides by shifts", "[fused]") {
    auto c = compileSt(R"(
PROGRAM Main
VAR x : DINT := 7; y : DINT; l : LINT := 9; s : INT := 5; u : UDINT := 9; END_VAR
y := x MOD 2;
y := x / 7;
l := l / -4;
s := s MOD 8;
u := u / 3;
END_PROGRAM
)");
    REQUIRE(c->ok());
    auto body = bodyOf(*c, "Main");
    REQUIRE(body.size() == 5);
    using VX = exec::OpVar<int32_t, exec::BaseKind::Self>;
    CHECK(is<exec::AssignBinLocal<int32_t, exec::BinOp::Mod, VX, exec::OpPow2Divisor<int32_t>, false>>(body[0]));
    CHECK(is<exec::AssignBinLocal<int32_t, exec::BinOp::Div, VX, exec::OpConst<int32_t>, false>>(body[1]));
    CHECK(is<exec::AssignBinLocal<int64_t, exec::BinOp::Div, exec::OpVar<int64_t, exec::BaseKind::Self>, exec::OpPow2Divisor<int64_t>, false>>(body[2]));
    auto* narrow = dynamic_cast<exec::AssignLocal<int16_t, false>*>(body[3]);
    REQUIRE(narrow);
    CHECK(dynamic_cast<exec::ModPow2K<int32_t>*>(narrow->value));
    auto* wide = dynamic_cast<exec::AssignLocal<uint32_t, false>*>(body[4]);
    REQUIRE(wide);
    CHECK(dynamic_cast<exec::DivIK<uint32_t>*>(wide->value));
}

// Decision 0493: the fusers' shape test answers as dynamic_cast does.
TEST_CASE("nodeCast finds a final node class by its type and an interface by dynamic_cast", "[fused]") {
    exec::NodePool pool;
    exec::Expr* constant = pool.make<exec::ConstInt>(7);
    exec::Expr* var = pool.make<exec::VarNode<int32_t, exec::BaseKind::Frame>>(8);
    exec::Expr* sum = pool.make<exec::AddIK<int32_t>>(var, 1);
    CHECK(exec::nodeCast<exec::ConstInt>(constant) == constant);
    CHECK(exec::nodeCast<exec::ConstInt>(var) == nullptr);
    CHECK(exec::nodeCast<exec::VarNode<int32_t, exec::BaseKind::Frame>>(var) == var);
    CHECK(exec::nodeCast<exec::VarNode<int32_t, exec::BaseKind::Self>>(var) == nullptr);  // same template, other base
    CHECK(exec::nodeCast<exec::VarNode<int64_t, exec::BaseKind::Frame>>(var) == nullptr);  // other type
    CHECK(exec::nodeCast<exec::AddIK<int32_t>>(sum) == sum);
    CHECK(exec::nodeCast<exec::AddIK<int64_t>>(sum) == nullptr);
    CHECK(exec::nodeCast<exec::IntOperator>(sum) == sum);  // an interface: dynamic_cast
    CHECK(exec::nodeCast<exec::IntOperator>(constant) == nullptr);
    CHECK(exec::nodeCast<exec::ConstInt>(static_cast<exec::Expr*>(nullptr)) == nullptr);
    const exec::Expr* readOnly = constant;
    CHECK(exec::nodeCast<const exec::ConstInt>(readOnly) == constant);
}
