#include "interpreter/project/variable_path.h"

#include <cctype>

#include "interpreter/source/closest_name.h"
#include "stdlib/literals.h"
#include "stdlib/number_scan.h"

namespace strun::project {

using sema::TK;
using sema::Type;

namespace {

// "; did you mean 'X'?" for a mistyped name among `names` (any case, as ST), or "".
std::string didYouMean(const std::string& typed, const std::vector<std::string>& names) {
    std::vector<std::string> keys;
    for (const auto& n : names) keys.push_back(stdlib::upperAscii(n));
    const std::string best = closestName(stdlib::upperAscii(typed), keys);
    for (size_t i = 0; i < keys.size(); ++i)
        if (!best.empty() && keys[i] == best) return "; did you mean '" + names[i] + "'?";
    return {};
}

bool opaque(const Type* t) { return t->kind == TK::Pointer || t->kind == TK::Reference || t->kind == TK::Interface; }

// A path split into steps: names and subscript lists.
struct Step {
    std::string name;              // set for a member step
    std::vector<int64_t> indices;  // set for a subscript step
};

bool splitPath(std::string_view path, std::vector<Step>& steps, std::string& error) {
    size_t i = 0;
    auto isIdent = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    bool expectName = true;
    while (i < path.size()) {
        char c = path[i];
        if (expectName) {
            size_t start = i;
            while (i < path.size() && isIdent(path[i])) ++i;
            if (i == start) {
                error = "'" + std::string(path) + "' is not a variable path (e.g. Main.start, Main.levels[3])";
                return false;
            }
            steps.push_back({std::string(path.substr(start, i - start)), {}});
            expectName = false;
        } else if (c == '.') {
            ++i;
            expectName = true;
        } else if (c == '[') {
            size_t close = path.find(']', i);
            if (close == std::string_view::npos) {
                error = "'" + std::string(path) + "': missing ']'";
                return false;
            }
            Step sub;
            std::string_view list = path.substr(i + 1, close - i - 1);
            size_t from = 0;
            for (;;) {
                size_t comma = list.find(',', from);
                std::string_view part = list.substr(from, comma == std::string_view::npos ? std::string_view::npos : comma - from);
                while (!part.empty() && part.front() == ' ') part.remove_prefix(1);
                while (!part.empty() && part.back() == ' ') part.remove_suffix(1);
                auto v = stdlib::parseSignedIntegerLiteral(part);
                if (!v) {
                    error = "'" + std::string(path) + "': subscript '" + std::string(part) + "' is not an integer";
                    return false;
                }
                sub.indices.push_back(v.value());
                if (comma == std::string_view::npos) break;
                from = comma + 1;
            }
            steps.push_back(std::move(sub));
            i = close + 1;
        } else {
            error = "'" + std::string(path) + "' is not a variable path (unexpected '" + std::string(1, c) + "')";
            return false;
        }
    }
    if (expectName || steps.empty()) {
        error = "'" + std::string(path) + "' is not a variable path";
        return false;
    }
    return true;
}

const sema::VarSym* memberVar(const Type* fb, const std::string& upperName) {
    for (const sema::PouInfo* p = fb->pou; p; p = p->parent) {
        auto it = p->vars.find(upperName);
        if (it != p->vars.end()) return it->second;
    }
    return nullptr;
}

// Walks the steps after the variable itself.
bool descend(VariableRef& ref, const std::vector<Step>& steps, size_t from, std::string& error) {
    for (size_t k = from; k < steps.size(); ++k) {
        const Step& step = steps[k];
        const Type* t = ref.type;
        if (step.name.empty()) {
            if (t->kind != TK::Array || t->dims.size() != step.indices.size()) {
                error = "'" + ref.path + "' is not an array of " + std::to_string(step.indices.size()) + " dimension(s)";
                return false;
            }
            uint64_t offset = 0, stride = t->size;
            std::string text;
            for (size_t d = 0; d < t->dims.size(); ++d) {
                const auto& dim = t->dims[d];
                stride /= uint64_t(dim.count());
                int64_t index = step.indices[d];
                if (index < dim.lo || index > dim.hi) {
                    error = "'" + ref.path + "': subscript " + std::to_string(index) + " is outside [" + std::to_string(dim.lo) + ".." +
                            std::to_string(dim.hi) + "]";
                    return false;
                }
                offset += uint64_t(index - dim.lo) * stride;
                text += (d ? "," : "") + std::to_string(index);
            }
            ref.addr += offset;
            ref.type = t->elem;
            ref.path += "[" + text + "]";
            continue;
        }
        if (t->kind != TK::Struct && t->kind != TK::FunctionBlock) {
            error = "'" + ref.path + "' has no members ('" + step.name + "')";
            return false;
        }
        const sema::Field* field = t->findField(stdlib::upperAscii(step.name));
        if (!field) {
            std::vector<std::string> names;
            for (const auto& f : t->fields) names.push_back(f.name);
            error = "no member '" + step.name + "' in '" + ref.path + "' (" + t->name + ")" + didYouMean(step.name, names);
            return false;
        }
        if (t->kind == TK::FunctionBlock)
            if (const sema::VarSym* v = memberVar(t, stdlib::upperAscii(step.name)); v && v->constant) ref.constant = true;
        ref.addr += field->offset;
        ref.type = field->type;
        ref.path += "." + field->name;
    }
    if (opaque(ref.type)) {
        error = "'" + ref.path + "' is a " + ref.type->name + ", which cannot be set or recorded";
        return false;
    }
    return true;
}

uint8_t* programVarAddress(const sema::ProgramInstance& inst, const sema::VarSym& v) {
    return v.storage == sema::Storage::Self ? inst.memory + v.offset : v.abs;
}

}  // namespace

std::optional<VariableRef> resolveVariablePath(const sema::ProgramModel& model, std::string_view path, std::string& error) {
    std::vector<Step> steps;
    if (!splitPath(path, steps, error)) return std::nullopt;
    std::string first = stdlib::upperAscii(steps[0].name);
    for (const auto& inst : model.programs) {
        if (stdlib::upperAscii(inst.name) != first) continue;
        if (steps.size() < 2 || steps[1].name.empty()) {
            error = "'" + std::string(path) + "' names the program instance '" + inst.name + "', not one of its variables";
            return std::nullopt;
        }
        auto it = inst.pou->vars.find(stdlib::upperAscii(steps[1].name));
        const sema::VarSym* v = it == inst.pou->vars.end() ? nullptr : it->second;
        if (!v || v->section == ast::VarSection::Temp || v->byRef || !programVarAddress(inst, *v)) {
            std::vector<std::string> names;
            for (const auto& [key, var] : inst.pou->vars)
                if (var->section != ast::VarSection::Temp && !var->byRef) names.push_back(var->name);
            error = "no variable '" + steps[1].name + "' in program instance '" + inst.name + "'" + didYouMean(steps[1].name, names);
            return std::nullopt;
        }
        VariableRef ref{inst.name + "." + v->name, v->type, programVarAddress(inst, *v), v->bit, v->constant, &inst};
        if (!descend(ref, steps, 2, error)) return std::nullopt;
        return ref;
    }
    // A global, by its name (skip 0) or after a global list's name (skip 1).
    for (size_t skip = 0; skip < 2 && skip < steps.size() && !steps[skip].name.empty(); ++skip) {
        std::string name = stdlib::upperAscii(steps[skip].name);
        for (const sema::VarSym* g : model.globals) {
            if (stdlib::upperAscii(g->name) != name || g->byRef || !g->abs) continue;
            // A name two global lists declare needs its list: GVL_A.x (decision 0096).
            if (g->sharedName && (skip == 0 || stdlib::upperAscii(g->listName) != stdlib::upperAscii(steps[0].name))) continue;
            VariableRef ref{g->globalKey(), g->type, g->abs, g->bit, g->constant, nullptr};
            if (!descend(ref, steps, skip + 1, error)) return std::nullopt;
            return ref;
        }
    }
    std::vector<std::string> names;
    for (const auto& inst : model.programs) names.push_back(inst.name);
    for (const sema::VarSym* g : model.globals) names.push_back(g->name);
    error = "no variable '" + std::string(path) + "' (neither a program instance's variable nor a global)" + didYouMean(steps[0].name, names);
    return std::nullopt;
}

namespace {

// False once `visit` asked to stop.
bool expand(const VariableRef& ref, std::vector<std::string>& scopes, const std::string& leaf,
            const std::function<bool(const ElementaryVar&)>& visit) {
    const Type* t = ref.type;
    if (opaque(t)) return true;
    if (t->kind == TK::Struct || t->kind == TK::FunctionBlock) {
        scopes.push_back(leaf);
        std::vector<const Type*> chain;
        for (const Type* c = t; c; c = c->parent) chain.insert(chain.begin(), c);
        for (const Type* c : chain)
            for (const auto& f : c->fields) {
                if (f.hidden) continue;
                VariableRef member{ref.path + "." + f.name, f.type, ref.addr + f.offset, -1, ref.constant, ref.program};
                if (!expand(member, scopes, f.name, visit)) return false;
            }
        scopes.pop_back();
        return true;
    }
    if (t->kind == TK::Array) {
        if (t->dims.empty()) return true;
        uint64_t count = 1;
        for (const auto& d : t->dims) count *= uint64_t(d.count());
        uint64_t elemSize = count ? t->size / count : 0;
        for (uint64_t n = 0; n < count; ++n) {
            std::string sub;
            uint64_t rest = n;
            std::vector<int64_t> idx(t->dims.size());
            for (size_t d = t->dims.size(); d-- > 0;) {
                idx[d] = t->dims[d].lo + int64_t(rest % uint64_t(t->dims[d].count()));
                rest /= uint64_t(t->dims[d].count());
            }
            for (size_t d = 0; d < idx.size(); ++d) sub += (d ? "," : "") + std::to_string(idx[d]);
            VariableRef element{ref.path + "[" + sub + "]", t->elem, ref.addr + n * elemSize, -1, ref.constant, ref.program};
            if (!expand(element, scopes, leaf + "[" + sub + "]", visit)) return false;
        }
        return true;
    }
    return visit(ElementaryVar{ref, scopes, leaf});
}

}  // namespace

void forEachElementary(const sema::ProgramModel& model, const std::function<bool(const ElementaryVar&)>& visit) {
    std::vector<std::string> scopes;
    for (const auto& inst : model.programs) {
        scopes.assign(1, inst.name);
        for (const auto& v : inst.pou->ownedVars) {
            if (v->section == ast::VarSection::Temp || v->byRef || v->hidden) continue;
            uint8_t* addr = programVarAddress(inst, *v);
            if (!addr) continue;
            if (!expand(VariableRef{inst.name + "." + v->name, v->type, addr, v->bit, v->constant, &inst}, scopes, v->name, visit)) return;
        }
    }
    scopes.clear();
    for (const sema::VarSym* g : model.globals) {
        if (g->byRef || !g->abs || g->hidden) continue;
        if (!expand(VariableRef{g->globalKey(), g->type, g->abs, g->bit, g->constant, nullptr}, scopes, g->globalKey(), visit)) return;
    }
}

}  // namespace strun::project
