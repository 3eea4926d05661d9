// "Did you mean ...?" for the checker's name errors: the closest declared
// name (one edit-distance implementation: interpreter/source/closest_name),
// compared without case as ST does, returned in its declared spelling.
#include <algorithm>

#include <fmt/format.h>

#include "interpreter/sema/checker.h"
#include "interpreter/source/closest_name.h"
#include "stdlib/library_registry.h"

namespace strun::sema {

namespace {

const char* const kElementaryTypes[] = {"BOOL", "BYTE", "WORD", "DWORD", "LWORD", "SINT", "INT", "DINT", "LINT",
                                        "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL", "TIME", "LTIME", "DATE",
                                        "TIME_OF_DAY", "TOD", "DATE_AND_TIME", "DT", "STRING", "WSTRING", "CHAR", "WCHAR"};

}  // namespace

std::string Checker::closestDeclared(const std::string& typed, const std::vector<std::string>& declared) const {
    std::vector<std::string> keys;
    keys.reserve(declared.size());
    for (const std::string& d : declared) keys.push_back(upper(d));
    const std::string best = closestName(upper(typed), keys);
    if (best.empty()) return "";
    for (size_t i = 0; i < keys.size(); ++i)
        if (keys[i] == best) return declared[i];
    return "";
}

void Checker::suggest(Diagnostic& d, const std::string& typed, const std::vector<std::string>& declared) const {
    if (!shown(d)) return;
    // A name of a vendor library (provided or not) says where it comes from (decision 0220).
    if (std::string hint = stdlib::libraryHint(typed); !hint.empty()) {
        d.withHelp(hint);
        return;
    }
    // One or two letters are one edit from too many names to guess which was meant.
    if (typed.size() < 3) return;
    const std::string best = closestDeclared(typed, declared);
    if (!best.empty() && upper(best) != upper(typed)) d.withHelp(fmt::format("did you mean '{}'?", best));
}

void Checker::suggest(Diagnostic& d, const std::string& typed, std::vector<std::string> (Checker::*candidates)() const) const {
    if (!shown(d)) return;
    suggest(d, typed, (this->*candidates)());
}

std::vector<std::string> Checker::visibleVariableNames() const {
    std::vector<std::string> out;
    const PouInfo* self = pou_;
    for (const PouInfo* p = self; p != nullptr; p = p->parent)
        for (const auto& [key, v] : p->vars) out.push_back(v->name);
    if (self && self->owner)
        for (const PouInfo* p = self->owner; p != nullptr; p = p->parent)
            for (const auto& [key, v] : p->vars) out.push_back(v->name);
    for (const auto& [key, v] : globals_) out.push_back(v->name);
    for (const auto& [key, value] : enumValues_.unique) out.push_back(value.second->name);
    return out;
}

std::vector<std::string> Checker::globalNames() const {
    std::vector<std::string> out;
    for (const auto& [key, v] : globals_) out.push_back(v->name);
    return out;
}

std::vector<std::string> Checker::typeNames() const {
    std::vector<std::string> out(std::begin(kElementaryTypes), std::end(kElementaryTypes));
    for (const auto& [key, decl] : typeDecls_) out.push_back(decl->name);
    for (const auto& [key, p] : pous_)
        if (p->kind == ast::PouKind::FunctionBlock || p->kind == ast::PouKind::Interface) out.push_back(p->name);
    // The library's block types, also of files the project did not load
    // (decisions 0150, 0220): read from the registry only when a name is not found.
    for (const stdlib::LibraryName& n : stdlib::libraryNames())
        if (n.kind == 'B' || n.kind == 'I' || n.kind == 'T') out.emplace_back(n.written);
    return out;
}

std::vector<std::string> Checker::functionNames() const {
    std::vector<std::string> out;
    for (const auto& [key, p] : pous_)
        if (p->kind == ast::PouKind::Function) out.push_back(p->name);
    // In name order, as the map they were kept in gave them (the suggestion
    // prefers the first of equally close names).
    std::vector<std::string> builtins = builtinTable().names();
    std::sort(builtins.begin(), builtins.end());
    for (std::string& key : builtins) out.push_back(std::move(key));
    for (const stdlib::LibraryName& n : stdlib::libraryNames())
        if (n.kind == 'F' || n.kind == 'X') out.emplace_back(n.written);
    return out;
}

void Checker::markUnresolved(const std::string& upperName) { unresolvedVars_.insert({pou_, upperName}); }

bool Checker::isUnresolved(const std::string& upperName) const {
    if (unresolvedVars_.count({nullptr, upperName})) return true;
    for (const PouInfo* p = pou_; p != nullptr; p = p->parent)
        if (unresolvedVars_.count({p, upperName})) return true;
    if (pou_ && pou_->owner)
        for (const PouInfo* p = pou_->owner; p != nullptr; p = p->parent)
            if (unresolvedVars_.count({p, upperName})) return true;
    return false;
}

}  // namespace strun::sema

namespace strun::sema {

void Checker::enumValueError(const ast::Loc& loc, const std::string& written, const Type* enumType) {
    Diagnostic& d = error(diag::E0104, loc, fmt::format("'{}' is not a value of enumeration '{}'", written, enumType->name));
    std::vector<std::string> values;
    std::string list;
    for (const auto& en : enumType->enumerators) {
        values.push_back(en.name);
        if (!list.empty()) list += ", ";
        list += en.name;
    }
    if (values.size() <= 20) d.note(fmt::format("'{}' has the values {}", enumType->name, list));
    suggest(d, written, values);
}

std::string Checker::instanceNameFor(const std::string& typeName) {
    std::string name = typeName.empty() ? "inst" : std::string(1, static_cast<char>(std::tolower(static_cast<unsigned char>(typeName[0]))));
    return name;
}

}  // namespace strun::sema
