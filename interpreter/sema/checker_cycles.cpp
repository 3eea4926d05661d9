// Declarations that refer to themselves: inheritance cycles (FB, STRUCT and
// INTERFACE EXTENDS), types containing themselves by value, and chains of
// declarations too deep to resolve. All are compile errors naming the cycle;
// a POINTER TO / REFERENCE TO self stays legal (it has a size of its own).
#include <functional>
#include <map>
#include <set>

#include <fmt/format.h>

#include "interpreter/sema/checker.h"

namespace strun::sema {

DeclDepthGuard::DeclDepthGuard(Checker& checker, const std::string& name, const ast::Loc& loc) : checker_(checker) {
    if (checker_.declStack_.size() >= kMaxDeclarationDepth) {
        checker_.error(diag::E0007, loc, fmt::format("declarations nested more than {} deep (at '{}'): each type or block contains, "
                                        "aliases or extends the next",
                                        kMaxDeclarationDepth, name));
        checker_.declDepthExceeded_ = true;
        return;
    }
    checker_.declStack_.push_back(name);
    ok_ = true;
}

DeclDepthGuard::~DeclDepthGuard() {
    if (ok_) checker_.declStack_.pop_back();
}

// "A -> B -> A": the declarations from `name` (in progress) to the innermost one, then `name` again.
std::string Checker::cyclePath(const std::string& name) const {
    const std::string key = upper(name);
    size_t from = declStack_.size();
    for (size_t k = declStack_.size(); k-- > 0;)
        if (upper(declStack_[k]) == key) { from = k; break; }
    std::string path;
    for (size_t k = from; k < declStack_.size(); ++k) path += declStack_[k] + " -> ";
    return path + name;
}

// `t` is the type of a member, element or variable held by value. A struct or
// FB still being laid out there means the declaration contains itself.
bool Checker::rejectByValueCycle(const Type* t, const ast::Loc& loc) {
    while (t && t->kind == TK::Array) t = t->elem;
    if (!t || !t->incomplete) return false;
    error(diag::E0403, loc, fmt::format("'{}' contains itself by value ({}); use POINTER TO or REFERENCE TO", t->name, cyclePath(t->name)));
    return true;
}

namespace {
// One node of an EXTENDS graph: its name, where it is declared and what it extends.
struct Extender {
    std::string name;
    ast::Loc loc;
    std::vector<std::string>* bases;  // FB / INTERFACE: extendsList or a one-element view
    std::string* single;              // FB / STRUCT: the one base name
};

// Iterative depth-first search (chains may be tens of thousands long): a base
// reached again while still on the path closes a cycle; the edge that closes it
// is removed so that everything after the error terminates.
void breakCycles(std::map<std::string, Extender>& nodes, const std::function<void(const Extender&, const std::string&)>& report) {
    std::map<std::string, int> state;  // 0 new, 1 on the path, 2 done
    for (auto& [key, node] : nodes) {
        if (state[key]) continue;
        struct Frame { std::string key; size_t next; };
        std::vector<Frame> path{{key, 0}};
        state[key] = 1;
        while (!path.empty()) {
            Frame& top = path.back();
            Extender& n = nodes.at(top.key);
            std::vector<std::string> bases = n.bases ? *n.bases : std::vector<std::string>{};
            if (n.single && !n.single->empty() && bases.empty()) bases.push_back(*n.single);
            if (top.next >= bases.size()) {
                state[top.key] = 2;
                path.pop_back();
                continue;
            }
            const std::string base = upper(bases[top.next++]);
            auto it = nodes.find(base);
            if (it == nodes.end()) continue;  // unknown or of another kind: reported where it is used
            if (state[base] == 1) {
                std::string cycle;
                bool on = false;
                for (const Frame& f : path) {
                    on = on || f.key == base;
                    if (on) cycle += nodes.at(f.key).name + " EXTENDS ";
                }
                report(n, cycle + it->second.name);
                if (n.bases) {
                    n.bases->erase(n.bases->begin() + static_cast<long>(top.next - 1));
                    --top.next;
                }
                if (n.single && upper(*n.single) == base) n.single->clear();
                continue;
            }
            if (state[base] == 0) {
                state[base] = 1;
                path.push_back({base, 0});
            }
        }
    }
}
}  // namespace

void Checker::breakInheritanceCycles() {
    auto report = [&](const Extender& n, const std::string& cycle) { error(diag::E0403, n.loc, fmt::format("inheritance cycle: {}", cycle)); };
    std::map<std::string, Extender> blocks, interfaces, structs;
    for (PouInfo* p : pouOrder_) {
        ast::Pou* a = p->ast;
        const ast::Loc loc = a->nameLoc.line ? a->nameLoc : a->loc;
        if (p->kind == ast::PouKind::FunctionBlock) blocks[upper(p->name)] = {p->name, loc, nullptr, &a->extends};
        if (p->kind == ast::PouKind::Interface) {
            if (a->extendsList.empty() && !a->extends.empty()) a->extendsList.push_back(a->extends);
            a->extends = a->extendsList.empty() ? std::string() : a->extendsList.front();
            interfaces[upper(p->name)] = {p->name, loc, &a->extendsList, nullptr};
        }
    }
    for (auto& [key, decl] : typeDecls_)
        if (decl->spec && decl->spec->kind == ast::TypeSpecKind::Struct && !decl->extends.empty())
            structs[key] = {decl->name, decl->nameLoc.line ? decl->nameLoc : decl->loc, nullptr, &decl->extends};
    breakCycles(blocks, report);
    breakCycles(interfaces, report);
    for (auto& [key, n] : interfaces) {  // keep `extends` (the first base) in step with the list
        auto it = pous_.find(key);
        if (it != pous_.end()) it->second->ast->extends = n.bases->empty() ? std::string() : n.bases->front();
    }
    breakCycles(structs, report);
}

}  // namespace strun::sema
