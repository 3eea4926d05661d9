// A function block's `out => v` into a variable of the output's own type is
// one CopyLocal node (decision 0409); other connections keep their
// assignment. The conformance test pous/fb_outputs_copied_directly checks
// the values through the CLI.
#include <catch2/catch.hpp>

#include "interpreter/exec/call_nodes.h"
#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

namespace {

// The block call that is the `index`-th statement of Main.
exec::CallFbStmt* blockCallIn(const Compiled& c, size_t index) {
    for (const auto& code : c.model->codes)
        if (sema::upper(code.name) == "MAIN" && code.body && index < code.body->stmts.size())
            return dynamic_cast<exec::CallFbStmt*>(code.body->stmts[index]);
    return nullptr;
}

}  // namespace

TEST_CASE("a block's output into a variable of its own type is copied by one node", "[inline][fb]") {
    auto c = compileSt(R"(
FUNCTION_BLOCK Acc
VAR_INPUT x : DINT; END_VAR
VAR_OUTPUT total : DINT; high : BOOL; ratio : REAL; END_VAR
total := total + x;
high := total > 5;
ratio := DINT_TO_REAL(total) / 2.0;
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Acc; t : DINT; wide : LINT; h, nh : BOOL; r : REAL; lr : LREAL; END_VAR
a(x := 1, total => t, high => h, ratio => r);
a(x := 1, total => wide, NOT high => nh, ratio => lr);
END_PROGRAM
)");
    INFO(c->printed());
    REQUIRE(c->ok());
    exec::CallFbStmt* same = blockCallIn(*c, 0);
    REQUIRE(same);
    REQUIRE(same->outputs.size() == 3);
    CHECK(dynamic_cast<exec::CopyLocal<int32_t, false, false>*>(same->outputs[0]));
    CHECK(dynamic_cast<exec::CopyLocal<bool, false, false>*>(same->outputs[1]));  // stored as 0/1
    CHECK(dynamic_cast<exec::CopyLocal<float, false, false>*>(same->outputs[2]));
    // Converted (DINT => LINT, REAL => LREAL) or negated: the assignment as before.
    exec::CallFbStmt* other = blockCallIn(*c, 1);
    REQUIRE(other);
    REQUIRE(other->outputs.size() == 3);
    CHECK_FALSE(dynamic_cast<exec::CopyLocal<int64_t, false, false>*>(other->outputs[0]));
    CHECK_FALSE(dynamic_cast<exec::CopyLocal<bool, false, false>*>(other->outputs[1]));
    CHECK_FALSE(dynamic_cast<exec::CopyLocal<double, false, false>*>(other->outputs[2]));
}
