// Small leaf FUNCTIONs inlined at their calls (decision 0317): which calls
// the checker inlines, and that an inlined call behaves as the real one
// (results, the CALL_DEPTH rule, fault locations). The conformance test
// pous/inlined_leaf_functions checks the results through the CLI.
#include <catch2/catch.hpp>

#include "interpreter/exec/call_nodes.h"
#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

namespace {

// The call of FUNCTION `callee` assigned by the `index`-th statement of Main.
exec::CallPou* callIn(const Compiled& c, size_t index) {
    for (const auto& code : c.model->codes)
        if (sema::upper(code.name) == "MAIN" && code.body && index < code.body->stmts.size()) {
            auto* assign = dynamic_cast<exec::AssignCallLocal<int32_t, false>*>(code.body->stmts[index]);
            return assign ? assign->call : nullptr;
        }
    return nullptr;
}

const exec::PouCode& codeOf(const Compiled& c, const std::string& name) {
    for (const auto& code : c.model->codes)
        if (sema::upper(code.name) == sema::upper(name)) return code;
    FAIL("no POU " << name);
    return c.model->codes.front();
}

const char* kCalls = R"(
FUNCTION Leaf : DINT
VAR_INPUT a : DINT; b : DINT := 4; END_VAR
Leaf := a * b;
END_FUNCTION
FUNCTION Caller : DINT
VAR_INPUT a : DINT; END_VAR
Caller := Leaf(a := a) + 1;
END_FUNCTION
FUNCTION Long : DINT
VAR_INPUT a : DINT; END_VAR
Long := a; Long := Long + 1; Long := Long + 1; Long := Long + 1; Long := Long + 1; Long := Long + 1; Long := Long + 1;
Long := Long + 1; Long := Long + 1; Long := Long + 1; Long := Long + 1; Long := Long + 1; Long := Long + 1;
END_FUNCTION
FUNCTION WithOutput : DINT
VAR_INPUT a : DINT; END_VAR
VAR_OUTPUT twice : DINT; END_VAR
twice := 2 * a;
WithOutput := a;
END_FUNCTION
FUNCTION Jumps : DINT
VAR_INPUT a : DINT; END_VAR
IF a > 0 THEN JMP done; END_IF;
Jumps := 1;
done:
END_FUNCTION
PROGRAM Main
VAR x, y, z, w, t, u, j : DINT; END_VAR
x := Leaf(a := 3);
y := Caller(3);
z := Long(1);
w := WithOutput(5, twice => t);
u := Leaf(a := x, b := 2);
j := Jumps(1);
END_PROGRAM
)";

}  // namespace

TEST_CASE("a small FUNCTION that calls nothing is inlined; the others keep their frame", "[inline]") {
    auto c = compileSt(kCalls);
    INFO(c->printed());
    REQUIRE(c->ok());
    REQUIRE(callIn(*c, 0));
    CHECK(callIn(*c, 0)->inlined != nullptr);    // Leaf
    CHECK(callIn(*c, 1)->inlined == nullptr);    // Caller calls Leaf: not a leaf
    CHECK(callIn(*c, 2)->inlined == nullptr);    // Long: 13 statements, above the limit of 12
    CHECK(callIn(*c, 3)->inlined == nullptr);    // an output connection (=>)
    CHECK(callIn(*c, 4)->inlined != nullptr);    // formal arguments
    CHECK(callIn(*c, 5)->inlined == nullptr);    // JMP needs the labels of a Block
    // The constant argument is part of the call's frame image; the caller's
    // variable is read by the body itself (decision 0403: one task, a leaf
    // that writes only its own frame): nothing is bound per call.
    CHECK(callIn(*c, 0)->binds.empty());
    CHECK(callIn(*c, 4)->binds.empty());
    // Decision 0382: the per-call list ends with How::End; Leaf's one
    // statement is run directly; the calls run on the caller (no METHOD).
    const exec::InlinedCall& leaf = *callIn(*c, 4)->inlined;
    REQUIRE(leaf.binds.size() == 1);
    CHECK(leaf.binds[0].how == exec::ArgBind::How::End);
    // Decision 0404: no list to walk, and only the result initialised.
    CHECK(leaf.args == exec::InlinedCall::Args::None);
    CHECK(leaf.resultOnly);
    CHECK(leaf.single != nullptr);
    CHECK(callIn(*c, 4)->inlinedOnCaller);
    CHECK(callIn(*c, 0)->inlined->binds.size() == 1);  // constants only: just the End
    CHECK_FALSE(callIn(*c, 1)->inlinedOnCaller);
    // Main's frame holds the areas of its inlined calls; a call initialises only its own variables.
    const exec::PouCode& main = codeOf(*c, "Main");
    CHECK(main.frameSize > main.initSize);
    // Caller's own call of Leaf is inlined too (into Caller's frame).
    const exec::PouCode& caller = codeOf(*c, "Caller");
    CHECK(caller.frameSize > caller.initSize);
}

TEST_CASE("without inlining (the debugger) every call keeps its frame, with the same results", "[inline]") {
    auto c = compileSt(kCalls, false, false);
    REQUIRE(c->ok());
    for (size_t k = 0; k < 6; ++k) {
        REQUIRE(callIn(*c, k));
        CHECK(callIn(*c, k)->inlined == nullptr);
    }
    CHECK(codeOf(*c, "Main").frameSize == codeOf(*c, "Main").initSize);
    auto r = runSt(kCalls);
    REQUIRE(r.ok());
    CHECK(r.var("Main", "x") == 12);
    CHECK(r.var("Main", "y") == 13);
    CHECK(r.var("Main", "z") == 13);
    CHECK(r.var("Main", "w") == 5);
    CHECK(r.var("Main", "t") == 10);
    CHECK(r.var("Main", "u") == 24);
    CHECK(r.var("Main", "j") == 0);
}

TEST_CASE("an inlined call keeps the CALL_DEPTH rule: the 17th nested call fails", "[inline][depth]") {
    // Depth(n) nests n calls of itself and ends with one call of the leaf Last.
    auto source = [](int n) {
        return R"(
FUNCTION Last : INT
VAR_INPUT n : INT; END_VAR
Last := n;
END_FUNCTION
FUNCTION Depth : INT
VAR_INPUT n : INT; END_VAR
IF n > 1 THEN Depth := Depth(n - 1) + 1; ELSE Depth := Last(1); END_IF;
END_FUNCTION
PROGRAM Main
VAR r : INT := -1; END_VAR
r := Depth()" + std::to_string(n) + R"();
END_PROGRAM
)";
    };
    auto ok = runSt(source(15));  // 15 calls of Depth and Last: 16 nested calls
    REQUIRE(ok.ok());
    CHECK(ok.state == rt::PlcState::Run);
    CHECK(ok.var("Main", "r") == 15);
    auto deep = runSt(source(16));  // Last is the 17th
    REQUIRE(deep.ok());
    CHECK(deep.state == rt::PlcState::Stop);
    CHECK(deep.count(rt::DiagCode::CallDepth) == 1);
}

TEST_CASE("a fault inside an inlined call names the callee and its line", "[inline][faults][list]") {
    // Ratio's one statement runs as InlinedCall::single, Spread's three from
    // the ended list (decision 0481): the fault names the statement either way.
    const std::string main = R"(
PROGRAM Main
VAR q : DINT; after : BOOL; END_VAR
q := Ratio(10, 0);
after := TRUE;
END_PROGRAM
)";
    const std::string one = R"(
FUNCTION Ratio : DINT
VAR_INPUT a : DINT; b : DINT; END_VAR
Ratio := a / b;
END_FUNCTION)";
    const std::string three = R"(
FUNCTION Ratio : DINT
VAR_INPUT a : DINT; b : DINT; END_VAR
Ratio := a;
Ratio := Ratio + b;
Ratio := Ratio / b;
END_FUNCTION)";
    for (const auto& [callee, line] : {std::pair{one, 4}, std::pair{three, 6}}) {
        auto c = compileSt(callee + main);
        REQUIRE(c->ok());
        REQUIRE(callIn(*c, 0));
        REQUIRE(callIn(*c, 0)->inlined);
        CHECK(callIn(*c, 0)->inlined->list.empty() == (line == 4));
        auto r = runSt(callee + main);
        REQUIRE(r.ok());
        REQUIRE(r.count(rt::DiagCode::DivByZero) == 1);
        CHECK(r.diagnostics[0].pou == "Ratio");
        CHECK(r.diagnostics[0].line == line);
        CHECK(r.var("Main", "after") == true);
    }
}

TEST_CASE("a small METHOD is inlined only where the call's class is known", "[inline][oop]") {
    auto c = compileSt(R"(
FUNCTION_BLOCK Counter
VAR count : DINT; END_VAR
METHOD Add : DINT
VAR_INPUT n : DINT; END_VAR
count := count + n;
Add := count;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Base
METHOD Kind : DINT
Kind := 1;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Derived EXTENDS Base
METHOD Kind : DINT
Kind := 2;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Counter; d : Derived; b : Base; p : POINTER TO Counter; x, y, z, w : DINT; END_VAR
x := a.Add(1);
y := d.Kind();
z := b.Kind();
p := ADR(a);
w := p^.Add(2);
END_PROGRAM
)");
    INFO(c->printed());
    REQUIRE(c->ok());
    REQUIRE(callIn(*c, 0));
    CHECK(callIn(*c, 0)->inlined != nullptr);  // a plain Counter: nothing extends Counter
    CHECK(callIn(*c, 0)->inlined->onInstance);
    CHECK(callIn(*c, 1)->inlined != nullptr);  // a plain Derived: nothing extends Derived
    CHECK(callIn(*c, 2)->inlined == nullptr);  // Derived extends Base: the call keeps its dispatch
    REQUIRE(callIn(*c, 4));
    CHECK(callIn(*c, 4)->inlined == nullptr);  // through a pointer: the NULL_POINTER check of the dispatch stays
}

TEST_CASE("a small function block body is inlined on a plain instance, not through an array element", "[inline][fb]") {
    auto c = compileSt(R"(
FUNCTION_BLOCK Count
VAR_INPUT step : DINT; END_VAR
VAR_OUTPUT total : DINT; END_VAR
total := total + step;
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Count; many : ARRAY[1..2] OF Count; END_VAR
a(step := 2);
many[1](step := 3);
END_PROGRAM
)");
    INFO(c->printed());
    REQUIRE(c->ok());
    const exec::PouCode& main = codeOf(*c, "Main");
    REQUIRE(main.body->stmts.size() == 2);
    auto* plain = dynamic_cast<exec::CallFbStmt*>(main.body->stmts[0]);
    auto* element = dynamic_cast<exec::CallFbStmt*>(main.body->stmts[1]);
    REQUIRE(plain);
    REQUIRE(element);
    CHECK(plain->inlined != nullptr);
    CHECK(element->inlined == nullptr);
}

TEST_CASE("an inlined call binds several computed DINT arguments without the list (decision 0471)", "[inline][args]") {
    // The arguments are computed per call (they are not constants or caller
    // variables read in place): Blend's three are 4-byte integers, Mixed has
    // an INT among them and keeps the ended ArgBind list. The calls pass
    // arguments with side effects (Bump appends its digit to `order`), so
    // that the order of their evaluation is observable too.
    const char* source = R"(
FUNCTION Blend : DINT
VAR_INPUT a : DINT; b : UDINT; c : DINT; END_VAR
Blend := a * 100 + UDINT_TO_DINT(b) * 10 + c;
END_FUNCTION
FUNCTION Mixed : DINT
VAR_INPUT a : DINT; b : INT; c : DINT; END_VAR
Mixed := a * 100 + INT_TO_DINT(b) * 10 + c;
END_FUNCTION
FUNCTION Bump : DINT
VAR_INPUT k : DINT; END_VAR
VAR_IN_OUT order : DINT; END_VAR
order := order * 10 + k;
Bump := k;
END_FUNCTION
PROGRAM Main
VAR i : DINT := 2; x : DINT; y : DINT; z : DINT; w : DINT; order : DINT; END_VAR
x := Blend(i + 1, DINT_TO_UDINT(i * 2), i - 5);
y := Mixed(i + 1, DINT_TO_INT(i * 2), i - 5);
z := Blend(c := i MOD 2, a := i * 3, b := DINT_TO_UDINT(i + 4));
w := Blend(c := Bump(3, order), a := Bump(1, order), b := DINT_TO_UDINT(Bump(2, order)));
END_PROGRAM
)";
    auto c = compileSt(source);
    INFO(c->printed());
    REQUIRE(c->ok());
    REQUIRE(callIn(*c, 0));
    REQUIRE(callIn(*c, 0)->inlined);
    const exec::InlinedCall& blend = *callIn(*c, 0)->inlined;
    CHECK(blend.args == exec::InlinedCall::Args::Int4s);
    REQUIRE(blend.ints.size() == 4);  // three arguments and the null end
    CHECK(blend.ints[3].value == nullptr);
    CHECK(blend.ints[0].dst < blend.ints[1].dst);  // in the call's order: a, b, c
    REQUIRE(callIn(*c, 1));
    REQUIRE(callIn(*c, 1)->inlined);
    CHECK(callIn(*c, 1)->inlined->args == exec::InlinedCall::Args::List);
    REQUIRE(callIn(*c, 2));
    REQUIRE(callIn(*c, 2)->inlined);
    CHECK(callIn(*c, 2)->inlined->args == exec::InlinedCall::Args::Int4s);
    REQUIRE(callIn(*c, 3));
    REQUIRE(callIn(*c, 3)->inlined);
    CHECK(callIn(*c, 3)->inlined->args == exec::InlinedCall::Args::Int4s);
    auto r = runSt(source);
    REQUIRE(r.ok());
    CHECK(r.var("Main", "x") == 300 + 40 - 3);
    CHECK(r.var("Main", "y") == 300 + 40 - 3);
    CHECK(r.var("Main", "z") == 600 + 60 + 0);
    CHECK(r.var("Main", "w") == 100 + 20 + 3);
    CHECK(r.var("Main", "order") == 312);  // the arguments as written, not in the parameters' order
    // The same program without inlining computes the same.
    auto plain = compileSt(source, false, false);
    REQUIRE(plain->ok());
    CHECK(callIn(*plain, 0)->inlined == nullptr);
}

TEST_CASE("an inlined block call binds 4-byte and BOOL inputs as QuickArgs (decision 0472)", "[inline][fb][args]") {
    const char* source = R"(
FUNCTION_BLOCK Acc
VAR_INPUT x : DINT; w : DINT; enable : BOOL; flag : BOOL; END_VAR
VAR_OUTPUT total : DINT; seen : DINT; END_VAR
IF enable THEN total := total + x * w; END_IF;
IF flag THEN seen := seen + 1; END_IF;
END_FUNCTION_BLOCK
FUNCTION_BLOCK Small
VAR_INPUT x : INT; END_VAR
VAR_OUTPUT twice : INT; END_VAR
twice := x * 2;
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Acc; b : Acc; c : Acc; s : Small; i : DINT; t : DINT; END_VAR
FOR i := 1 TO 5 DO
    a(x := i MOD 10, w := 3, enable := i MOD 2 = 1, flag := TRUE);
    b(flag := FALSE, x := a.total MOD 1000, enable := a.total > 10, w := -2, total => t);
    c(x := i, w := 1, enable := TRUE, flag := TRUE);
    s(x := DINT_TO_INT(i));
END_FOR;
END_PROGRAM
)";
    auto c = compileSt(source);
    INFO(c->printed());
    REQUIRE(c->ok());
    const exec::PouCode& main = codeOf(*c, "Main");
    auto* loop = dynamic_cast<exec::ForStmt<int32_t>*>(main.body->stmts[0]);
    REQUIRE(loop);
    REQUIRE(loop->body.block);
    auto* a = dynamic_cast<exec::CallFbStmt*>(loop->body.block->stmts[0]);
    auto* b = dynamic_cast<exec::CallFbStmt*>(loop->body.block->stmts[1]);
    auto* copy = dynamic_cast<exec::CallFbStmt*>(loop->body.block->stmts[2]);
    auto* s = dynamic_cast<exec::CallFbStmt*>(loop->body.block->stmts[3]);
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(s);
    REQUIRE(a->inlined);
    REQUIRE(a->quick.size() == 4);  // a value, a 4-byte constant, a BOOL value, a BOOL constant
    CHECK(a->quick[0].value != nullptr);
    CHECK_FALSE(a->quick[0].oneByte);
    CHECK(a->quick[1].value == nullptr);
    CHECK(a->quick[1].bits == 3);
    CHECK(a->quick[2].oneByte);
    CHECK(a->quick[3].value == nullptr);
    CHECK(a->quick[3].oneByte);
    CHECK(a->quick[3].last);
    CHECK_FALSE(a->quick[2].last);
    REQUIRE(b->quick.size() == 4);
    CHECK(b->quick[0].value == nullptr);  // FALSE first: the order as written
    CHECK(b->quick[3].bits == static_cast<uint32_t>(-2));
    CHECK(s->inlined != nullptr);
    CHECK(s->quick.empty());  // an INT input: the ArgBind list
    REQUIRE(copy);
    CHECK(copy->inlined != nullptr);
    CHECK(copy->quick.empty());  // x := i copies the caller's variable: the ArgBind list
    auto r = runSt(source);
    REQUIRE(r.ok());
    // a: x*3 added for i = 1, 3, 5: 27; seen 5. b: enabled once a.total > 10
    // (i = 3: total 12, i = 4: 12, i = 5: 27): -24 - 24 - 54.
    CHECK(r.var("Main", "a").at("total") == 27);
    CHECK(r.var("Main", "a").at("seen") == 5);
    CHECK(r.var("Main", "b").at("total") == -102);
    CHECK(r.var("Main", "b").at("seen") == 0);
    CHECK(r.var("Main", "t") == -102);
    CHECK(r.var("Main", "s").at("twice") == 10);
    CHECK(r.var("Main", "c").at("total") == 15);
    CHECK(r.var("Main", "c").at("seen") == 5);
}

TEST_CASE("an inlined call's result of every integer width reads back sign- or zero-extended in an expression", "[inline][result]") {
    // CallPou::iInlined reads DINT and BOOL results directly and the others
    // through loadIntRep (decision 0471): each width keeps its extension.
    const char* source = R"(
FUNCTION S8 : SINT VAR_INPUT v : DINT; END_VAR S8 := DINT_TO_SINT(v); END_FUNCTION
FUNCTION U8 : USINT VAR_INPUT v : DINT; END_VAR U8 := DINT_TO_USINT(v); END_FUNCTION
FUNCTION I32 : DINT VAR_INPUT v : DINT; END_VAR I32 := v * 2; END_FUNCTION
FUNCTION U32 : UDINT VAR_INPUT v : DINT; END_VAR U32 := DINT_TO_UDINT(v); END_FUNCTION
FUNCTION B : BOOL VAR_INPUT v : DINT; END_VAR B := v > 0; END_FUNCTION
PROGRAM Main
VAR i : DINT := -6; a, b, d, e : LINT; f : BOOL; END_VAR
a := S8(i) + 0;
b := U8(i) + 0;
d := I32(i) + 0;
e := U32(i) + 0;
f := B(i) OR B(i + 10);
END_PROGRAM
)";
    auto r = runSt(source);
    REQUIRE(r.ok());
    CHECK(r.var("Main", "a") == -6);
    CHECK(r.var("Main", "b") == 250);
    CHECK(r.var("Main", "d") == -12);
    CHECK(r.var("Main", "e") == 4294967290LL);
    CHECK(r.var("Main", "f") == true);
}

TEST_CASE("an inlined body of more than two statements runs from its ended list (decision 0481)", "[inline][list]") {
    // Max3's three statements and Early's four run from InlinedCall::list;
    // Pair's two keep the Body. Each statement ticks once, as in a framed
    // call: with 1 ms a statement the cycle's execution time counts them.
    const char* source = R"(
FUNCTION Max3 : DINT
VAR_INPUT a : DINT; b : DINT; c : DINT; END_VAR
Max3 := a;
IF b > Max3 THEN Max3 := b; END_IF;
IF c > Max3 THEN Max3 := c; END_IF;
END_FUNCTION
FUNCTION Early : DINT
VAR_INPUT a : DINT; END_VAR
Early := a;
IF a > 0 THEN RETURN; END_IF;
Early := 99;
Early := Early + 1;
END_FUNCTION
FUNCTION Pair : DINT
VAR_INPUT a : DINT; END_VAR
Pair := a;
Pair := Pair * 2;
END_FUNCTION
PROGRAM Main
VAR i : DINT := 1; x, y, z, w : DINT; END_VAR
x := Max3(i, i + 4, i + 2);
y := Early(i);
z := Early(i - 2);
w := Pair(i + 2);
END_PROGRAM
)";
    auto c = compileSt(source);
    INFO(c->printed());
    REQUIRE(c->ok());
    for (size_t k = 0; k < 4; ++k) {
        REQUIRE(callIn(*c, k));
        REQUIRE(callIn(*c, k)->inlined);
    }
    const exec::InlinedCall& max3 = *callIn(*c, 0)->inlined;
    REQUIRE(max3.body.block);
    REQUIRE(max3.list.size() == 4);  // three statements and the null end
    CHECK(max3.list[0] == max3.body.block->stmts[0]);
    CHECK(max3.list[2] == max3.body.block->stmts[2]);
    CHECK(max3.list[3] == nullptr);
    CHECK(callIn(*c, 1)->inlined->list.size() == 5);
    CHECK(callIn(*c, 3)->inlined->list.empty());  // two statements: the Body
    CHECK_FALSE(callIn(*c, 3)->inlined->body.block);
    // The run empties Max3's Block: the call still computes its maximum
    // only when it runs from the list.
    RunSettings settings;
    settings.stmtCost = 1'000'000;
    settings.beforeRun = [](sema::ProgramModel& model) {
        for (auto& code : model.codes)
            if (sema::upper(code.name) == "MAIN")
                if (auto* assign = dynamic_cast<exec::AssignCallLocal<int32_t, false>*>(code.body->stmts[0]))
                    if (assign->call->inlined && assign->call->inlined->body.block) assign->call->inlined->body.block->stmts.clear();
    };
    auto r = runSt(source, settings);
    REQUIRE(r.ok());
    CHECK(r.var("Main", "x") == 5);
    CHECK(r.var("Main", "y") == 1);    // RETURN in the second statement ends the list
    CHECK(r.var("Main", "z") == 100);
    CHECK(r.var("Main", "w") == 6);
    // One tick of the cycle itself (a one-statement program runs 2), Main 4,
    // Max3 1 + 2 + 1 (b > a, c not), Early(1) 1 + 2, Early(-1) 4, Pair 2:
    // as many as the same calls with their frames (strun before the list).
    CHECK(r.tasks[0]["last_exec_us"] == (1 + 4 + 4 + 3 + 4 + 2) * 1000);
}
