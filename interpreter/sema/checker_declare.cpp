// Declarations: collecting names, resolving types, laying out storage and
// writing initial values.
#include <algorithm>
#include <limits>
#include <cstring>

#include <fmt/format.h>

#include "interpreter/sema/attributes.h"
#include "interpreter/sema/any_argument.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/edge_inputs.h"
#include "interpreter/sema/fb_eno_slots.h"
#include "interpreter/sema/node_factory.h"

#include "stdlib/string_functions.h"

namespace strun::sema {

namespace {
bool byRefSection(ast::VarSection s) { return s == ast::VarSection::InOut; }
uint32_t alignUp(uint32_t v, uint32_t a) { return a <= 1 ? v : (v + a - 1) / a * a; }
constexpr uint32_t kMaxStorage = 256u * 1024u * 1024u;  // per block: keeps absurd declarations from exhausting memory
constexpr uint32_t kFbHeader = 8;                        // every FB instance starts with its class pointer
}  // namespace

namespace {
// "A.B" -> {"A", "A.B"}
void addNamespacePath(std::set<std::string>& out, const std::string& path) {
    if (path.empty()) return;
    std::string up = upper(path);
    for (size_t dot = up.find('.'); dot != std::string::npos; dot = up.find('.', dot + 1)) out.insert(up.substr(0, dot));
    out.insert(up);
}
}  // namespace

Checker::Checker(ProgramModel& model, CompileLog& log) : model_(model), log_(log) {
    model_.machine.image.inputExtent = 0;
    model_.machine.image.outputExtent = 0;
}

void Checker::collect(ast::CompilationUnit& unit) {
    for (auto& t : unit.types) {
        std::string key = upper(t.name);
        auto known = typeDecls_.find(key);
        if (known != typeDecls_.end() && libraryFiles_.count(known->second->loc.file) && !libraryFiles_.count(t.loc.file)) {
            // A user type named like a library one (an own T_MaxString, say) replaces it.
            known->second = &t;
            addNamespacePath(namespaces_, t.nameSpace);
            continue;
        }
        if (typeDecls_.count(key) || types().byName(key)) {
            error(diag::E0106, t.nameLoc.line ? t.nameLoc : t.loc, fmt::format("duplicate type name '{}'", t.name));
            continue;
        }
        typeDecls_[key] = &t;
        addNamespacePath(namespaces_, t.nameSpace);
    }
    for (auto& g : unit.globals) addNamespacePath(namespaces_, g.nameSpace);
    for (auto& p : unit.pous) declarePou(p.get(), nullptr);
    for (auto& g : unit.globals) globalLists_.push_back(&g);
    for (auto& c : unit.configurations) configurations_.push_back(&c);
}


// A name written `Ns.x`: the namespace part (flattened: names are unique project-wide).
bool Checker::isNamespace(const ast::Expr& e) const {
    if (e.kind == ast::ExprKind::Name) {
        const std::string name = upper(e.name);
        if (namespaces_.count(name)) return true;
        // Relative to a USING of the file or an enclosing namespace (IEC Ed.3,
        // SIMATIC AX: `USING AxUnit;` then `Assert.Equal(...)`, decision 0366).
        if (auto usings = usingsByFile_.find(nameScope_.file); usings != usingsByFile_.end())
            for (const std::string& u : usings->second)
                if (namespaces_.count(u + "." + name)) return true;
        for (std::string ns = nameScope_.nameSpace; !ns.empty();) {
            if (namespaces_.count(ns + "." + name)) return true;
            const auto dot = ns.rfind('.');
            ns = dot == std::string::npos ? std::string() : ns.substr(0, dot);
        }
        return false;
    }
    if (e.kind == ast::ExprKind::Member && !e.kids.empty() && isNamespace(*e.kids[0])) {
        std::string path;
        for (const ast::Expr* p = &e; p; p = p->kids.empty() ? nullptr : p->kids[0].get()) {
            path = upper(p->name) + (path.empty() ? "" : "." + path);
            if (p->kind == ast::ExprKind::Name) break;
        }
        // Namespaces are flattened, so a namespace or library name in front of another
        // namespace (`TcUnit.GVL_Param_TcUnit.X`, a library's global list) names that one.
        if (namespaces_.count(path) != 0 || namespaces_.count(upper(e.name)) != 0) return true;
        // Relative, as a single name above: `Strings.ToArray.OfCharCount(...)`
        // inside NAMESPACE Simatic.Ax.Conversion (simatic-ax/conversion's tests).
        if (auto usings = usingsByFile_.find(nameScope_.file); usings != usingsByFile_.end())
            for (const std::string& u : usings->second)
                if (namespaces_.count(u + "." + path)) return true;
        for (std::string ns = nameScope_.nameSpace; !ns.empty();) {
            if (namespaces_.count(ns + "." + path)) return true;
            const auto dot = ns.rfind('.');
            ns = dot == std::string::npos ? std::string() : ns.substr(0, dot);
        }
    }
    return false;
}

PouInfo* Checker::pouNamed(const std::string& written) const {
    std::string key = scopedKey(upper(written));
    auto it = pous_.find(key);
    if (it == pous_.end() && key.rfind('.') != std::string::npos) it = pous_.find(key.substr(key.rfind('.') + 1));
    return it == pous_.end() ? nullptr : it->second;
}

void Checker::declarePou(ast::Pou* pou, PouInfo* owner) {
    addNamespacePath(namespaces_, pou->nameSpace);
    addFbEnoSlots(*pou);  // the ENO of its instances called with EN/ENO (decision 0358)
    lowerEdgeInputs(*pou);  // `x : BOOL R_EDGE;` as a hidden R_TRIG (decision 0339)
    auto info = std::make_unique<PouInfo>();
    info->ast = pou;
    info->kind = pou->kind;
    info->name = pou->name;
    info->owner = owner;
    model_.codes.emplace_back();
    info->code = &model_.codes.back();
    info->code->library = libraryFiles_.count(pou->loc.file) > 0;
    info->code->name = owner ? owner->name + "." + pou->name : pou->name;
    PouInfo* raw = info.get();
    std::string key = upper(pou->name);
    if (owner) {
        info->slot = methodSlot(key);
        if (owner->methods.count(key)) error(diag::E0106, pou->nameLoc.line ? pou->nameLoc : pou->loc, fmt::format("duplicate method '{}' in '{}'", pou->name, owner->name));
        owner->methods[key] = raw;
        model_.pouStore.push_back(std::move(info));
    } else {
        auto existing = pous_.find(key);
        if (existing != pous_.end() && libraryFiles_.count(existing->second->ast->loc.file) && !libraryFiles_.count(pou->loc.file)) {
            // A user POU named like a library one (an own TON, say) replaces it.
            std::replace(pouOrder_.begin(), pouOrder_.end(), existing->second, raw);
            existing->second = raw;
            model_.pouStore.push_back(std::move(info));
        } else if (pous_.count(key) || typeDecls_.count(key) || types().byName(key)) {
            Diagnostic& d = error(diag::E0106, pou->nameLoc.line ? pou->nameLoc : pou->loc, fmt::format("duplicate declaration of '{}'", pou->name));
            if (existing != pous_.end() && existing->second->ast) {
                const ast::Pou& first = *existing->second->ast;
                d.note(first.nameLoc.line ? first.nameLoc : first.loc, fmt::format("'{}' is first declared here", first.name));
            }
            model_.pouStore.push_back(std::move(info));  // keep it alive, unreachable by name
        } else {
            pous_[key] = raw;
            model_.pouStore.push_back(std::move(info));
            pouOrder_.push_back(raw);
        }
    }
    for (auto& m : pou->methods) declarePou(m.get(), raw);
    // A PROPERTY is a pair of accessor methods: __GET_<name> returns it, __SET_<name> receives it.
    for (auto& prop : pou->properties) {
        for (int setter = 0; setter < 2; ++setter) {
            ast::Pou* acc = setter ? prop.setter.get() : prop.getter.get();
            if (!acc) continue;
            auto a = std::make_unique<PouInfo>();
            a->ast = acc;
            a->kind = ast::PouKind::Method;
            a->name = (setter ? "__SET_" : "__GET_") + prop.name;
            a->owner = raw;
            a->property = &prop;
            a->isSetter = setter != 0;
            model_.codes.emplace_back();
            a->code = &model_.codes.back();
            a->code->name = raw->name + "." + prop.name + (setter ? ".SET" : ".GET");
            std::string akey = upper(a->name);
            a->slot = methodSlot(akey);
            if (raw->methods.count(akey)) error(diag::E0106, prop.loc, fmt::format("duplicate property '{}' in '{}'", prop.name, raw->name));
            raw->methods[akey] = a.get();
            model_.pouStore.push_back(std::move(a));
        }
    }
}

// ---------------------------------------------------------------- types

const Type* Checker::resolveNamedType(const std::string& name, const ast::Loc& loc) {
    std::string key = scopedKey(upper(name));
    auto dot = key.rfind('.');
    if (dot != std::string::npos && !typeDecls_.count(key) && !pous_.count(key)) key = key.substr(dot + 1);
    if (const Type* t = types().byName(key)) {
        // __XWORD, __UXINT, __XINT: an IEC name cannot start with '__'.
        if (key.rfind("__", 0) == 0)
            refusedByStrict(diag::E0102, loc, fmt::format("'{}' is a CODESYS/TwinCAT platform-width type; --strict needs {}", name, t->name));
        return t;
    }
    if (typeDecls_.count(key)) return resolveTypeDecl(key, loc);
    if (isGenericTypeName(key)) {
        // ANY, ANY_NUM, ...: the __SYSTEM.AnyType of stdlib/st/system.st when the
        // project names __SYSTEM (which selects that file), else the same layout
        // built here with a UDINT TypeClass (decision 0302).
        if (typeDecls_.count("ANYTYPE")) return resolveTypeDecl("ANYTYPE", loc);
        auto& slot = resolvedTypes_[" AnyType"];  // no declared name has a space
        if (!slot) {
            Type t;
            t.kind = TK::Struct;
            t.name = "__SYSTEM.AnyType";
            t.fields = {Field{"TypeClass", types().elementary(TK::UDInt), 0, loc, false},
                        Field{"pValue", types().pointer(types().elementary(TK::Byte)), 8, loc, false},
                        Field{"diSize", types().elementary(TK::DInt), 16, loc, false}};
            t.size = 24;
            t.align = 8;
            slot = types().create(std::move(t));
        }
        return slot;
    }
    auto it = pous_.find(key);
    if (it != pous_.end()) {
        PouInfo* p = it->second;
        if (p->kind == ast::PouKind::FunctionBlock || p->kind == ast::PouKind::Program) {
            layoutPou(p);
            return p->instanceType;
        }
        if (p->kind == ast::PouKind::Interface) {
            Type t;
            t.kind = TK::Interface;
            t.name = p->name;
            t.size = 8;
            t.align = 8;
            t.pou = p;
            auto& slot = resolvedTypes_[key];
            if (!slot) slot = types().create(std::move(t));
            return slot;
        }
        error(diag::E0107, loc, fmt::format("'{}' is a function, not a type", name));
        return nullptr;
    }
    if (std::string candidates = ambiguityOf(key); !candidates.empty()) {
        error(diag::E0102, loc, fmt::format("'{}' is declared in more than one namespace: write one of {}, or add a USING", name, candidates));
        return nullptr;
    }
    suggest(error(diag::E0102, loc, fmt::format("unknown type '{}'", name)), name, &Checker::typeNames);
    return nullptr;
}

const Type* Checker::resolveTypeDecl(const std::string& key, const ast::Loc& loc) {
    auto done = resolvedTypes_.find(key);
    if (done != resolvedTypes_.end()) return done->second;
    ast::TypeDecl* decl = typeDecls_.at(key);
    if (resolvingTypes_.count(key)) {
        error(diag::E0403, decl->loc, fmt::format("type '{}' is defined in terms of itself", decl->name));
        return nullptr;
    }
    DeclDepthGuard depth(*this, decl->name, decl->nameLoc.line ? decl->nameLoc : decl->loc);
    if (!depth.ok()) return nullptr;
    NameScopeGuard scope(*this, decl->nameSpace, decl->loc.file);
    resolvingTypes_.insert(key);
    // A TYPE's own inline enumerations (a STRUCT member's) are global, whichever
    // POU's declaration made it be resolved now.
    const bool inlineEnum = decl->name.rfind("__ENUM_", 0) == 0;
    const PouInfo* enumScope = inlineEnumScope_;
    if (!inlineEnum) inlineEnumScope_ = nullptr;
    const Type* result = nullptr;
    const ast::TypeSpec* spec = decl->spec.get();
    if (spec && spec->kind == ast::TypeSpecKind::Struct) {
        Type* t = types().create(Type{});
        resolvedTypes_[key] = t;  // allows POINTER TO self inside
        t->kind = TK::Struct;
        t->name = decl->name;
        t->incomplete = true;
        uint32_t off = 0;
        uint32_t align = 1;
        if (!decl->extends.empty()) {
            const Type* base = resolveNamedType(decl->extends, decl->loc);
            if (base && base->incomplete) {
                error(diag::E0403, decl->loc, fmt::format("inheritance cycle: {}", cyclePath(base->name)));
            } else if (base && base->kind == TK::Struct) {
                t->parent = base;
                off = base->size;
                align = base->align;
            } else if (base) {
                error(diag::E0407, decl->loc, fmt::format("'{}' can only extend a structure", decl->name));
            }
        }
        std::vector<uint8_t> image;
        if (t->parent) image = t->parent->defaultImage.empty() ? std::vector<uint8_t>(t->parent->size) : t->parent->defaultImage;
        uint32_t unionSize = 0;
        for (const auto& f : spec->fields) {
            const Type* ft = resolveTypeSpec(f.type.get(), decl->name);
            if (!ft) {
                for (const std::string& name : f.names) unresolvedMembers_.insert({t, upper(name)});
                continue;
            }
            if (rejectByValueCycle(ft, f.type ? f.type->loc : f.loc)) continue;
            for (size_t n = 0; n < f.names.size(); ++n) {
                if (t->findField(upper(f.names[n]))) {
                    error(diag::E0106, f.loc, fmt::format("duplicate member '{}' in structure '{}'", f.names[n], decl->name));
                    continue;
                }
                align = std::max(align, ft->align);
                if (spec->isUnion) {
                    // UNION: every member starts at the union's first byte.
                    t->fields.push_back({f.names[n], ft, 0, n < f.nameLocs.size() ? f.nameLocs[n] : f.loc, hasAttribute(f.pragmas, "strun_hidden")});
                    unionSize = std::max(unionSize, ft->size);
                    continue;
                }
                off = alignUp(off, ft->align);
                t->fields.push_back({f.names[n], ft, off, n < f.nameLocs.size() ? f.nameLocs[n] : f.loc, hasAttribute(f.pragmas, "strun_hidden")});
                off += ft->size;
                if (off > kMaxStorage) { error(diag::E0007, f.loc, "structure too large"); off = 0; break; }
            }
        }
        if (spec->isUnion) off = std::max(off, unionSize);
        t->size = alignUp(off, align);
        t->align = align;
        image.resize(t->size);
        bool nonZero = false;
        std::unordered_map<std::string, const ast::VarDecl*> declOf;  // the last declaration of a name, as before
        for (const auto& f : spec->fields)
            for (const auto& n : f.names) declOf[upper(n)] = &f;
        for (const auto& fld : t->fields) {
            auto found = declOf.find(upper(fld.name));
            const ast::VarDecl* fd = found == declOf.end() ? nullptr : found->second;
            writeDefault(image.data() + fld.offset, fld.type);
            if (fd && fd->init) writeInitial(image.data() + fld.offset, fld.type, fd->init.get(), fd->loc);
        }
        if (t->parent && !t->parent->defaultImage.empty()) nonZero = true;
        for (uint8_t b : image) nonZero = nonZero || b != 0;
        if (nonZero) t->defaultImage = std::move(image);
        t->incomplete = false;
        result = t;
    } else if (spec && spec->kind == ast::TypeSpecKind::Enum) {
        Type t;
        t.kind = TK::Enum;
        t.name = decl->name;
        t.strictEnum = hasAttribute(decl->pragmas, "strict");
        t.enumToString = hasAttribute(decl->pragmas, "to_string");
        t.qualifiedOnly = hasAttribute(decl->pragmas, "qualified_only");
        const Type* base = spec->elem ? resolveTypeSpec(spec->elem.get(), decl->name) : types().elementary(TK::Int);
        if (base && !isInteger(base->kind) && !isBitString(base->kind)) {
            error(diag::E0407, spec->loc, "the base type of an enumeration must be an integer type");
            base = types().elementary(TK::Int);
        }
        if (!base) base = types().elementary(TK::Int);
        t.base = base;
        t.size = base->size;
        t.align = base->align;
        int64_t next = 0;
        bool pastLargest = false;  // the previous value was the largest LINT: no implicit next one
        for (const auto& ev : spec->enumValues) {
            int64_t v = next;
            if (ev.value && !constIntExpr(ev.value.get(), v, "an enumeration value")) v = next;
            if (!ev.value && pastLargest)
                error(diag::E0407, ev.loc, fmt::format("the enumeration value '{}' would follow the largest LINT: give it an explicit value", ev.name));
            if (t.findEnumerator(upper(ev.name))) error(diag::E0106, ev.loc, fmt::format("duplicate enumeration value '{}'", ev.name));
            t.enumerators.push_back({ev.name, v});
            pastLargest = v == std::numeric_limits<int64_t>::max();
            next = pastLargest ? v : v + 1;
        }
        t.enumDefault = t.enumerators.empty() ? 0 : t.enumerators.front().value;
        Type* created = types().create(std::move(t));
        resolvedTypes_[key] = created;
        registerEnumValues(created, inlineEnum);
        if (decl->init && decl->init->expr && decl->init->expr->kind == ast::ExprKind::Name) {
            const Enumerator* named = created->findEnumerator(upper(decl->init->expr->name));
            if (named) created->enumDefault = named->value;
            if (!named) error(diag::E0104, decl->init->loc, fmt::format("'{}' is not a value of '{}'", decl->init->expr->name, decl->name));
        }
        created->defaultImage.resize(created->size);
        writeScalar(created->defaultImage.data(), created, constInt(created->enumDefault, created->base, decl->loc));
        result = created;
    } else if (spec) {
        const Type* base = resolveTypeSpec(spec, decl->name);
        if (base && (decl->init || spec->kind == ast::TypeSpecKind::Subrange)) {
            Type t = *base;
            t.name = decl->name;
            if (decl->init) {
                t.defaultImage.assign(t.size, 0);
                writeInitial(t.defaultImage.data(), base, decl->init.get(), decl->loc);
            }
            result = types().create(std::move(t));
        } else {
            result = base;  // a plain alias is the same type
        }
    }
    inlineEnumScope_ = enumScope;
    resolvingTypes_.erase(key);
    resolvedTypes_[key] = result;
    if (resolvingTypes_.empty()) layOutDeferredMethods();
    return result;
}

// The methods of the blocks laid out while a TYPE was being resolved. A
// method's variables live in its call frame, not in the instance, so
// `TYPE T_Error : FB_Error;` with a method of FB_Error returning a T_Error
// through a VAR_OUTPUT is no cycle (decision 0458): they wait until no TYPE is
// in progress.
void Checker::layOutDeferredMethods() {
    while (!methodsDeferred_.empty()) {
        std::vector<PouInfo*> blocks;
        blocks.swap(methodsDeferred_);
        for (PouInfo* fb : blocks)
            for (auto& [name, m] : fb->methods) layoutPou(m);
    }
}

const Type* Checker::resolveTypeSpec(const ast::TypeSpec* spec, const std::string& context) {
    if (!spec) return nullptr;
    switch (spec->kind) {
        case ast::TypeSpecKind::Named:
            if (!spec->elementInitArgs.empty() && !elementArgsAllowed_) {
                error(diag::E0407, spec->loc, fmt::format("'{}[(...), ...]' gives FB_init arguments per element: it needs ARRAY[...] OF before it",
                                                  spec->name));
                return nullptr;
            }
            if (!spec->genericArgs.empty()) return specialisedInstanceType(*spec);
            return resolveNamedType(spec->name, spec->loc);
        case ast::TypeSpecKind::String: {
            const int64_t standard = types().elementary(spec->wide ? TK::WString : TK::String)->maxLen;  // 80; AX 254 (decision 0394)
            int64_t len = standard;
            if (spec->length && !constIntExpr(spec->length.get(), len, "a string length")) len = standard;
            // STRING(0) (TwinCAT: one byte, always empty; Beckhoff's MQTT sample
            // passes ADR of one as an empty payload) is accepted (decision 0329).
            if (len < 0 || len > stdlib::kMaxStringLength) {
                error(diag::E0407, spec->loc, fmt::format("string length {} outside 0..{}", len, stdlib::kMaxStringLength));
                len = 80;
            }
            return types().string(static_cast<uint32_t>(len), spec->wide);
        }
        case ast::TypeSpecKind::Array: {
            // `ARRAY[..] OF FB_X[(a := 1), (a := 2)]`: FB_init arguments per element (decision 0330).
            const bool perElement = spec->elem && !spec->elem->elementInitArgs.empty();
            elementArgsAllowed_ = perElement;
            const Type* elem = resolveTypeSpec(spec->elem.get(), context);
            elementArgsAllowed_ = false;
            if (!elem) return nullptr;
            if (perElement && elem->kind != TK::FunctionBlock) {
                error(diag::E0407, spec->elem->loc, fmt::format("FB_init arguments per element need an array of function blocks, not of {}",
                                                        typeName(elem)));
                return nullptr;
            }
            std::vector<ArrayDim> dims;
            bool flexible = false;
            // Bytes, counting a zero-size element (an empty STRUCT) as one byte so
            // that the element count is capped too (docs/limits.md).
            uint64_t total = std::max<uint32_t>(elem->size, 1);
            for (const auto& r : spec->dims) {
                if (r.star) { flexible = true; dims.push_back({0, -1}); continue; }
                int64_t lo = 0, hi = 0;
                // Both bounds are checked, lower first, so that both get their diagnostics.
                const bool loOk = constIntExpr(r.lo.get(), lo, "an array bound");
                const bool hiOk = constIntExpr(r.hi.get(), hi, "an array bound");
                if (!loOk || !hiOk) return nullptr;
                if (hi < lo) {
                    error(diag::E0407, spec->loc, fmt::format("array upper bound {} is below lower bound {}", hi, lo));
                    return nullptr;
                }
                // Unsigned span: LINT#-9223372036854775808..LINT#9223372036854775807 has 2^64 elements.
                const uint64_t span = static_cast<uint64_t>(hi) - static_cast<uint64_t>(lo);
                if (span >= kMaxStorage || (span + 1) > kMaxStorage / total) {
                    error(diag::E0007, spec->loc, "array too large (more than 256 MiB)");
                    return nullptr;
                }
                total *= span + 1;
                dims.push_back({lo, hi});
            }
            const Type* t = types().array(elem, std::move(dims), flexible);
            return t;
        }
        case ast::TypeSpecKind::Pointer: {
            const Type* target = resolveTypeSpec(spec->elem.get(), context);
            return target ? (spec->refTo ? types().refTo(target) : types().pointer(target)) : nullptr;
        }
        case ast::TypeSpecKind::Reference: {
            const Type* target = resolveTypeSpec(spec->elem.get(), context);
            // TwinCAT and CODESYS take an ARRAY[*] only at the top of a
            // parameter's type; REFERENCE TO is theirs alone (SIMATIC AX
            // writes REF_TO ARRAY[*], which strun accepts): decision 0428.
            if (target && target->kind == TK::Array && target->flexible) {
                error(diag::E0407, spec->loc, "REFERENCE TO ARRAY[*] is not a type TwinCAT or CODESYS accept")
                    .withHelp("declare a VAR_IN_OUT 'name : ARRAY[*] OF T' (passed by reference), or a 'REF_TO ARRAY[*] OF T' "
                              "bound with REF(array)");
                return nullptr;
            }
            return target ? types().reference(target) : nullptr;
        }
        case ast::TypeSpecKind::Subrange: {
            const Type* base = resolveTypeSpec(spec->elem.get(), context);
            if (!base) return nullptr;
            if (!isInteger(base->kind)) {
                error(diag::E0407, spec->loc, "a subrange needs an integer base type");
                return base;
            }
            int64_t lo = 0, hi = 0;
            if (!constIntExpr(spec->lo.get(), lo, "a subrange bound") || !constIntExpr(spec->hi.get(), hi, "a subrange bound"))
                return base;
            Type t = *base;
            t.isSubrange = true;
            t.rangeLo = lo;
            t.rangeHi = hi;
            t.base = base;
            t.name = fmt::format("{}({}..{})", base->name, lo, hi);
            if (lo > 0 || hi < 0) {
                t.defaultImage.assign(t.size, 0);
                writeScalar(t.defaultImage.data(), base, constInt(lo, base, spec->loc));
            }
            return types().create(std::move(t));
        }
        case ast::TypeSpecKind::Enum: {
            // `fb : FB(a := 1)` parses like a typed enumeration: it is an FB
            // instance with FB_init arguments (see buildFbInitCalls).
            if (spec->elem && spec->elem->kind == ast::TypeSpecKind::Named) {
                auto it = pous_.find(scopedKey(upper(spec->elem->name)));
                if (it != pous_.end() && it->second->kind == ast::PouKind::FunctionBlock)
                    return spec->elem->genericArgs.empty() ? resolveNamedType(spec->elem->name, spec->loc)
                                                           : specialisedInstanceType(*spec->elem);
                // A name that is no type at all (`ARRAY[..] OF UAHADataValue(ValueSize := n)`
                // with a library strun lacks): an unknown block with FB_init
                // arguments, not an enumeration on it; the unknown type is the
                // one error (decision 0330).
                const std::string key = scopedKey(upper(spec->elem->name));
                if (!types().byName(upper(spec->elem->name)) && !typeDecls_.count(key) && it == pous_.end())
                    return resolveNamedType(spec->elem->name, spec->elem->loc);
            }
            // Inline enumeration in a declaration: an anonymous enum type.
            static int counter = 0;
            std::string name = fmt::format("__ENUM_{}_{}", context, counter++);
            auto decl = std::make_unique<ast::TypeDecl>();
            decl->name = name;
            decl->loc = spec->loc;
            // Borrow the spec: the anonymous decl only lives during resolution.
            ast::TypeSpec copy;
            copy.kind = spec->kind;
            copy.loc = spec->loc;
            for (const auto& ev : spec->enumValues) {
                ast::EnumValue v;
                v.loc = ev.loc;
                v.name = ev.name;
                if (ev.value) {
                    // Values of inline enumerations are evaluated now, so the AST stays untouched.
                    int64_t iv = 0;
                    if (constIntExpr(ev.value.get(), iv, "an enumeration value")) {
                        v.value = std::make_unique<ast::Expr>();
                        v.value->kind = ast::ExprKind::Literal;
                        v.value->lit = ast::LitKind::Integer;
                        v.value->text = std::to_string(iv < 0 ? -iv : iv);
                        if (iv < 0) {
                            auto neg = std::make_unique<ast::Expr>();
                            neg->kind = ast::ExprKind::Unary;
                            neg->op = ast::Op::Neg;
                            neg->kids.push_back(std::move(v.value));
                            v.value = std::move(neg);
                        }
                    }
                }
                copy.enumValues.push_back(std::move(v));
            }
            decl->spec = std::make_unique<ast::TypeSpec>(std::move(copy));
            std::string key = upper(name);
            typeDecls_[key] = decl.get();
            const Type* t = resolveTypeDecl(key, spec->loc);
            inlineEnumDecls_.push_back(std::move(decl));
            return t;
        }
        case ast::TypeSpecKind::Struct:
            error(diag::E0009, spec->loc, "a STRUCT can only be declared in a TYPE");
            return nullptr;
    }
    return nullptr;
}

// Whether `e` (a name) is a constant integer, without reporting anything:
// `[N(x)]` repeats x N times then, else it is a call of N (a function).
bool Checker::isConstantInteger(const ast::Expr& e) {
    const bool saved = silent_;
    silent_ = true;
    Checked c = checkExpr(e);
    silent_ = saved;
    return c.ok && c.isConst && (isIntRep(c.type) || c.untypedInt);
}

bool Checker::constIntExpr(const ast::Expr* e, int64_t& out, const char* what) {
    if (!e) return false;
    Checked c = checkExpr(*e);
    if (!c.ok) return false;
    if (!c.isConst || !(isIntRep(c.type) || c.untypedInt)) {
        error(diag::E0401, e->loc, fmt::format("{} must be a constant integer expression", what));
        return false;
    }
    out = c.constInt;
    return true;
}

// ---------------------------------------------------------------- layout

void Checker::layoutPou(PouInfo* pou) {
    if (pou->laidOut) return;
    // Laid out again while in progress: the caller reports the cycle
    // (rejectByValueCycle on the incomplete instance type).
    if (pou->layingOut) return;
    DeclDepthGuard depth(*this, pou->name, pou->ast->nameLoc.line ? pou->ast->nameLoc : pou->ast->loc);
    if (!depth.ok()) return;
    pou->layingOut = true;
    NameScopeGuard scope(*this, pou->ast->nameSpace, pou->ast->loc.file);
    PouInfo* savedPou = pou_;
    pou_ = pou;
    const bool hasInstance = pou->kind == ast::PouKind::Program || pou->kind == ast::PouKind::FunctionBlock;
    uint32_t instOff = 0;
    uint32_t frameOff = 0;
    std::vector<Field> fields;
    Type* inst = nullptr;
    if (hasInstance) {
        inst = types().create(Type{});
        inst->kind = TK::FunctionBlock;
        inst->name = pou->name;
        inst->pou = pou;
        inst->incomplete = true;
        pou->instanceType = inst;
        if (pou->kind == ast::PouKind::FunctionBlock) instOff = kFbHeader;
        if (!pou->ast->extends.empty() && pou->kind == ast::PouKind::FunctionBlock) {
            // EXTENDS Lib.Base: namespaces are flattened, as for type names.
            // EXTENDS FB_Base<100>: the specialisation for those values.
            const bool generic = !pou->ast->extendsGenericArgs.empty();
            PouInfo* baseInfo = generic ? specialise(pou->ast->extends, pou->ast->extendsGenericArgs, pou->ast->loc)
                                        : pouNamed(pou->ast->extends);
            if (baseInfo && baseInfo->kind == ast::PouKind::FunctionBlock)
                layoutPou(baseInfo);
            else if (!generic)  // specialise reported its own error
                error(diag::E0102, pou->ast->loc, fmt::format("unknown function block '{}' in EXTENDS", pou->ast->extends));
            if (baseInfo && baseInfo->kind == ast::PouKind::FunctionBlock && baseInfo->laidOut) {
                pou->parent = baseInfo;
                inst->parent = pou->parent->instanceType;
                instOff = pou->parent->instanceType ? pou->parent->instanceType->size : kFbHeader;
                pou->params = pou->parent->params;
            }
        }
    }
    if (pou->property && pou->isSetter) {
        // The setter receives the new value in a variable named like the property.
        const Type* pt = resolveTypeSpec(pou->property->type.get(), pou->name);
        if (pt) {
            auto v = std::make_unique<VarSym>();
            v->name = pou->property->name;
            v->loc = pou->property->loc;
            v->type = pt;
            v->section = ast::VarSection::Input;
            v->storage = Storage::Frame;
            v->owner = pou;
            frameOff = pt->size;
            pou->params.push_back(v.get());
            pou->vars[upper(v->name)] = v.get();
            pou->ownedVars.push_back(std::move(v));
        }
    }
    if (pou->kind == ast::PouKind::Function || pou->kind == ast::PouKind::Method) {
        const ast::TypeSpec* resultSpec = pou->ast->returnType.get();
        if (pou->property) resultSpec = pou->isSetter ? nullptr : pou->property->type.get();
        if (resultSpec) {
            pou->resultType = resolveTypeSpec(resultSpec, pou->name);
            if (isFlexibleRef(pou->resultType))  // returned as an 8-byte value: no bounds (decision 0402)
                error(diag::E0407, resultSpec->loc, "a REF_TO ARRAY[*] cannot be a result type");
            if (pou->resultType) {
                auto v = std::make_unique<VarSym>();
                // A function renamed to its qualified name (decision 0325) still
                // assigns its result by its own name.
                // An overload renamed "F(INT)" (decision 0362) likewise.
                const std::string plain = pou->name.substr(0, pou->name.find('('));
                v->name = pou->property ? pou->property->name : plain.substr(plain.rfind('.') + 1);
                v->loc = pou->ast->loc;
                v->type = pou->resultType;
                v->section = ast::VarSection::Output;
                v->storage = Storage::Frame;
                v->offset = 0;
                v->owner = pou;
                frameOff = pou->resultType->size;
                pou->result = v.get();
                pou->vars[upper(v->name)] = v.get();
                pou->ownedVars.push_back(std::move(v));
            }
        }
    }
    declareVars(pou, pou->ast->vars, instOff, frameOff, hasInstance ? &fields : nullptr);
    // A PROGRAM's methods keep their VAR_INST in the program instance as a block's do (decision 0146).
    if (inst && (pou->kind == ast::PouKind::FunctionBlock || pou->kind == ast::PouKind::Program))
        declareMethodInstanceVars(pou, instOff, fields);
    if (inst) {
        uint32_t align = 8;
        inst->fields = std::move(fields);
        inst->size = alignUp(std::max<uint32_t>(instOff, 1), align);
        inst->align = align;
        inst->incomplete = false;
        // Initial image: parent image, then own members.
        std::vector<uint8_t> image(inst->size, 0);
        if (pou->parent && pou->parent->instanceType)
            std::memcpy(image.data(), pou->parent->instanceInit.data(), pou->parent->instanceInit.size());
        auto initialise = [&](PouInfo* owner) {
            for (auto& v : owner->ownedVars) {
                if (v->storage != Storage::Self || v->byRef) continue;
                writeDefault(image.data() + v->offset, v->type);
                if (isAddressInit(v.get())) { pou->addressInits.push_back({v.get(), nullptr, v->decl->init->expr.get()}); continue; }
                // A method's VAR_INST too (TwinCAT collections: `fbView : FB_View :=
                // (ipList := THIS^.fbList);` in a property's getter): its
                // assignment is checked in the method's scope (addressInitStmt).
                writeVarInitial(image.data() + v->offset, v.get(), &pou->addressInits);
            }
        };
        initialise(pou);
        if (pou->kind == ast::PouKind::FunctionBlock || pou->kind == ast::PouKind::Program)
            for (auto& [name, m] : pou->methods) initialise(m);  // the methods' VAR_INST
        if (pou->kind == ast::PouKind::FunctionBlock) {
            // Every FB instance starts with its class (methods dispatch through it).
            if (!pou->classDesc) {
                model_.classes.emplace_back();
                model_.machine.memory.addObject(&model_.classes.back());
                pou->classDesc = &model_.classes.back();
                pou->classDesc->name = pou->name;
            }
            const exec::ClassDesc* desc = pou->classDesc;
            std::memcpy(image.data(), &desc, sizeof desc);
        }
        pou->instanceInit = image;
        inst->defaultImage = std::move(image);
    }
    pou->frameSize = alignUp(frameOff, 16);
    pou->code->frameSize = pou->frameSize;
    pou->code->initSize = pou->frameSize;
    pou->code->resultOffset = 0;
    if (!pou->resultType && (pou->kind == ast::PouKind::Method || pou->kind == ast::PouKind::Function))
        for (const VarSym* p : pou->params)  // TwinCAT's value of a VOID method or function (decision 0387)
            if (p->section == ast::VarSection::Output) {
                if (!p->byRef && p->type) pou->code->resultOffset = p->offset;
                break;
            }
    pou->code->frameInit.assign(exec::frameImageSize(pou->frameSize), 0);
    for (auto& v : pou->ownedVars) {
        if (v->storage != Storage::Frame || v->byRef || v->inferred) continue;
        uint8_t* p = pou->code->frameInit.data() + v->offset;
        writeDefault(p, v->type);
        if (isAddressInit(v.get())) { pou->frameAddressInits.push_back({v.get(), nullptr, v->decl->init->expr.get()}); continue; }
        // Inputs keep what the caller passed: only locals and outputs are assigned at each call.
        const bool assignable = v->section != ast::VarSection::Input && v->section != ast::VarSection::InOut;
        writeVarInitial(p, v.get(), assignable ? &pou->frameAddressInits : nullptr);
    }
    pou->layingOut = false;
    pou->laidOut = true;
    pou_ = savedPou;
    if (!resolvingTypes_.empty() && !pou->methods.empty()) {
        methodsDeferred_.push_back(pou);  // after the TYPE in progress (layOutDeferredMethods)
        return;
    }
    for (auto& [name, m] : pou->methods) layoutPou(m);
}

// CODESYS VAR_INST of a method: kept between calls, in the instance of the
// block that owns the method (laid out with it, before the method itself).
// Their fields are named `Method.var`, which no member access can spell.
void Checker::declareMethodInstanceVars(PouInfo* fb, uint32_t& instOff, std::vector<Field>& fields) {
    for (auto& [key, m] : fb->methods) {
        if (!m->ast) continue;
        bool any = false;
        for (const auto& block : m->ast->vars) any = any || block.section == ast::VarSection::Inst;
        if (!any) continue;
        const size_t first = fields.size();
        uint32_t unusedFrame = 0;
        PouInfo* saved = pou_;
        pou_ = m;
        declareVars(m, m->ast->vars, instOff, unusedFrame, &fields, true);
        pou_ = saved;
        for (size_t k = first; k < fields.size(); ++k) fields[k].name = m->name + "." + fields[k].name;
        m->instanceVarsDeclared = true;
    }
}

void Checker::declareVars(PouInfo* pou, const std::vector<ast::VarBlock>& blocks, uint32_t& instOff, uint32_t& frameOff,
                          std::vector<Field>* instanceFields, bool instOnly) {
    const bool hasInstance = instanceFields != nullptr;
    for (const auto& block : blocks) {
        if (instOnly && block.section != ast::VarSection::Inst) continue;
        // A method's VAR_INST was declared with its block's instance (declareMethodInstanceVars).
        if (block.section == ast::VarSection::Inst && !instOnly && pou->instanceVarsDeclared) continue;
        if (block.generic && pou->kind != ast::PouKind::FunctionBlock)
            error(diag::E0009, block.loc, "VAR_GENERIC CONSTANT belongs to a FUNCTION_BLOCK");
        for (const auto& decl : block.vars) {
            const Type* t = nullptr;
            bool isExternal = block.section == ast::VarSection::External;
            if (decl.type) {
                const PouInfo* outer = inlineEnumScope_;
                inlineEnumScope_ = pou;  // `eState : (IDLE, RUN)`: its values are the POU's (decision 0441)
                t = resolveTypeSpec(decl.type.get(), pou->name);
                inlineEnumScope_ = outer;
            }
            if (!t && !isExternal) {
                for (const std::string& name : decl.names) unresolvedVars_.insert({pou, upper(name)});
                continue;
            }
            if (t && block.section != ast::VarSection::InOut && rejectByValueCycle(t, decl.type ? decl.type->loc : decl.loc)) continue;
            if (decl.edge != ast::VarDecl::Edge::None &&
                (block.section != ast::VarSection::Input || (pou->kind != ast::PouKind::FunctionBlock && pou->kind != ast::PouKind::Program) ||
                 !t || t->kind != TK::Bool))
                error(diag::E0407, decl.type ? decl.type->loc : decl.loc,
                      "R_EDGE and F_EDGE belong to a BOOL input (VAR_INPUT) of a function block or program");
            for (size_t n = 0; n < decl.names.size(); ++n) {
                const std::string& name = decl.names[n];
                ast::Loc loc = n < decl.nameLocs.size() ? decl.nameLocs[n] : decl.loc;
                std::string key = upper(name);
                bool dup = pou->vars.count(key) != 0;
                // A base class's VAR PRIVATE member is invisible here: the name is
                // free for the derived class's own (SIMATIC AX, IEC Ed.3; decision 0393).
                for (PouInfo* p = pou->parent; p && !dup; p = p->parent) {
                    auto inherited = p->vars.find(key);
                    dup = inherited != p->vars.end() &&
                          !(inherited->second->access == ast::Access::Private && inherited->second->section == ast::VarSection::Var);
                }
                if (dup) {
                    error(diag::E0106, loc, fmt::format("duplicate variable '{}' in '{}'", name, pou->name));
                    continue;
                }
                auto v = std::make_unique<VarSym>();
                v->name = name;
                v->loc = loc;
                v->type = t;
                v->section = block.section;
                v->access = block.access;
                v->constant = block.constant;
                v->retain = block.retain || block.persistent;
                v->decl = &decl;
                v->owner = pou;
                v->hidden = hasAttribute(decl.pragmas, "strun_hidden");
                if (hasAttribute(decl.pragmas, "strun_inferred_temp")) {
                    // Typed and placed at its first assignment (fixInferredTemp).
                    v->inferred = v->inferredPending = v->hidden = true;
                    v->storage = Storage::Frame;
                    pou->vars[key] = v.get();
                    pou->ownedVars.push_back(std::move(v));
                    continue;
                }
                if (isExternal) {
                    auto g = globals_.find(key);
                    if (g == globals_.end()) {
                        suggest(error(diag::E0406, loc, fmt::format("VAR_EXTERNAL '{}' names no global variable", name)), name, &Checker::globalNames);
                        unresolvedVars_.insert({pou, key});
                        continue;
                    }
                    if (g->second->sharedName) ambiguousGlobal(g->second, loc, name);
                    if (t && !sameType(t, g->second->type))
                        error(diag::E0406, loc, fmt::format("VAR_EXTERNAL '{}' is declared {} but the global is {}", name, typeName(t), typeName(g->second->type)));
                    v->global = g->second;
                    v->type = g->second->type;
                    v->storage = Storage::Abs;
                    v->abs = g->second->abs;
                    v->bit = g->second->bit;
                    v->constant = v->constant || g->second->constant;
                    pou->vars[key] = v.get();
                    pou->ownedVars.push_back(std::move(v));
                    continue;
                }
                if (t->kind == TK::FunctionBlock && t->pou && t->pou->ast->abstract && !byRefSection(block.section))
                    error(diag::E0405, decl.type ? decl.type->loc : loc, fmt::format("'{}' is ABSTRACT: it cannot have instances", t->name));
                // ARRAY[*] as a VAR_INPUT (SIMATIC AX, IEC Ed.3): bound like a
                // VAR_IN_OUT CONSTANT, by address and bounds, read-only (decision 0395).
                const bool flexibleInput = t->kind == TK::Array && t->flexible && block.section == ast::VarSection::Input;
                if (t->kind == TK::Array && t->flexible && block.section != ast::VarSection::InOut && !flexibleInput)
                    error(diag::E0407, loc, "ARRAY[*] is only allowed in VAR_IN_OUT and VAR_INPUT");
                if (flexibleInput) v->constant = true;
                // A REF_TO ARRAY[*] is copied by its descriptor only where an
                // assignment stores it (decision 0402): not as an input or output.
                if (isFlexibleRef(t) && (block.section == ast::VarSection::Input || block.section == ast::VarSection::Output))
                    error(diag::E0407, loc, "a REF_TO ARRAY[*] can be a VAR, VAR_TEMP, VAR_IN_OUT, member or global variable, not an input or output");
                const bool byRef = block.section == ast::VarSection::InOut || flexibleInput;
                // ARRAY[*]: address and bounds (docs/decisions/0077); other in-outs: an address.
                const uint32_t size = byRef ? (t->flexible ? 8 + 16 * static_cast<uint32_t>(t->dims.size()) : 8) : t->size;
                const uint32_t align = byRef ? 8 : t->align;
                if (!decl.address.empty() && decl.address.find('*') == std::string::npos) {
                    int bit = -1;
                    v->abs = mapAddress(decl.address, t, loc, bit);
                    v->bit = bit;
                    v->storage = Storage::Abs;
                    if (!v->abs) continue;
                    if (decl.init) writeLocatedInitial(*v, decl.init.get(), decl.loc);
                } else if (block.section == ast::VarSection::Temp || !hasInstance) {
                    if (block.section == ast::VarSection::Stat) {
                        v->storage = Storage::Abs;
                        v->abs = model_.allocate(size);
                        writeDefault(v->abs, t);
                        // `nSeed : DWORD := F_Seed();`: what is not a constant is
                        // assigned once before the first cycle, as for a global.
                        if (decl.init && isAddressInit(v.get())) staticInits_.push_back({v.get(), nullptr, decl.init->expr.get()});
                        else if (decl.init) writeVarInitial(v->abs, v.get(), &staticInits_);
                    } else {
                        frameOff = alignUp(frameOff, align);
                        v->storage = Storage::Frame;
                        v->offset = frameOff;
                        frameOff += size;
                        if (frameOff > kMaxStorage) { error(diag::E0007, loc, "too many local variables (frame above 256 MiB)"); frameOff = 0; }
                    }
                } else {
                    instOff = alignUp(instOff, align);
                    v->storage = Storage::Self;
                    v->offset = instOff;
                    instOff += size;
                    if (instOff > kMaxStorage) { error(diag::E0007, loc, "instance too large (above 256 MiB)"); instOff = 0; }
                    instanceFields->push_back({name, byRef ? types().reference(t) : t, v->offset, loc, v->hidden});
                }
                v->byRef = byRef;
                model_.largestType = std::max(model_.largestType, t->size);
                if (block.section == ast::VarSection::Input || block.section == ast::VarSection::Output ||
                    block.section == ast::VarSection::InOut)
                    pou->params.push_back(v.get());
                // VAR_IN_OUT CONSTANT (CODESYS, TwinCAT): read-only by reference, no initial value.
                // VAR_INPUT CONSTANT: an input the POU cannot write; the caller gives
                // its value, its initial value is only the default (decision 0436).
                if (block.constant && block.section == ast::VarSection::Input)
                    refusedByStrict(diag::E0407, loc, fmt::format("VAR_INPUT CONSTANT '{}' is a CODESYS extension; --strict needs a plain VAR_INPUT", name));
                else if (block.constant && !byRef) {
                    if (!decl.init) error(diag::E0401, loc, fmt::format("CONSTANT '{}' needs an initial value", name));
                    else foldConstant(*v, decl);
                }
                pou->vars[key] = v.get();
                pou->ownedVars.push_back(std::move(v));
            }
        }
    }
}

// A CONSTANT scalar with a constant initial value is folded into its uses.
void Checker::foldConstant(VarSym& v, const ast::VarDecl& decl) {
    if (decl.init->kind == ast::InitKind::Expr && v.type && isStringType(v.type->kind)) {
        foldStringConstant(v, decl);
        return;
    }
    if (decl.init->kind != ast::InitKind::Expr || !(isIntRep(v.type) || isRealRep(v.type))) return;
    Checked c = checkExpr(*decl.init->expr);
    if (!c.ok || !c.isConst) return;
    c = coerce(c, v.type, decl.init->loc, "initial value");
    if (!c.ok || !c.isConst) return;
    v.hasConstValue = true;
    v.constInt = c.constInt;
    v.constReal = c.constReal;
}

// ---------------------------------------------------------------- globals

VarSym* Checker::addGlobal(const ast::VarDecl& decl, size_t n, const ast::VarBlock& block, uint32_t& listSize) {
    const std::string& name = decl.names[n];
    ast::Loc loc = n < decl.nameLocs.size() ? decl.nameLocs[n] : decl.loc;
    std::string key = upper(name);
    auto existing = globals_.find(key);
    // Two named lists may both declare a name (GVL_A.x, GVL_B.x); within one
    // list, or beside a global of no list, it is a duplicate.
    VarSym* other = existing == globals_.end() ? nullptr : existing->second;
    // The project's own global named like a library's (TCPADS_MAXUDP_BUFFSIZE in a
    // project's GVL): the project's takes the name, as a user POU or type named
    // like a library's does; TwinCAT keeps the library's behind its namespace.
    const bool replacesLibraryGlobal = other && libraryFiles_.count(other->loc.file) && !libraryFiles_.count(loc.file);
    // A {attribute 'qualified_only'} list's name is invisible unqualified, so
    // it neither takes the bare name from another global nor clashes with one
    // (decision 0455): a bare PI beside Struckig's Constants.PI is Tc2_System's.
    const bool inOtherList = other && !listGlobals_.count(upper(declaringList_) + "." + key);
    const bool hiddenBesideOther = inOtherList && !qualifiedOnlyList_.empty();
    const bool otherHidden = inOtherList && !other->qualifiedOnlyList.empty();
    if (replacesLibraryGlobal || hiddenBesideOther || otherHidden) other = nullptr;
    if (other && (other->listName.empty() || declaringList_.empty() || listGlobals_.count(upper(declaringList_) + "." + key))) {
        error(diag::E0106, loc, fmt::format("duplicate global variable '{}'", name));
        return nullptr;
    }
    const Type* t = resolveTypeSpec(decl.type.get(), name);
    if (!t) {
        unresolvedVars_.insert({nullptr, upper(name)});
        return nullptr;
    }
    auto v = std::make_unique<VarSym>();
    v->name = name;
    v->loc = loc;
    v->type = t;
    v->section = ast::VarSection::Global;
    v->qualifiedOnlyList = qualifiedOnlyList_;
    v->constant = block.constant;
    v->retain = block.retain || block.persistent;
    v->decl = &decl;
    v->hidden = hasAttribute(decl.pragmas, "strun_hidden");  // a library's own helper global
    v->storage = Storage::Abs;
    model_.largestType = std::max(model_.largestType, t->size);
    if (!decl.address.empty() && decl.address.find('*') == std::string::npos) {
        int bit = -1;
        v->abs = mapAddress(decl.address, t, loc, bit);
        v->bit = bit;
        if (!v->abs) return nullptr;
        if (decl.init) writeLocatedInitial(*v, decl.init.get(), decl.loc);
    } else {
        // Placed in its list's block once the whole list is laid out (declareGlobals).
        listSize = alignUp(listSize, t->align);
        v->offset = listSize;
        listSize += std::max<uint32_t>(t->size, 1);
        if (listSize > kMaxStorage) {
            error(diag::E0007, loc, "global variable list too large (above 256 MiB)");
            listSize = 0;
        }
    }
    if (block.constant && decl.init) foldConstant(*v, decl);
    VarSym* raw = v.get();
    raw->listName = declaringList_;
    if (!declaringList_.empty()) listGlobals_[upper(declaringList_) + "." + key] = raw;
    if (other) {
        other->sharedName = raw->sharedName = true;  // unqualified use: an error naming both lists
    } else if (!hiddenBesideOther) {
        globals_[key] = raw;
    }
    // The library's own lists (GVL_Param_TcUnit) are not the project's state:
    // they stay out of --dump, --vcd and the names --set can write; except a
    // simulation's controls, named strun_* (Tc2_EtherCAT's bus, decision 0220).
    if (!libraryFiles_.count(loc.file) || key.rfind("STRUN_", 0) == 0) model_.globals.push_back(raw);
    model_.globalStore.push_back(std::move(v));
    return raw;
}

void Checker::declareGlobals() {
    // Each global list (a VAR_GLOBAL file, a configuration, a resource) owns
    // one block of storage; its variables sit at fixed offsets in it.
    auto declareBlocks = [&](const std::vector<ast::VarBlock>& blocks) {
        uint32_t size = 0;
        std::vector<VarSym*> placed;
        for (const auto& block : blocks) {
            if (block.section != ast::VarSection::Global) continue;
            for (const auto& decl : block.vars)
                for (size_t n = 0; n < decl.names.size(); ++n)
                    if (VarSym* v = addGlobal(decl, n, block, size); v && !v->abs) placed.push_back(v);
        }
        if (placed.empty()) return;
        uint8_t* storage = model_.allocate(size);
        // Every address first: an initialiser may name a later global of the list.
        for (VarSym* v : placed) {
            v->abs = storage + v->offset;
            v->offset = 0;  // an Abs variable's address is `abs` itself
        }
        for (VarSym* v : placed) {
            writeDefault(v->abs, v->type);
            if (isAddressInit(v)) { globalAddressInits_.push_back({v, nullptr, v->decl->init->expr.get()}); continue; }
            writeVarInitial(v->abs, v, &globalAddressInits_);
        }
    };
    // A list of the project named like one of strun's library lists (TcUnit's
    // own source declares GVL_Param_TcUnit) replaces it, as a user type does.
    std::set<std::string> projectLists;
    for (auto* list : globalLists_)
        if (!list->nameSpace.empty() && !libraryFiles_.count(list->loc.file)) projectLists.insert(upper(list->nameSpace));
    for (auto* list : globalLists_) {
        if (libraryFiles_.count(list->loc.file) && projectLists.count(upper(list->nameSpace))) continue;
        qualifiedOnlyList_ = hasAttribute(list->pragmas, "qualified_only") ? list->nameSpace : "";
        declaringList_ = list->nameSpace;
        NameScopeGuard scope(*this, list->nameSpace, list->loc.file);
        declareBlocks(list->blocks);
        qualifiedOnlyList_.clear();
        declaringList_.clear();
    }
    for (auto* conf : configurations_) {
        declareBlocks(conf->globals);
        for (auto& res : conf->resources) declareBlocks(res.globals);
    }
    globalsDeclared_ = true;
}

// ---------------------------------------------------------------- initial values

void Checker::writeDefault(uint8_t* p, const Type* t) {
    if (!t) return;
    if (!t->defaultImage.empty()) {
        std::memcpy(p, t->defaultImage.data(), std::min<size_t>(t->defaultImage.size(), t->size));
        return;
    }
    if (t->kind == TK::Array && t->elem && !t->elem->defaultImage.empty()) {
        for (uint64_t k = 0; k < t->elemCount; ++k) writeDefault(p + k * t->elem->size, t->elem);
    }
}

void Checker::writeScalar(uint8_t* p, const Type* t, const Checked& v) {
    const Type* st = t->kind == TK::Enum ? t->base : t;
    switch (st->kind) {
        case TK::Real: { float f = static_cast<float>(v.constReal); std::memcpy(p, &f, 4); return; }
        case TK::LReal: std::memcpy(p, &v.constReal, 8); return;
        default: break;
    }
    int64_t iv = v.constInt;
    switch (st->size) {
        case 1: { uint8_t b = static_cast<uint8_t>(st->kind == TK::Bool ? (iv != 0) : iv); std::memcpy(p, &b, 1); break; }
        case 2: { uint16_t w = static_cast<uint16_t>(iv); std::memcpy(p, &w, 2); break; }
        case 4: { uint32_t d = static_cast<uint32_t>(iv); std::memcpy(p, &d, 4); break; }
        default: std::memcpy(p, &iv, 8); break;
    }
}

// `r : REF_TO INT := REF(counter)`, `p : POINTER TO INT := ADR(x)`: an address
// is only known per instance, so the initialiser runs once before the first cycle.
bool Checker::isAddressInit(const VarSym* v) const {
    if (!v->decl || !v->decl->init || v->decl->init->kind != ast::InitKind::Expr || !v->decl->init->expr) return false;
    if (v->type->kind != TK::Pointer && v->type->kind != TK::Reference) return false;
    return v->decl->init->expr->kind != ast::ExprKind::Literal && !(v->decl->init->expr->kind == ast::ExprKind::Name &&
                                                                     upper(v->decl->init->expr->name) == "NULL");
}

// A variable AT a direct address starts with its initial value in the
// process image, as in CODESYS (`a AT %MW0 : WORD := 400;`). A BOOL at a bit
// address (%QX0.1) sets or clears only its own bit of the byte.
void Checker::writeLocatedInitial(const VarSym& v, const ast::Init* init, const ast::Loc& loc) {
    if (v.bit < 0) {
        writeInitial(v.abs, v.type, init, loc);
        return;
    }
    uint8_t value = 0;
    writeInitial(&value, v.type, init, loc);
    if (value) *v.abs |= uint8_t(1u << v.bit);
    else *v.abs &= uint8_t(~(1u << v.bit));
}

void Checker::writeInitial(uint8_t* p, const Type* t, const ast::Init* init, const ast::Loc& loc) {
    if (!t || !init) return;
    switch (init->kind) {
        case ast::InitKind::Expr: {
            if (!init->expr) return;
            const size_t messagesBefore = log_.messages().size();
            Checked c = checkExpr(*init->expr);
            if (!c.ok) return;
            // Not known at compile time: an assignment at initialisation, when this
            // variable may have one (its warnings come when that is checked).
            auto deferred = [&] {
                if (!deferInitial(*init->expr)) return false;
                log_.dropFrom(messagesBefore);
                return true;
            };
            if (t->kind == TK::Enum && c.type && c.type->kind == TK::Enum && c.type != t) {
                error(diag::E0201, init->loc, fmt::format("initial value of type {} for a variable of type {}", typeName(c.type), typeName(t)));
                return;
            }
            c = coerce(c, t, init->expr->loc, "initial value");
            if (!c.ok) return;
            if (isIntRep(t) || isRealRep(t)) {
                if (!c.isConst) {
                    if (deferred()) return;
                    error(diag::E0401, init->expr->loc, "an initial value must be a constant expression");
                    return;
                }
                writeScalar(p, t, c);
            } else if (isStringType(t->kind)) {
                auto* bytes = exec::nodeCast<exec::ConstBytes>(c.node);
                if (!bytes) {
                    if (!deferred()) error(diag::E0401, init->expr->loc, "an initial value must be a constant expression");
                    return;
                }
                size_t n = std::min<size_t>(bytes->bytes.size(), t->size);
                std::memcpy(p, bytes->bytes.data(), n);
                p[t->size - 1] = 0;
                if (t->kind == TK::WString) p[t->size - 2] = 0;
            } else if ((t->kind == TK::Interface || t->kind == TK::Pointer) && c.isConst && c.constInt == 0) {
                // `ipSourceInfo : I_TcSourceInfo := 0` (Beckhoff's declarations),
                // `value : PVOID := 0` (LCLS's T_HashTableEntry; decision 0439):
                // no instance, no address, the storage's zero.
            } else if (const VarSym* named = c.var; named && named->constant && named->abs && isAggregate(t) && sameType(named->type, t)) {
                // A structured CONSTANT named whole (`astAttenuators := [N(stAttenuators)]`
                // in LCLS's PMPS_GVL CONSTANT list): its image, written when it was
                // declared, is its value for good (decision 0462).
                std::memcpy(p, named->abs, t->size);
            } else if (auto* image = exec::nodeCast<exec::ConstBytes>(c.node);
                       image && c.isConst && t->kind == TK::Struct && sameType(c.type, t) && image->bytes.size() == t->size) {
                std::memcpy(p, image->bytes.data(), t->size);  // the same, named in a TYPE (earlyStructureConstant)
            } else if (!deferred()) {
                error(diag::E0401, init->expr->loc, fmt::format("a value of type {} cannot be initialised with an expression", typeName(t)));
            }
            return;
        }
        case ast::InitKind::Array: {
            if (t->kind != TK::Array || t->flexible) {
                error(diag::E0402, init->loc, fmt::format("an array initialiser for a variable of type {}", typeName(t)));
                return;
            }
            uint64_t k = 0;
            for (const auto& item : init->items) {
                int64_t repeat = 1;
                const ast::Init* value = item.value.get();
                if (item.callForm && !isConstantInteger(*item.repeat)) value = item.callForm.get();  // `[F(x)]`: a call
                else if (item.repeat && !constIntExpr(item.repeat.get(), repeat, "a repetition count")) repeat = 1;
                if (repeat <= 0) continue;
                if (static_cast<uint64_t>(repeat) > t->elemCount - k) {
                    error(diag::E0402, init->loc, fmt::format("too many initial values for {} elements", t->elemCount));
                    return;
                }
                // `N(x)`: x is checked and written once, then its bytes copied
                // (an initialiser of 50 million elements makes no nodes per element).
                uint8_t* first = p + k * t->elem->size;
                if (value) {
                    initPath_.push_back({"", t, k});
                    const size_t runtimeBefore = runtimeInits_ ? runtimeInits_->size() : 0;
                    writeInitial(first, t->elem, value, loc);
                    for (int64_t r = 1; r < repeat; ++r) std::memcpy(first + uint64_t(r) * t->elem->size, first, t->elem->size);
                    // `N(x)` with x known only at run time: one assignment per element.
                    if (runtimeInits_ && runtimeInits_->size() > runtimeBefore)
                        for (int64_t r = 1; r < repeat; ++r) {
                            initPath_.back().element = k + static_cast<uint64_t>(r);
                            writeInitial(first + uint64_t(r) * t->elem->size, t->elem, value, loc);
                        }
                    initPath_.pop_back();
                }
                k += static_cast<uint64_t>(repeat);
            }
            return;
        }
        case ast::InitKind::Struct: {
            if (t->kind != TK::Struct && t->kind != TK::FunctionBlock) {
                error(diag::E0402, init->loc, fmt::format("a structure initialiser for a variable of type {}", typeName(t)));
                return;
            }
            for (const auto& f : init->fields) {
                const Field* fld = t->findField(upper(f.name));
                if (!fld && t->kind == TK::FunctionBlock && t->pou && f.value && f.value->kind == ast::InitKind::Expr &&
                    f.value->expr && findMethod(t->pou, "__SET_" + upper(f.name))) {
                    // `fbBrake : FB_Brake := (BrakeMode := ...)`: a property given a value in the
                    // declaration, set through its setter before the first cycle (decision 0335).
                    initPath_.push_back({f.name, nullptr, 0});
                    if (!deferInitial(*f.value->expr))
                        error(diag::E0402, f.loc, fmt::format("property '{}' cannot be set in this declaration: only a variable's "
                                                             "initialiser sets a property, before the first cycle", f.name));
                    initPath_.pop_back();
                    continue;
                }
                if (!fld && t->kind == TK::FunctionBlock && t->pou && findMethod(t->pou, "__GET_" + upper(f.name))) {
                    error(diag::E0103, f.loc, fmt::format("property '{}' of {} has no SET: it cannot be given a value", f.name, typeName(t)));
                    continue;
                }
                if (!fld) {
                    error(diag::E0103, f.loc, fmt::format("'{}' has no member '{}'", typeName(t), f.name));
                    continue;
                }
                const Type* ft = fld->type;
                if (ft->kind == TK::Reference && t->kind == TK::FunctionBlock) continue;
                initPath_.push_back({f.name, nullptr, 0});
                writeInitial(p + fld->offset, ft, f.value.get(), f.loc);
                initPath_.pop_back();
            }
            return;
        }
    }
}

uint8_t* Checker::mapAddress(const std::string& address, const Type* t, const ast::Loc& loc, int& bit) {
    // %<area><size><index>[.<bit>] — CODESYS addressing (see runtime/machine.h).
    std::string a = upper(address);
    bit = -1;
    auto fail = [&](const std::string& why) -> uint8_t* {
        error(diag::E0408, loc, fmt::format("bad direct address '{}': {}", address, why));
        return nullptr;
    };
    if (a.size() < 3 || a[0] != '%') return fail("expected %I, %Q or %M");
    if (a[1] == 'S') return mapSystemAddress(address, t, loc, bit);
    rt::ImageArea* area = nullptr;
    switch (a[1]) {
        case 'I': area = &model_.machine.image.inputs; break;
        case 'Q': area = &model_.machine.image.outputs; break;
        case 'M': area = &model_.machine.image.memory; break;
        default: return fail("expected %I, %Q or %M");
    }
    size_t pos = 2;
    char size = 'X';
    if (pos < a.size() && std::isalpha(static_cast<unsigned char>(a[pos]))) size = a[pos++];
    uint64_t unit = 0;
    switch (size) {
        case 'X': unit = 0; break;
        case 'B': unit = 1; break;
        case 'W': unit = 2; break;
        case 'D': unit = 4; break;
        case 'L': unit = 8; break;
        default: return fail("size must be X, B, W, D or L");
    }
    std::vector<uint64_t> parts;
    uint64_t cur = 0;
    bool any = false;
    for (; pos < a.size(); ++pos) {
        char ch = a[pos];
        if (ch >= '0' && ch <= '9') {
            cur = cur * 10 + static_cast<uint64_t>(ch - '0');
            any = true;
            if (cur > rt::ProcessImage::kSize * 8) return fail("address outside the process image");
        } else if (ch == '.' && any) {
            parts.push_back(cur);
            cur = 0;
            any = false;
        } else {
            return fail("malformed");
        }
    }
    if (!any) return fail("malformed");
    parts.push_back(cur);
    if (parts.size() > (unit == 0 ? 2u : 1u)) return mapHierarchicalAddress(*area, address, parts, unit, t, loc, bit);  // decision 0390
    uint64_t byte = 0;
    if (unit == 0) {
        if (parts.size() == 1) { byte = parts[0] / 8; bit = static_cast<int>(parts[0] % 8); }
        else { byte = parts[parts.size() - 2]; bit = static_cast<int>(parts.back()); }
        if (bit > 7) return fail("bit number above 7");
        // matiec/Beremiz: a structure located at `%I3.0` (no size prefix) is
        // the structure from byte 3 on, which an extension fills (decision 0465).
        if (t->kind == TK::Struct && bit == 0 && parts.size() == 2) {
            // With --strict an error, but the variable keeps its place: no follow-on message at its uses.
            refusedByStrict(diag::E0408, loc,
                            fmt::format("bad direct address '{}': a structure needs a byte address ('%{}B{}'), not a bit address", address, a[1], byte));
            bit = -1;
        } else if (t->kind != TK::Bool) {
            return fail("a bit address needs a BOOL variable");
        }
    } else {
        if (parts.size() != 1) {
            // %MW1.3: a bit of a word is not a storage location of its own.
            return fail("a bit number only goes with X addresses");
        }
        byte = parts[0] * unit;
        if (t->size > unit && t->kind != TK::Array && t->kind != TK::Struct && !isStringType(t->kind))
            log_.warning(diag::W0008, loc, fmt::format("{} is larger than the {}-byte address '{}'", typeName(t), unit, address));
    }
    uint64_t end = byte + std::max<uint64_t>(t->size, 1);
    if (end > area->size() - hierarchicalUsed_[area]) {
        return fail(hierarchicalUsed_[area] ? "address inside the part of the image the hierarchical addresses use" : "address outside the process image");
    }
    flatEnd_[area] = std::max<size_t>(flatEnd_[area], end);
    // Tasks copy only the addressed part of %I / %Q at their start and end.
    auto& image = model_.machine.image;
    if (area == &image.inputs) image.inputExtent = std::max<size_t>(image.inputExtent, end);
    if (area == &image.outputs) image.outputExtent = std::max<size_t>(image.outputExtent, end);
    return area->data() + byte;
}

}  // namespace strun::sema

namespace strun::sema {

// %Sn (system bit n) and %SWn / %SWn.b (system word n, bit b of it): only on
// a target that has system variables (M340); the layout is runtime/machine.h's.
uint8_t* Checker::mapSystemAddress(const std::string& address, const Type* t, const ast::Loc& loc, int& bit) {
    auto fail = [&](const std::string& why) -> uint8_t* {
        error(diag::E0408, loc, fmt::format("bad system address '{}': {}", address, why));
        return nullptr;
    };
    if (profile().systemVariables == rt::SystemVariables::None) {
        const rt::PlcProfile* owner = rt::profileWithSystemVariables();
        error(diag::E0602, loc, fmt::format("system variable '{}' exists only with --target {} ({}); the target is {}", address,
                               owner ? owner->id : "m340", owner ? owner->description : "Modicon M340", profile().id));
        return nullptr;
    }
    std::string a = upper(address);
    bool isWord = a.size() > 2 && a[2] == 'W';
    if (a.size() > 2 && std::isalpha(static_cast<unsigned char>(a[2])) && !isWord)
        return fail("system variables are bits %Sn and words %SWn");
    std::vector<uint64_t> parts;
    uint64_t cur = 0;
    bool any = false;
    for (size_t pos = isWord ? 3 : 2; pos < a.size(); ++pos) {
        char ch = a[pos];
        if (ch >= '0' && ch <= '9') {
            cur = cur * 10 + static_cast<uint64_t>(ch - '0');
            any = true;
            if (cur > 100000) return fail("number too large");
        } else if (ch == '.' && any && parts.empty()) {
            parts.push_back(cur);
            cur = 0;
            any = false;
        } else {
            return fail("malformed");
        }
    }
    if (!any) return fail("malformed");
    parts.push_back(cur);
    auto& image = model_.machine.image;
    bit = -1;
    uint64_t number = parts[0];
    bool emulated = false;
    uint8_t* where = nullptr;
    if (!isWord) {
        if (parts.size() != 1) return fail("a system bit has no bit number");
        if (number >= rt::ProcessImage::kSystemBits)
            return fail(fmt::format("system bits are %S0..%S{}", rt::ProcessImage::kSystemBits - 1));
        if (t->kind != TK::Bool) return fail("a system bit needs a BOOL variable");
        emulated = number == 11 || number == 19 || (number >= 30 && number <= 35);
        bit = static_cast<int>(number % 8);
        where = image.systemBits.data() + number / 8;
    } else {
        if (number >= rt::ProcessImage::kSystemWords)
            return fail(fmt::format("system words are %SW0..%SW{}", rt::ProcessImage::kSystemWords - 1));
        emulated = number <= 5 || number == 8 || number == 9 || number == 11 || (number >= 30 && number <= 47);
        if (parts.size() == 2) {
            if (parts[1] > 15) return fail("bit number above 15");
            if (t->kind != TK::Bool) return fail("a bit of a system word needs a BOOL variable");
            bit = static_cast<int>(parts[1] % 8);
            where = image.systemWords.data() + number * 2 + parts[1] / 8;
        } else {
            if (t->size > 2 && t->kind != TK::Array && t->kind != TK::Struct)
                return fail(fmt::format("{} is larger than the 2-byte system word", typeName(t)));
            if (number * 2 + std::max<uint64_t>(t->size, 1) > image.systemWords.size())
                return fail("outside the system words");
            where = image.systemWords.data() + number * 2;
        }
    }
    if (!emulated)
        log_.warning(diag::W0009, loc, fmt::format("'{}' is not maintained by strun on {}: it reads 0 unless the program writes it",
                                      address, profile().description));
    return where;
}

}  // namespace strun::sema
