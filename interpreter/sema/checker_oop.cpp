// Object orientation (IEC 61131-3 3rd edition, CODESYS): methods with
// dynamic dispatch, THIS / SUPER, properties, interfaces, pointers and
// references.
#include <cstring>

#include <fmt/format.h>

#include "interpreter/sema/checker.h"
#include "interpreter/sema/node_factory.h"

namespace strun::sema {

int Checker::methodSlot(const std::string& key) {
    auto it = methodSlots_.find(key);
    if (it != methodSlots_.end()) return it->second;
    int slot = static_cast<int>(methodSlots_.size());
    methodSlots_[key] = slot;
    return slot;
}

PouInfo* Checker::findMethod(PouInfo* owner, const std::string& key) {
    for (PouInfo* p = owner; p; p = p->parent) {
        auto it = p->methods.find(key);
        if (it != p->methods.end()) return it->second;
    }
    if (owner && owner->kind == ast::PouKind::Interface) {
        std::vector<PouInfo*> all;
        collectInterfaces(owner, all);
        for (PouInfo* i : all) {
            auto it = i->methods.find(key);
            if (it != i->methods.end()) return it->second;
        }
    }
    return nullptr;
}

void Checker::collectInterfaces(PouInfo* itf, std::vector<PouInfo*>& out) {
    if (std::find(out.begin(), out.end(), itf) != out.end()) return;
    out.push_back(itf);
    NameScopeGuard scope(*this, itf->ast->nameSpace, itf->ast->loc.file);
    std::vector<std::string> bases = itf->ast->extendsList;
    if (bases.empty() && !itf->ast->extends.empty()) bases.push_back(itf->ast->extends);
    for (const auto& b : bases) {
        PouInfo* base = pouNamed(b);  // also `EXTENDS __SYSTEM.IQueryInterface`
        if (!base || base->kind != ast::PouKind::Interface) {
            error(diag::E0405, itf->ast->loc, fmt::format("'{}' is not an interface", b));
            continue;
        }
        collectInterfaces(base, out);
    }
}

namespace {
bool sameSignature(const PouInfo* a, const PouInfo* b) {
    if (!sameType(a->resultType, b->resultType) && (a->resultType || b->resultType)) return false;
    if (a->params.size() != b->params.size()) return false;
    for (size_t k = 0; k < a->params.size(); ++k) {
        const VarSym* x = a->params[k];
        const VarSym* y = b->params[k];
        if (x->section != y->section || !sameType(x->type, y->type) || x->offset != y->offset) return false;
    }
    return true;
}

// A derived block's FB_init repeats its base's inputs and may add more
// (Beckhoff, "Behavior with derived function blocks"; decision 0461).
bool extendsFbInitSignature(const PouInfo* base, const PouInfo* derived) {
    if (!sameType(base->resultType, derived->resultType) && (base->resultType || derived->resultType)) return false;
    if (derived->params.size() < base->params.size()) return false;
    for (size_t k = 0; k < base->params.size(); ++k) {
        const VarSym* x = base->params[k];
        const VarSym* y = derived->params[k];
        if (x->section != y->section || !sameType(x->type, y->type) || upper(x->name) != upper(y->name)) return false;
    }
    return true;
}
}  // namespace

void Checker::buildClasses() {
    const size_t slots = methodSlots_.size();
    std::set<PouInfo*> done;
    std::function<void(PouInfo*)> build = [&](PouInfo* fb) {
        if (done.count(fb) || !fb->classDesc) return;
        done.insert(fb);
        NameScopeGuard scope(*this, fb->ast->nameSpace, fb->ast->loc.file);
        exec::ClassDesc& d = *fb->classDesc;
        d.methods.assign(slots, nullptr);
        d.body = fb->code;
        if (fb->parent) {
            build(fb->parent);
            if (fb->parent->classDesc) d.methods = fb->parent->classDesc->methods;
            fb->interfaces = fb->parent->interfaces;
            if (fb->parent->ast->final) error(diag::E0405, fb->ast->loc, fmt::format("'{}' cannot extend the FINAL '{}'", fb->name, fb->parent->name));
        }
        for (auto& [key, m] : fb->methods) {
            if (m->slot < 0) continue;
            if (m->ast && m->ast->override && !(fb->parent && findMethod(fb->parent, key)))
                error(diag::E0405, m->ast->nameLoc.line ? m->ast->nameLoc : m->ast->loc,
                      fmt::format("method '{}' is marked OVERRIDE but '{}' has no base with a method '{}'", m->name,
                                  fb->name, m->name));
            if (fb->parent) {
                PouInfo* base = findMethod(fb->parent, key);
                if (base && base->ast && base->ast->final)
                    error(diag::E0405, m->ast->loc, fmt::format("method '{}' is FINAL in '{}'", m->name, fb->parent->name));
                if (base && !sameSignature(base, m) && !(key == "FB_INIT" && extendsFbInitSignature(base, m)))
                    error(diag::E0405, m->ast->nameLoc.line ? m->ast->nameLoc : m->ast->loc,
                          fmt::format("'{}' overrides '{}.{}' with a different signature", m->name, fb->parent->name, m->name));
            }
            if (m->ast && (m->ast->hasBody || !m->ast->body.empty() || !m->ast->abstract)) d.methods[static_cast<size_t>(m->slot)] = m->code;
            else d.methods[static_cast<size_t>(m->slot)] = nullptr;
        }
        for (const auto& name : fb->ast->implements) {
            PouInfo* itf = pouNamed(name);  // also `IMPLEMENTS __SYSTEM.IQueryInterface`
            if (!itf && !typeDecls_.count(scopedKey(upper(name)))) {
                // Declared nowhere (a library strun lacks: its name is answered, decision 0370).
                suggest(error(diag::E0102, fb->ast->loc, fmt::format("unknown interface '{}' in IMPLEMENTS", name)), name, &Checker::typeNames);
                continue;
            }
            if (!itf || itf->kind != ast::PouKind::Interface) {
                error(diag::E0405, fb->ast->loc, fmt::format("'{}' in IMPLEMENTS is not an interface", name));
                continue;
            }
            collectInterfaces(itf, fb->interfaces);
        }
        // The class and its bases answer a type test too: `ref ?= itf` into a
        // REF_TO a class (IEC Ed.3, SIMATIC AX; decision 0366).
        for (PouInfo* b = fb; b; b = b->parent)
            if (std::find(d.interfaces.begin(), d.interfaces.end(), b) == d.interfaces.end()) d.interfaces.push_back(b);
        for (PouInfo* itf : fb->interfaces) {
            if (std::find(d.interfaces.begin(), d.interfaces.end(), itf) == d.interfaces.end()) d.interfaces.push_back(itf);
            if (fb->ast->abstract) continue;
            for (auto& [key, im] : itf->methods) {
                PouInfo* impl = findMethod(fb, key);
                if (!impl && im->property) continue;  // an accessor left out faults when called (NULL_POINTER)
                if (!impl) {
                    error(diag::E0405, fb->ast->nameLoc.line ? fb->ast->nameLoc : fb->ast->loc,
                          fmt::format("'{}' does not implement '{}.{}'", fb->name, itf->name, im->property ? im->property->name : im->name));
                } else {
                    layoutPou(im);
                    if (!sameSignature(im, impl))
                        error(diag::E0405, impl->ast->loc, fmt::format("'{}.{}' does not match the signature in '{}'", fb->name, impl->name, itf->name));
                }
            }
        }
        if (!fb->ast->abstract) {
            // A concrete block implements every ABSTRACT method it inherits.
            for (PouInfo* p = fb->parent; p; p = p->parent)
                for (auto& [key, m] : p->methods) {
                    if (!m->ast || !m->ast->abstract || m->slot < 0) continue;
                    PouInfo* impl = findMethod(fb, key);
                    if (!impl || !impl->ast || impl->ast->abstract)
                        error(diag::E0405, fb->ast->nameLoc.line ? fb->ast->nameLoc : fb->ast->loc,
                              fmt::format("'{}' must implement the ABSTRACT method '{}' of '{}'", fb->name, m->name, p->name));
                }
        }
    };
    // By index: a layout may append a generic block's specialisation to pouOrder_.
    for (size_t i = 0; i < pouOrder_.size(); ++i)
        if (pouOrder_[i]->kind == ast::PouKind::FunctionBlock) build(pouOrder_[i]);
    for (size_t i = 0; i < pouOrder_.size(); ++i)
        if (pouOrder_[i]->kind == ast::PouKind::Interface)
            for (auto& [key, m] : pouOrder_[i]->methods) layoutPou(m);
}

// A call of `method` on `base` (an FB instance place, an interface value, SUPER^).
Checked Checker::methodCall(Checked base, PouInfo* method, const ast::Expr& call) {
    exec::Expr* instance = base.node;
    bool viaInterface = base.type->kind == TK::Interface;
    if (viaInterface) instance = pool().make<exec::AddressValuePlace>(base.node);
    if (method->ast && method->ast->access == ast::Access::Private && !insideOwnInstance(method->owner))
        error(diag::E0109, call.kids[0]->nameLoc.line ? call.kids[0]->nameLoc : call.loc, fmt::format("method '{}' is PRIVATE", method->name));
    Checked r = callUserFunction(method, call, instance);
    if (!r.ok) return r;
    auto* node = static_cast<exec::CallPou*>(r.node);
    const bool isProgram = method->owner && method->owner->kind == ast::PouKind::Program;
    if (!base.superRef && !isProgram) node->virtualSlot = method->slot;
    // On a plain variable of a block nothing EXTENDS, the method the call
    // dispatches to is known: it may be inlined (decision 0317).
    if (!viaInterface && !base.superRef && base.var && !base.var->byRef && base.var->type == base.type && base.type->pou &&
        !isExtended(base.type->pou))
        noteInlineSite(node, method, true, call);
    if (!viaInterface && !isProgram && method->ast && method->ast->abstract && base.superRef)
        error(diag::E0405, call.loc, fmt::format("'{}' is ABSTRACT in the parent", method->name));
    return r;
}

Checked Checker::checkThis(const ast::Expr& e, bool deref) {
    PouInfo* fb = pou_ && pou_->owner ? pou_->owner : pou_;
    if (!fb || (fb->kind != ast::PouKind::FunctionBlock && fb->kind != ast::PouKind::Program)) {
        error(diag::E0109, e.loc, fmt::format("{} is only available inside a function block", e.kind == ast::ExprKind::Super ? "SUPER" : "THIS"));
        return bad(e.loc);
    }
    const Type* t = fb->instanceType;
    bool super = e.kind == ast::ExprKind::Super;
    if (super) {
        if (!fb->parent) {
            error(diag::E0405, e.loc, fmt::format("'{}' has no parent: SUPER needs EXTENDS", fb->name));
            return bad(e.loc);
        }
        t = fb->parent->instanceType;
    }
    Checked c;
    c.ok = true;
    c.loc = e.loc;
    if (!deref) {
        c.type = types().pointer(t);
        c.node = pool().make<exec::SelfAddress>();
        c.node->type = c.type;
        return c;
    }
    c.type = t;
    c.isPlace = true;
    c.superRef = super;
    c.direct = Checked::Direct::Self;
    c.directOffset = 0;
    c.node = pool().make<exec::SelfVar<void>>(0);
    c.node->type = t;
    return c;
}

Checked Checker::propertyAccess(Checked base, const std::string& key, const ast::Loc& loc, bool& found) {
    found = false;
    PouInfo* owner = base.type->kind == TK::Interface || base.type->kind == TK::FunctionBlock ? base.type->pou : nullptr;
    if (!owner) return bad(loc);
    PouInfo* getter = findMethod(owner, "__GET_" + key);
    PouInfo* setter = findMethod(owner, "__SET_" + key);
    if (!getter && !setter) return bad(loc);
    found = true;
    // A PRIVATE property is checked as a PRIVATE method is (decision 0430).
    if (const PouInfo* accessor = getter ? getter : setter;
        accessor->property && accessor->property->access == ast::Access::Private && !insideOwnInstance(accessor->owner))
        error(diag::E0109, loc, fmt::format("property '{}' is PRIVATE", accessor->property->name));
    exec::Expr* instance = base.node;
    bool viaInterface = base.type->kind == TK::Interface;
    if (viaInterface) instance = pool().make<exec::AddressValuePlace>(base.node);
    Checked c;
    c.ok = true;
    c.loc = loc;
    c.propertySetter = setter;
    c.propertyInstance = instance;
    c.propertyName = (getter ? getter : setter)->name.substr(6);  // "__GET_Speed" -> "Speed"
    c.superRef = base.superRef;
    if (getter) {
        layoutPou(getter);
        if (!getter->resultType) return bad(loc);  // the property's type did not resolve (reported there)
        ++userCallsMade_;
        auto* call = pool().make<exec::CallPou>();
        call->callee = getter->code;
        call->instance = instance;
        call->site = site(loc);
        call->rep = resultRepOf(getter->resultType);
        if (!base.superRef && owner->kind != ast::PouKind::Program) call->virtualSlot = getter->slot;
        if (getter->resultType && isAggregate(getter->resultType)) {
            call->resultSize = getter->resultType->size;
            call->tempOffset = allocTemp(getter->resultType->size);
        }
        c.type = getter->resultType;
        call->type = c.type;
        c.node = call;
        c.hasCall = true;
        if (c.type->kind == TK::Reference && !suppressAutoDeref_) {
            // A REFERENCE TO T property reads as the T it refers to, a place that
            // `fb.Output.bDone := TRUE` writes through; assigning the property
            // itself still calls SET (decision 0443). REF= on it keeps the reference.
            Checked d = derefReference(c);
            d.propertySetter = c.propertySetter;
            d.propertyInstance = c.propertyInstance;
            d.propertyName = c.propertyName;
            d.superRef = c.superRef;
            c = d;
        }
    } else {
        layoutPou(setter);
        if (setter->params.empty()) return bad(loc);  // the property's type did not resolve (reported there)
        c.type = setter->params.front()->type;
        c.node = pool().make<exec::ConstInt>(0);
        c.node->type = c.type;
        c.readOnly = false;
        c.writeOnlyProperty = true;
    }
    return c;
}

// Inside a block (its body, methods, actions, other properties' accessors) its
// own properties are named without THIS^, as its variables are: `x := x + d;`
// calls GET and SET (TwinCAT, CODESYS; decision 0440). Inside a property's own
// accessors the name is the result / the new value, a variable found first.
bool Checker::hasOwnProperty(const std::string& key) {
    PouInfo* fb = pou_ && pou_->owner ? pou_->owner : pou_;
    if (!fb || (fb->kind != ast::PouKind::FunctionBlock && fb->kind != ast::PouKind::Program)) return false;
    return findMethod(fb, "__GET_" + key) || findMethod(fb, "__SET_" + key);
}

Checked Checker::ownProperty(const std::string& key, const ast::Loc& loc, bool& found) {
    found = false;
    if (!hasOwnProperty(key)) return bad(loc);
    ast::Expr thisExpr;
    thisExpr.kind = ast::ExprKind::This;
    thisExpr.loc = loc;
    return propertyAccess(checkThis(thisExpr, true), key, loc, found);
}

exec::Stmt* Checker::assignProperty(Checked target, Checked value, const ast::Loc& loc) {
    PouInfo* setter = target.propertySetter;
    if (!setter) {
        error(diag::E0405, loc, fmt::format("the property '{}' has no SET accessor (it can be read, not assigned)", target.propertyName));
        return nullptr;
    }
    layoutPou(setter);
    if (setter->params.empty()) return nullptr;
    VarSym* p = setter->params.front();
    exec::Expr* place = makeByRep<exec::PendingVar>(pool(), isAggregate(p->type) ? Rep::Void : repOf(p->type), p->offset);
    exec::Stmt* bind = nullptr;
    if (p->type->kind == TK::Reference) {
        // A REFERENCE TO T property, set with := or REF=: SET receives a
        // reference to the value, as a REFERENCE input does (decision 0443).
        bind = bindReference(p, value, place, value.loc);
    } else {
        Checked v = coerce(value, p->type, value.loc, "property value");
        if (v.ok) bind = storeTo(place, p->type, v.node);
    }
    if (!bind) return nullptr;
    ++userCallsMade_;
    auto* call = pool().make<exec::CallPou>();
    call->callee = setter->code;
    call->instance = target.propertyInstance;
    call->site = site(loc);
    call->rep = exec::ResultRep::None;
    if (!target.superRef && !(setter->owner && setter->owner->kind == ast::PouKind::Program)) call->virtualSlot = setter->slot;
    call->inputs.push_back(bind);
    call->type = types().voidType();
    return pool().make<exec::EvalStmt>(call, exec::EvalStmt::Rep::Int);
}

// REFERENCE TO x values are used as the x they refer to.
Checked Checker::autoDeref(Checked c) {
    if (suppressAutoDeref_) return c;
    return derefReference(std::move(c));
}

// The x a REFERENCE TO x value refers to, as a place (a NULL reference faults).
Checked Checker::derefReference(Checked c) {
    if (!c.ok || c.type->kind != TK::Reference) return c;
    const Type* target = c.type->target;
    Checked d;
    d.ok = true;
    d.loc = c.loc;
    d.type = target;
    d.isPlace = true;
    d.hasCall = c.hasCall;
    d.readOnly = c.readOnly;
    d.readOnlyWhy = c.readOnlyWhy;
    d.node = loadFrom(pool().make<exec::DerefPlace>(c.node, site(c.loc), target->size), target);
    d.node->type = target;
    return d;
}

Checked Checker::addressOf(const ast::Expr& e, const char* fn) {
    // REF(THIS) / ADR(THIS) (SIMATIC AX): the instance's own address, which THIS already is (decision 0316).
    if (e.kind == ast::ExprKind::This) return checkThis(e, false);
    bool saved = suppressAutoDeref_;
    const bool savedOperand = addressOperand_;
    addressOperand_ = true;
    Checked v = checkExpr(e);
    addressOperand_ = savedOperand;
    suppressAutoDeref_ = saved;
    if (!v.ok) return v;
    if (!v.isPlace || v.node->bitIndex() >= 0) {
        error(diag::E0206, e.loc, fmt::format("{} needs a variable", fn));
        return bad(e.loc);
    }
    // OSCAT writes a function's result through a pointer (pt := ADR(BYTE_TO_STRB)).
    if (v.var && pou_ && v.var == pou_->result) assignedResult_ = true;
    Checked c;
    c.ok = true;
    c.loc = e.loc;
    c.hasCall = v.hasCall;
    c.type = std::strcmp(fn, "REF") == 0 ? types().refTo(v.type) : types().pointer(v.type);  // as written (decision 0427)
    c.node = pool().make<exec::AddressOf>(v.node);
    c.node->type = c.type;
    c.flexDesc = v.flexDesc;  // REF(arr) of an ARRAY[*]: its bounds come from its descriptor (decision 0402)
    return c;
}

}  // namespace strun::sema
