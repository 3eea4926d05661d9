// The diagnostic catalogue: unique codes, lookup, the codes call sites give,
// the pages; and the one edit distance behind every did-you-mean.
#include <set>
#include <string>

#include <catch2/catch.hpp>

#include "interpreter/source/closest_name.h"
#include "interpreter/source/diagnostic_codes.h"
#include "interpreter/source/source_set.h"

using namespace strun;
using namespace strun::diagnostics;

TEST_CASE("diagnostic catalogue: every code once, with a title and an explanation", "[diagnostics]") {
    std::set<std::string> seen;
    for (const CodeInfo& info : catalogue()) {
        CHECK(seen.insert(std::string(info.code)).second);
        CHECK(!info.title.empty());
        CHECK(!info.explanation.empty());
        const std::string page = textPage(info);
        CHECK(page.rfind(std::string(info.code) + ": ", 0) == 0);
        CHECK(markdownPage(info).find("# " + std::string(info.code)) == 0);
    }
    CHECK(find("e0101") == find("E0101"));
    REQUIRE(find("DIV_BY_ZERO") != nullptr);
    CHECK(find("DIV_BY_ZERO")->kind == Kind::Runtime);
    CHECK(find("E9999") == nullptr);
}

TEST_CASE("diagnostics: the log codes every message and keeps notes and help", "[diagnostics]") {
    CompileLog log;
    log.error(diag::E0101, ast::Loc{0, 3, 1}, "undeclared identifier 'bButon'").withHelp("did you mean 'bButton'?").note("a note");
    log.warning(diag::W0003, ast::Loc{0, 2, 1}, "variable 'x' is never used");
    REQUIRE(log.messages().size() == 2);
    CHECK(log.messages()[0].code == "E0101");
    CHECK(log.messages()[0].help.size() == 1);
    CHECK(log.messages()[0].notes.size() == 1);
    CHECK(log.messages()[1].code == "W0003");
    log.eraseIf([](const Diagnostic& d) { return d.severity == Severity::Error; });
    CHECK(!log.hasErrors());
    CHECK(log.messages().size() == 1);
}

TEST_CASE("closest name: typos, transpositions and prefixes; nothing far off", "[diagnostics]") {
    CHECK(closestName("BBUTON", {"BBUTTON", "BLAMP"}) == "BBUTTON");
    CHECK(closestName("RNU", {"IDLE", "RUN", "STOP"}) == "RUN");  // one transposition
    CHECK(closestName("--virt", {"--virtual", "--cycles"}) == "--virtual");
    CHECK(closestName("SPEED", {"TEMPERATURE", "PRESSURE"}).empty());
}

TEST_CASE("diagnostic codes: every typed code is in the catalogue, with its kind", "[diagnostics]") {
    // The codes call sites give (decision 0298) and the catalogue's pages are one list.
    std::set<std::string> typed;
    for (diag::Code code : diag::kAllCodes) {
        const std::string text(diag::text(code));
        CHECK(typed.insert(text).second);
        const CodeInfo* info = find(text);
        REQUIRE(info != nullptr);
        CHECK(info->kind == (diag::isWarning(code) ? Kind::Warning : Kind::Error));
    }
    for (const CodeInfo& info : catalogue())
        if (info.kind != Kind::Runtime) CHECK(typed.count(std::string(info.code)) == 1);
}

TEST_CASE("diagnostic codes: a code given at the call site wins over the wording", "[diagnostics]") {
    CompileLog log;
    // Worded like an undeclared identifier (E0101) and a W0001 warning, coded otherwise:
    // rewording can never move a message to another code.
    log.error(diag::E0406, ast::Loc{0, 1, 1}, "undeclared identifier 'x'");
    log.warning(diag::W0011, ast::Loc{0, 2, 1}, "implicit conversion from INT to SINT");
    REQUIRE(log.messages().size() == 2);
    CHECK(log.messages()[0].code == "E0406");
    CHECK(log.messages()[1].code == "W0011");
    CHECK(diag::fromText("W0041") == diag::W0041);
    CHECK(!diag::fromText("E9999"));
}
