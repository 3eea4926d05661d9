// The checker's registry of built-in functions is filled on the first
// look-up of a built-in name (decision 0478): the registrar runs once, not
// before, and a checker kept after compileProject (the debugger's watch
// expressions) still finds every built-in, TcUnit's included.
#include <catch2/catch.hpp>

#include <memory>

#include "interpreter/project/compile.h"
#include "interpreter/sema/checker.h"

using namespace strun;

TEST_CASE("the builtin registrar runs on the first look-up and only once", "[builtins]") {
    sema::ProgramModel model;
    CompileLog log;
    sema::Checker checker(model, log);
    int runs = 0;
    checker.setBuiltinRegistrar([&runs](sema::Checker& ck) {
        ++runs;
        ck.addBuiltin("FOO", [](sema::Checker& c, sema::CallArgs& call) { return c.bad(call.loc); });
    });
    CHECK(runs == 0);
    CHECK(checker.hasBuiltin("FOO"));
    CHECK(runs == 1);
    CHECK_FALSE(checker.hasBuiltin("BAR"));
    CHECK(runs == 1);
}

TEST_CASE("a checker kept after the compile still registers every builtin", "[builtins]") {
    SourceSet sources;
    CompileLog log;
    const int file = sources.add("main.st", "PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM");
    std::unique_ptr<sema::Checker> checker;
    project::CompileExtras extras;
    extras.keepChecker = &checker;
    auto model = project::compileProject(sources, {file}, log, {}, nullptr, nullptr, &extras);
    REQUIRE(model);
    REQUIRE(checker);
    // Registered only now, after compileProject returned: the registrar owns what it uses.
    CHECK(checker->hasBuiltin("ABS"));
    CHECK(checker->hasBuiltin("TO_BIG_ENDIAN"));
    CHECK(checker->hasBuiltin("ASSERTEQUALS_INT"));  // TcUnit's, bound to the model's test registry
    CHECK(checker->hasBuiltin("AXUNIT_FAIL"));
    CHECK_FALSE(checker->hasBuiltin("NO_SUCH_FUNCTION"));
}
