// The checker's registry of built-in functions: filled on the first look-up
// of a built-in name (decision 0478), its entries a function pointer and a
// few plain values in an open-addressing hash (decision 0487). The registrar
// runs once, not before; a later registration of a name replaces an earlier
// one; a checker kept after compileProject (the debugger's watch expressions)
// still finds every built-in, TcUnit's included; a vendor library's natives
// are there only when the project names the library; names are looked up
// upper-case, which makes calls case-insensitive.
#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "interpreter/project/compile.h"
#include "interpreter/sema/checker.h"

using namespace strun;

namespace {

// `text` compiled as main.st (without errors) with its checker kept; the
// sources and the model stay alive with it, as the debugger keeps them.
struct Kept {
    SourceSet sources;
    CompileLog log;
    std::unique_ptr<sema::ProgramModel> model;
    std::unique_ptr<sema::Checker> checker;
};

std::unique_ptr<Kept> keptChecker(const std::string& text) {
    auto kept = std::make_unique<Kept>();
    const int file = kept->sources.add("main.st", text);
    project::CompileExtras extras;
    extras.keepChecker = &kept->checker;
    kept->model = project::compileProject(kept->sources, {file}, kept->log, {}, nullptr, nullptr, &extras);
    REQUIRE(kept->model);
    REQUIRE(kept->checker);
    return kept;
}

// A check that reports the value it was registered with as an error code.
struct Tag {
    int value;
};

}  // namespace

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

TEST_CASE("a builtin's data reaches its check, and a later registration of a name replaces the earlier", "[builtins]") {
    sema::BuiltinRegistry registry;
    auto check = [](sema::Checker& ck, sema::CallArgs& call, const sema::BuiltinFn& self) -> sema::Checked {
        call.loc.line = self.data<Tag>().value;
        return ck.bad(call.loc);
    };
    // More names than the first table holds at half load: the table grows.
    for (int k = 0; k < 3000; ++k) registry.add("F" + std::to_string(k), sema::BuiltinFn(check, Tag{k}));
    registry.add("F7", sema::BuiltinFn(check, Tag{-7}));
    CHECK(registry.size() == 3000);
    sema::ProgramModel model;
    CompileLog log;
    sema::Checker checker(model, log);
    auto tagOf = [&](const std::string& name) {
        const sema::BuiltinFn* fn = registry.find(name);
        REQUIRE(fn);
        sema::CallArgs call;
        (*fn)(checker, call);
        return call.loc.line;
    };
    CHECK(tagOf("F0") == 0);
    CHECK(tagOf("F2999") == 2999);
    CHECK(tagOf("F1234") == 1234);
    CHECK(tagOf("F7") == -7);
    CHECK(registry.find("F3000") == nullptr);
    CHECK(registry.find("") == nullptr);
    CHECK(registry.names().size() == 3000);
}

TEST_CASE("a checker kept after the compile still registers every builtin", "[builtins]") {
    auto kept = keptChecker("PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM");
    sema::Checker* checker = kept->checker.get();
    // Registered only now, after compileProject returned: the registrar owns
    // what it uses. One of each group; ASSERTEQUALS_INT is TcUnit's, bound to
    // the model's test registry.
    for (const char* name : {"ABS", "TO_BIG_ENDIAN", "INT_TO_BCD_WORD", "WSTRING_TO_LREAL", "SPLIT_DT", sema::Checker::kDateAddOperator,
                             "ASSERTEQUALS_INT", "ASSERTARRAY3DEQUALS_LREAL", "AXUNIT_FAIL"}) {
        INFO(name);
        CHECK(checker->hasBuiltin(name));
    }
    CHECK_FALSE(checker->hasBuiltin("NO_SUCH_FUNCTION"));
}

TEST_CASE("a vendor library's natives are registered only when the project names the library", "[builtins]") {
    auto kept = keptChecker("PROGRAM Main VAR x : INT; END_VAR x := ABS(x - 1); END_PROGRAM");
    sema::Checker* plain = kept->checker.get();
    CHECK(plain->hasBuiltin("ABS"));
    CHECK_FALSE(plain->hasBuiltin("F_STRUN_FORMATARG"));   // Tc2_Utilities
    CHECK_FALSE(plain->hasBuiltin("F_STRUN_FILEOPEN"));    // Tc2_System
    auto keptLibrary = keptChecker("PROGRAM Main VAR fmt : FB_FormatString; END_VAR fmt(sFormat := '%d', arg1 := F_INT(3)); END_PROGRAM");
    sema::Checker* withLibrary = keptLibrary->checker.get();
    CHECK(withLibrary->hasBuiltin("F_STRUN_FORMATARG"));
    CHECK(withLibrary->hasBuiltin("ABS"));
}

TEST_CASE("built-ins are called in any case: the registry holds upper-case names", "[builtins]") {
    auto kept = keptChecker(
        "PROGRAM Main VAR x : INT; s : STRING; END_VAR x := abs(x - 1) + Abs(x) + ABS(x); s := int_to_string(x); END_PROGRAM");
    sema::Checker* checker = kept->checker.get();
    CHECK(checker->hasBuiltin("INT_TO_STRING"));
    CHECK_FALSE(checker->hasBuiltin("int_to_string"));  // callers upper-case the name first
}
