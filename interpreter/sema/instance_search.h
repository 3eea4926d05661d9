// Whether a value of some type holds a function-block instance with a given
// property, anywhere inside it (arrays, structures, instances within
// instances, base blocks), memoised per type. The start-up walkers (FB_init,
// instance paths) ask it first, so that arrays of types without any such
// instance are skipped instead of visited element by element.
#pragma once

#include <map>

#include "interpreter/sema/symbols.h"
#include "interpreter/sema/types.h"

namespace strun::sema {

// Every variable a block keeps in its instance: its own and its methods'
// VAR_INST (decision 0143), which live in the instance too.
template <typename Visit>
void forEachInstanceVar(PouInfo* block, const Visit& visit) {
    for (auto& v : block->ownedVars)
        if (v->storage == Storage::Self && !v->byRef) visit(v.get());
    for (auto& [name, method] : block->methods)
        for (auto& v : method->ownedVars)
            if (v->storage == Storage::Self && !v->byRef) visit(v.get());
}

// `blockHas(pou)`: the block itself has the property (asked for each block of
// the EXTENDS chain); instances by value inside it are searched in turn.
template <typename BlockHas>
bool holdsInstanceWhere(const Type* t, std::map<const Type*, bool>& memo, const BlockHas& blockHas) {
    if (!t) return false;
    auto known = memo.find(t);
    if (known != memo.end()) return known->second;
    memo[t] = false;  // a cycle (already an error) ends here
    bool result = false;
    if (t->kind == TK::Array) {
        result = holdsInstanceWhere(t->elem, memo, blockHas);
    } else if (t->kind == TK::Struct) {
        for (const Type* p = t; p && !result; p = p->parent)
            for (const auto& f : p->fields) result = result || holdsInstanceWhere(f.type, memo, blockHas);
    } else if (t->kind == TK::FunctionBlock && t->pou) {
        for (PouInfo* p = t->pou; p && !result; p = p->parent) result = blockHas(p);
        for (PouInfo* p = t->pou; p && !result; p = p->parent)
            forEachInstanceVar(p, [&](VarSym* v) { result = result || holdsInstanceWhere(v->type, memo, blockHas); });
    }
    memo[t] = result;
    return result;
}

}  // namespace strun::sema
