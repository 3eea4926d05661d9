// parseFiles (interpreter/ast/parse.h) parses two files at a time; the units
// and messages must be those of parseFile on each file in turn (decision 0159).
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "interpreter/ast/ast_dump.h"
#include "interpreter/ast/parse.h"

namespace {

using namespace strun;
using namespace strun::ast;

std::string describe(const std::vector<CompilationUnit>& units, const CompileLog& log) {
    std::ostringstream out;
    for (const auto& unit : units) {
        out << "file " << unit.file << ':';
        for (const auto& p : unit.pous) out << ' ' << p->name << ' ' << dump(p->body);
        out << '\n';
    }
    for (const auto& m : log.messages())
        out << m.loc.file << ':' << m.loc.line << ':' << m.loc.col << ' ' << m.message << " [" << m.code << "]\n";
    out << log.errorCount() << " errors";
    return out.str();
}

}  // namespace

TEST_CASE("files parsed two at a time give the units and messages of one after the other", "[parser][files]") {
    SourceSet sources;
    std::vector<int> files;
    for (int i = 0; i < 25; ++i) {
        std::string text = "FUNCTION F" + std::to_string(i) + " : INT\nF" + std::to_string(i) + " := " + std::to_string(i) + ";\n";
        if (i % 7 == 3) text += "x := := 1;\n";              // a syntax error
        if (i % 5 == 1) text += "{warning 'look here'}\n";  // a message pragma (a warning)
        if (i % 11 == 4) text += "a == b;\n";                // the C operator with its own message
        text += "END_FUNCTION\n";
        files.push_back(sources.add("f" + std::to_string(i) + ".st", text));
    }
    CompileLog sequentialLog;
    std::vector<CompilationUnit> sequential;
    for (int f : files) sequential.push_back(parseFile(sources, f, sequentialLog));
    CompileLog parallelLog;
    const std::vector<CompilationUnit> parallel = parseFiles(sources, files, parallelLog);
    REQUIRE(parallel.size() == files.size());
    CHECK(parallelLog.errorCount() > 0);
    CHECK(describe(parallel, parallelLog) == describe(sequential, sequentialLog));
}

TEST_CASE("a log appended to another keeps order, codes, the cap and the error count", "[parser][files]") {
    CompileLog first, second;
    for (int i = 0; i < 400; ++i) first.error(strun::diag::E0001, Loc{0, i + 1, 1}, "first " + std::to_string(i));
    second.warning(strun::diag::W0010, Loc{1, 1, 1}, "a warning");
    for (int i = 0; i < 700; ++i) second.error(strun::diag::E0001, Loc{1, i + 2, 1}, "second " + std::to_string(i));  // 500 of 701 kept
    first.append(std::move(second));
    REQUIRE(first.messages().size() == CompileLog::kMaxMessages);
    CHECK(first.messages()[399].message == "first 399");
    CHECK(first.messages()[400].message == "a warning");
    CHECK(first.messages()[400].code == "W0010");
    CHECK(first.messages()[401].message == "second 0");
    CHECK(first.errorCount() == 1100);
    CHECK(first.droppedCount() == 201 + 400);  // second's own 201, and 400 of its 500 past the cap here
}
