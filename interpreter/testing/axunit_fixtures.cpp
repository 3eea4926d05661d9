#include "interpreter/testing/axunit_fixtures.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "interpreter/sema/program_model.h"
#include "interpreter/testing/test_registry.h"

namespace strun::testing {

namespace {

const char* const kBlockPrefix = "strun_axunit_fixture_";

std::string trimmed(std::string s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.erase(s.begin());
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    return s;
}

// "Test", "Test(a := 1)" -> the pragma's name (upper case) and its argument text.
std::pair<std::string, std::string> splitPragma(const std::string& text) {
    const std::string t = trimmed(text);
    const auto open = t.find('(');
    std::string name = trimmed(t.substr(0, open));
    std::string args;
    if (open != std::string::npos) {
        const auto close = t.rfind(')');
        args = trimmed(t.substr(open + 1, close == std::string::npos || close < open ? std::string::npos : close - open - 1));
    }
    return {sema::upper(name), args};
}

std::string qualified(const ast::Pou& p) {
    if (p.name.find('.') != std::string::npos || p.nameSpace.empty()) return p.name;
    return p.nameSpace + "." + p.name;
}

// A test name inside an ST string literal: ' and $ escaped.
std::string stLiteral(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        if (c == '\'' || c == '$') out += '$';
        out += c;
    }
    return out + "'";
}

// A method or function as written: an overloaded one is renamed "Name(T1, T2)"
// by the checker (decision 0362), and the generated call picks the member again.
std::string plainName(const std::string& name) { return name.substr(0, name.find('(')); }

void addTests(const ast::Pou& p, const std::string& callName, std::vector<AxTest>& tests) {
    for (const ast::Pragma& pr : p.pragmas) {
        auto [name, args] = splitPragma(pr.text);
        if (name != "TEST") continue;
        AxTest t;
        t.name = args.empty() ? plainName(p.name) : plainName(p.name) + "(" + args + ")";
        t.call = plainName(callName) + "(" + args + ")";
        tests.push_back(std::move(t));
    }
}

bool hasPragma(const ast::Pou& p, const char* upperName) {
    return std::any_of(p.pragmas.begin(), p.pragmas.end(), [&](const ast::Pragma& pr) { return splitPragma(pr.text).first == upperName; });
}

}  // namespace

void recordAxFixtures(const sema::ProgramModel& model, TestRegistry& reg) {
    reg.axFixtures.clear();
    std::map<std::string, AxFixture> functionsByNamespace;
    for (const auto& info : model.pouStore) {
        const ast::Pou* p = info->ast;
        if (!p || info->owner) continue;
        if (p->kind == ast::PouKind::FunctionBlock && hasPragma(*p, "TESTFIXTURE") && !p->abstract) {
            AxFixture f;
            f.displayName = qualified(*p);
            f.typeName = f.displayName;
            for (const auto& m : p->methods) {
                addTests(*m, "fixture." + plainName(m->name), f.tests);
                if (hasPragma(*m, "TESTSETUP")) f.setup = plainName(m->name);
                if (hasPragma(*m, "TESTTEARDOWN")) f.teardown = plainName(m->name);
                if (hasPragma(*m, "FIXTURESETUP")) f.fixtureSetup = plainName(m->name);
                if (hasPragma(*m, "FIXTURETEARDOWN")) f.fixtureTeardown = plainName(m->name);
            }
            reg.axFixtures.push_back(std::move(f));
        } else if (p->kind == ast::PouKind::Function && hasPragma(*p, "TEST")) {
            AxFixture& f = functionsByNamespace[p->nameSpace];
            f.displayName = p->nameSpace.empty() ? "AxUnit" : p->nameSpace;
            addTests(*p, qualified(*p), f.tests);
        }
    }
    for (auto& [ns, f] : functionsByNamespace) reg.axFixtures.push_back(std::move(f));
    // AxUnit's order: alphabetical by the tests' fully qualified names.
    for (auto& f : reg.axFixtures)
        std::stable_sort(f.tests.begin(), f.tests.end(), [](const AxTest& a, const AxTest& b) { return sema::upper(a.name) < sema::upper(b.name); });
    std::stable_sort(reg.axFixtures.begin(), reg.axFixtures.end(),
                     [](const AxFixture& a, const AxFixture& b) { return sema::upper(a.displayName) < sema::upper(b.displayName); });
    reg.axFixtures.erase(std::remove_if(reg.axFixtures.begin(), reg.axFixtures.end(), [](const AxFixture& f) { return f.tests.empty(); }),
                         reg.axFixtures.end());
}

std::string axFixtureSuites(const std::vector<AxFixture>& fixtures, std::vector<std::string>& blocks) {
    std::string s;
    for (size_t k = 0; k < fixtures.size(); ++k) {
        const AxFixture& f = fixtures[k];
        const std::string block = kBlockPrefix + std::to_string(k + 1);
        blocks.push_back(block);
        s += "FUNCTION_BLOCK " + block + " EXTENDS FB_TestSuite\n";
        if (!f.typeName.empty()) s += "VAR\n  fixture : " + f.typeName + ";\nEND_VAR\n";
        if (!f.fixtureSetup.empty()) s += "fixture." + f.fixtureSetup + "();\n";
        for (const AxTest& t : f.tests) {
            s += "IF TEST_ORDERED(" + stLiteral(t.name) + ") THEN\n";
            if (!f.setup.empty()) s += "  fixture." + f.setup + "();\n";
            s += "  " + t.call + ";\n";
            if (!f.teardown.empty()) s += "  fixture." + f.teardown + "();\n";
            s += "  TEST_FINISHED();\nEND_IF\n";
        }
        if (!f.fixtureTeardown.empty()) s += "fixture." + f.fixtureTeardown + "();\n";
        s += "END_FUNCTION_BLOCK\n";
    }
    return s;
}

void nameAxSuites(TestRegistry& reg) {
    for (Suite& s : reg.suites) {
        if (s.typeName.rfind(kBlockPrefix, 0) != 0) continue;
        const size_t k = std::stoul(s.typeName.substr(std::string(kBlockPrefix).size()));
        if (k >= 1 && k <= reg.axFixtures.size()) s.name = reg.axFixtures[k - 1].displayName;
        s.axUnit = true;  // AxUnit has no MaxNumberOfTestsForEachTestSuite (simatic-ax/conversion: 108 in one fixture)
    }
}

}  // namespace strun::testing
