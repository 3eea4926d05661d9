#include "interpreter/testing/suite_finder.h"

#include "interpreter/testing/test_registry.h"

namespace strun::testing {

using sema::TK;
using sema::Type;

const char* const kSyntheticProgramName = "strun_tests";

bool isTestSuite(const sema::PouInfo* pou) {
    if (!pou || pou->kind != ast::PouKind::FunctionBlock) return false;
    for (const sema::PouInfo* p = pou->parent; p; p = p->parent)
        if (sema::upper(p->name) == "FB_TESTSUITE") return true;
    return false;
}

void recordProject(const sema::ProgramModel& model, TestRegistry& reg) {
    for (const auto& p : model.pouStore) {
        if (p->code && p->ast) reg.pouFiles[p->code->name] = p->ast->loc.file;
        if (!p->owner && isTestSuite(p.get()) && p->ast && !p->ast->abstract) reg.suiteBlocks.push_back(p->name);
    }
    recordAxFixtures(model, reg);
}

std::string syntheticTestProgram(const std::vector<std::string>& blocks) {
    std::string s = std::string("PROGRAM ") + kSyntheticProgramName + "\nVAR\n";
    for (const auto& b : blocks) s += "  " + b + " : " + b + ";\n";
    s += "END_VAR\nRUN();\nEND_PROGRAM\n";
    return s;
}

namespace {

void walk(const Type* t, uint8_t* p, const std::string& name, const std::string& path, TestRegistry& reg, int depth);

void walkMembers(const Type* t, uint8_t* p, const std::string& path, TestRegistry& reg, int depth) {
    if (t->parent) walkMembers(t->parent, p, path, reg, depth);
    for (const auto& f : t->fields) walk(f.type, p + f.offset, f.name, path + "." + f.name, reg, depth + 1);
}

void walk(const Type* t, uint8_t* p, const std::string& name, const std::string& path, TestRegistry& reg, int depth) {
    if (depth > 32) return;  // instances nest by value only, but stay bounded anyway
    if (t->kind == TK::FunctionBlock && isTestSuite(t->pou)) {
        Suite s;
        s.name = name;
        s.path = path;
        s.typeName = t->pou->name;
        s.instance = p;
        s.body = t->pou->code;
        for (const sema::PouInfo* b = t->pou; b; b = b->parent) s.blocks.push_back(sema::upper(b->name));
        reg.suites.push_back(std::move(s));
        return;
    }
    if (t->kind == TK::FunctionBlock || t->kind == TK::Struct) {
        walkMembers(t, p, path, reg, depth);
    } else if (t->kind == TK::Array && t->elem && (t->elem->kind == TK::FunctionBlock || t->elem->kind == TK::Struct || t->elem->kind == TK::Array)) {
        // Element k of a (multi-dimensional) array, named with its subscripts.
        uint64_t count = t->elemCount;
        for (uint64_t k = 0; k < count; ++k) {
            std::string sub;
            uint64_t rest = k;
            std::vector<int64_t> idx(t->dims.size());
            for (size_t d = t->dims.size(); d-- > 0;) {
                uint64_t n = static_cast<uint64_t>(t->dims[d].count());
                idx[d] = t->dims[d].lo + static_cast<int64_t>(rest % n);
                rest /= n;
            }
            for (size_t d = 0; d < idx.size(); ++d) sub += (d ? "," : "") + std::to_string(idx[d]);
            walk(t->elem, p + k * t->elem->size, name + "[" + sub + "]", path + "[" + sub + "]", reg, depth + 1);
        }
    }
}

}  // namespace

void collectSuites(sema::ProgramModel& model, TestRegistry& reg) {
    reg.suites.clear();
    for (auto& prog : model.programs)
        if (prog.pou && prog.pou->instanceType) walkMembers(prog.pou->instanceType, prog.memory, prog.name, reg, 0);
    for (const sema::VarSym* g : model.globals)
        if (g->abs && g->type) walk(g->type, g->abs, g->name, g->name, reg, 0);
}

}  // namespace strun::testing
