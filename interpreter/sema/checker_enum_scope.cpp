// Enumeration values named without their type (decision 0441).
//
// TwinCAT and CODESYS let several enumerations have a value of the same name.
// A bare name is resolved, in this order: by the type the context expects (an
// assignment to an enumeration variable, a CASE label of an enumeration
// selector, the right operand of a comparison with one); by the anonymous
// enumerations declared in the POU being checked (`eState : (IDLE, RUN);` in
// several blocks does not make IDLE ambiguous); by the global enumerations;
// last by the anonymous enumerations of other POUs. Ambiguity within one of
// these levels is the E0108 "qualify it" error.
#include "interpreter/sema/checker.h"

namespace strun::sema {

void Checker::registerEnumValues(const Type* created, bool inlineEnum) {
    if (created->qualifiedOnly) return;  // only E.value / E#value name it
    const bool local = inlineEnum && inlineEnumScope_;
    for (const auto& e : created->enumerators) {
        const std::string key = upper(e.name);
        if (local) {
            pouEnumValues_[inlineEnumScope_].add(key, created, &e);
            anyPouEnumValues_.add(key, created, &e);
        } else {
            enumValues_.add(key, created, &e);
        }
    }
}

const Enumerator* Checker::lookupEnumValue(const std::string& key, const Type** enumType, bool& ambiguous) {
    auto in = [&](const EnumNames& names) -> const Enumerator* {
        auto it = names.unique.find(key);
        if (it == names.unique.end()) return nullptr;
        ambiguous = names.ambiguous.count(key) != 0;
        *enumType = it->second.first;
        return it->second.second;
    };
    if (!pouEnumValues_.empty() && pou_) {
        // The method's own, then its block's (and the bases' the block EXTENDS).
        for (const PouInfo* start : {static_cast<const PouInfo*>(pou_), static_cast<const PouInfo*>(pou_->owner)})
            for (const PouInfo* p = start; p; p = p->parent) {
                auto scope = pouEnumValues_.find(p);
                if (scope == pouEnumValues_.end()) continue;
                if (const Enumerator* e = in(scope->second)) return e;
            }
    }
    if (const Enumerator* e = in(enumValues_)) return e;
    return in(anyPouEnumValues_);
}

Checked Checker::checkExprExpecting(const ast::Expr& e, const Type* expected) {
    if (expected && expected->kind == TK::Enum && !expected->qualifiedOnly && e.kind == ast::ExprKind::Name && !e.pointerTo) {
        const std::string key = upper(e.name);
        const Enumerator* en = expected->findEnumerator(key);
        // A variable (or the block's property) of that name is what the name means.
        if (en && !lookupVar(key) && !hasOwnProperty(key)) return constInt(en->value, expected, e.loc);
    }
    return checkExpr(e);
}

}  // namespace strun::sema
