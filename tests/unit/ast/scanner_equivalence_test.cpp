// The scanner strun runs (interpreter/ast/st_scanner.h) against the lexer
// ANTLR generates from grammar/STLexer.g4, the definition of the tokens
// (tests/fuzz/scanner_oracle.h): both must produce the same tokens (type,
// channel, text, line, column) on every source file of the repository and on
// generated input built from the fragments where lexing rules meet (decision
// 0157). The fuzz target compares them on every input it tries.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "interpreter/ast/utf8_input.h"
#include "tests/fuzz/scanner_oracle.h"

namespace {

void requireSameTokens(const std::string& rawSource, const std::string& what) {
    const auto difference = strun::fuzz::scannerDifference(strun::ast::sanitizeUtf8(rawSource));
    INFO(what << ": " << difference.value_or(""));
    CHECK_FALSE(difference.has_value());
}

}  // namespace

TEST_CASE("scanner equals the grammar's lexer on every source file of the repository", "[lexer][scanner]") {
    namespace fs = std::filesystem;
    size_t files = 0;
    for (const char* dir : {"tests", "programs", "stdlib/st", "benchmarks", "docs"}) {
        const fs::path root = fs::path(STRUN_SOURCE_DIR) / dir;
        if (!fs::exists(root)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(root)) {
            if (!entry.is_regular_file() || entry.file_size() > 2000000) continue;
            const std::string ext = entry.path().extension().string();
            if (ext != ".st" && ext != ".TcPOU" && ext != ".TcGVL" && ext != ".TcDUT" && ext != ".xml" && ext != ".md") continue;
            std::ifstream in(entry.path(), std::ios::binary);
            std::stringstream content;
            content << in.rdbuf();
            requireSameTokens(content.str(), entry.path().string());
            ++files;
        }
    }
    CHECK(files > 500);
}

TEST_CASE("scanner equals the grammar's lexer where its rules meet", "[lexer][scanner]") {
    for (const char* s : {"", " ", "\n\n  ", "(*", "(*)", "(* (* *)", "*)", "/*", "/*/", "/* * /", "//", "{", "{}", "}", "'",
                          "'$", "'$\n", "\"$", "'a$'", "'a$'b'", "%", "%I", "%IX", "%IX1.", "%IX1.2.", "%X", "%XB1", "%Q*",
                          "T#", "T#1", "T#1h30", "T#-", "T#+1s", "T#1.s", "T#1.5", "T#1_h_2m_", "TIME#1ms5us", "LTIME#5ns",
                          "D#2020-1", "D#2020-1-2", "DT#2020-1-2-", "DT#2020-1-2-3:4", "TOD#1:", "TOD#1:2:", "TOD#1:2:3.",
                          "INT#", "INT#-", "INT#16#", "INT#16#_F", "INT#1E", "INT#1.5E+3", "X#'a", "X#'a'", "X#\"a\"",
                          "16#", "16#_", "16#_F", "2#10_", "1__2", "1.", "1..2", "1.5e", "1e+", "1e+5", "10#99", "110#5",
                          "a.%X3", "?", "?=", "::=", "=>=", "<>=", "**)", "\xC3\xA9t\xC3\xA9", "\xFF", "a\x01" "b", "__x#1",
                          "T#1d2h3m4s5ms6us7ns8m", "t#1MS", "dATe_aNd_tIMe#1-2-3-4:5:6.7", "LDATE_AND_TIME#1-1-1-1:1"})
        requireSameTokens(s, std::string("'") + s + "'");
}

TEST_CASE("scanner equals the grammar's lexer on generated input", "[lexer][scanner]") {
    static const char* const kFragments[] = {
        "T", "TIME", "t", "LT", "D", "DT", "TOD", "LDATE", "TIME_OF_DAY", "INT", "x", "_", "abc", "IF", "end_if",
        "#", "#", "1", "0", "16", "2", "8", "10", "5", "_", ".", "..", "ms", "s", "m", "h", "d", "us", "ns", "e", "E",
        "+", "-", ":", "=", "'", "\"", "$", "\n", "\r", " ", "\t", "(*", "*)", "(", ")", "*", "/", "//", "/*", "*/",
        "{", "}", "%", "I", "X", "Q", "W", "?", "<", ">", ";", ",", "[", "]", "^", "&", "\xC3\xA9", "\xFF", "!"};
    std::mt19937 random(61131);
    std::uniform_int_distribution<size_t> pick(0, std::size(kFragments) - 1), length(1, 24);
    for (int n = 0; n < 20000; ++n) {
        std::string s;
        for (size_t k = length(random); k > 0; --k) s += kFragments[pick(random)];
        requireSameTokens(s, "generated '" + s + "'");
    }
}
