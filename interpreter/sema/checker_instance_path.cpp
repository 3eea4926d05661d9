// CODESYS/TwinCAT `{attribute 'instance-path'}` on a STRING variable of a
// function block: the variable holds the path of the instance it belongs to,
// `<project>.<program>.<instance>...` (TcUnit names its suites and tests by
// it, after removing the project name). strun's project name is the one
// _AppInfo.ProjectName gives, 'strun' (decision 0315). The paths are written
// into the instances' memory once, at compile time, before any FB_init runs.
#include <cstring>

#include <fmt/format.h>

#include "interpreter/sema/attributes.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/instance_search.h"

namespace strun::sema {

namespace {

constexpr int kMaxInstancePathNesting = 64;                   // as for FB_init
constexpr uint64_t kMaxPathWrites = 100000;       // instance paths per project (docs/limits.md)
constexpr const char* kProjectName = "strun";     // _AppInfo.ProjectName (stdlib/libraries/Tc2_System/system_info.st)

bool isInstancePathVar(const VarSym& v) {
    return v.decl && v.type && v.type->kind == TK::String && v.storage == Storage::Self && !v.byRef &&
           hasAttribute(v.decl->pragmas, "instance-path");
}

// "[2]" or "[1,3]": the subscripts of flat element `k` of array type `t`.
std::string subscripts(const Type* t, uint64_t k) {
    std::vector<int64_t> index(t->dims.size());
    for (size_t d = t->dims.size(); d-- > 0;) {
        const uint64_t extent = static_cast<uint64_t>(t->dims[d].hi - t->dims[d].lo) + 1;
        index[d] = t->dims[d].lo + static_cast<int64_t>(k % extent);
        k /= extent;
    }
    return fmt::format("[{}]", fmt::join(index, ","));
}

}  // namespace

bool Checker::holdsInstancePath(const Type* t) {
    return holdsInstanceWhere(t, holdsInstancePath_, [](PouInfo* p) {
        for (auto& v : p->ownedVars)
            if (isInstancePathVar(*v)) return true;
        return false;
    });
}

void Checker::writeInstancePaths(const Type* t, uint8_t* addr, const std::string& path, int depth) {
    if (!t || depth > kMaxInstancePathNesting || instancePathWrites_ >= kMaxPathWrites || !holdsInstancePath(t)) return;
    if (t->kind == TK::Array) {
        for (uint64_t k = 0; k < t->elemCount && instancePathWrites_ < kMaxPathWrites; ++k)
            writeInstancePaths(t->elem, addr + k * t->elem->size, path + subscripts(t, k), depth + 1);
        return;
    }
    if (t->kind == TK::Struct) {
        for (const Type* p = t; p; p = p->parent)
            for (const auto& f : p->fields) writeInstancePaths(f.type, addr + f.offset, path + "." + f.name, depth + 1);
        return;
    }
    if (t->kind != TK::FunctionBlock || !t->pou) return;
    for (PouInfo* p = t->pou; p; p = p->parent)
        for (auto& v : p->ownedVars) {
            if (isInstancePathVar(*v)) {
                // A STRING(n) keeps its first n bytes and the terminator, as an assignment would.
                const size_t n = std::min<size_t>(path.size(), v->type->maxLen);
                std::memcpy(addr + v->offset, path.data(), n);
                addr[v->offset + n] = 0;
                ++instancePathWrites_;
            } else if (v->storage == Storage::Self && !v->byRef) {
                writeInstancePaths(v->type, addr + v->offset, path + "." + v->name, depth + 1);
            }
        }
}

void Checker::writeAllInstancePaths() {
    const std::string project = kProjectName;
    for (VarSym* g : model_.globals)
        if (g->abs && !g->owner) writeInstancePaths(g->type, g->abs, project + "." + g->name, 0);
    for (auto& prog : model_.programs)
        writeInstancePaths(prog.pou->instanceType, prog.memory, project + "." + prog.name, 0);
}

}  // namespace strun::sema
