// CODESYS FB_init: a function block may declare METHOD FB_init
// (bInitRetains, bInCopyCode, further inputs); CODESYS calls it once for every
// instance when the application starts, with the further inputs given on the
// declaration (`ax : Axis(axisId := 3);` or positionally `Axis(3)`). strun
// runs these calls before the first activation of any task, embedded
// instances before the instance that contains them (docs/decisions/0079).
#include <fmt/format.h>

#include "interpreter/ast/ast_clone.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/fb_init_call.h"
#include "interpreter/exec/instance_init_nodes.h"
#include "interpreter/sema/instance_search.h"

namespace strun::sema {

namespace {
constexpr int kMaxFbInitNesting = 64;  // instances inside instances: far beyond real programs
}

// Whether a value of type `t` holds any instance that needs start-up code (an
// FB_init, or REF()/ADR() declaration initialisers): arrays of types without
// any are skipped instead of visited element by element.
bool Checker::holdsFbInit(const Type* t) {
    // Asked for each block of an EXTENDS chain: an FB_init of any of them, or its run-time initialisers.
    return holdsInstanceWhere(t, holdsFbInit_, [](PouInfo* p) {
        return (p->kind == ast::PouKind::FunctionBlock && p->methods.count("FB_INIT")) || !p->addressInits.empty();
    });
}

void Checker::collectFbInits(const Type* t, uint8_t* addr, const ast::TypeSpec* declSpec, int depth, PouInfo* enclosing,
                             uint8_t* enclosingAddr, const ast::Init* declInit) {
    if (!t || depth > kMaxFbInitNesting || !holdsFbInit(t)) return;
    if (t->kind == TK::Array) {
        if (t->elem && (t->elem->kind == TK::FunctionBlock || t->elem->kind == TK::Struct || t->elem->kind == TK::Array))
            collectArrayFbInits(t, addr, declSpec, depth, enclosing, enclosingAddr);
        return;
    }
    if (t->kind == TK::Struct) {
        for (const Type* p = t; p; p = p->parent)
            for (const auto& f : p->fields) collectFbInits(f.type, addr + f.offset, nullptr, depth + 1);
        return;
    }
    if (t->kind != TK::FunctionBlock || !t->pou) return;
    PouInfo* fb = t->pou;
    for (PouInfo* p = fb; p; p = p->parent)
        forEachInstanceVar(p, [&](VarSym* v) {  // the methods' VAR_INST too
            collectFbInits(v->type, addr + v->offset, v->decl ? v->decl->type.get() : nullptr, depth + 1, fb, addr,
                           v->decl ? v->decl->init.get() : nullptr);
        });
    // Run-time initialisers of this instance (its base blocks' first, then its own), before its FB_init.
    std::vector<PouInfo*> chain;
    for (PouInfo* p = fb; p && chain.size() <= static_cast<size_t>(kMaxFbInitNesting); p = p->parent) chain.insert(chain.begin(), p);
    for (PouInfo* p : chain) {
        if (p->addressInits.empty()) continue;
        if (!p->addressInitCode) {
            PouInfo* savedPou = pou_;
            pou_ = p;
            auto* block = pool().make<exec::Block>();
            for (const RuntimeInit& init : p->addressInits)
                if (exec::Stmt* st = addressInitStmt(init)) block->stmts.push_back(st);
            pou_ = savedPou;
            p->addressInitCode = block;
        }
        model_.initCalls.push_back(pool().make<exec::WithSelf>(addr, p->addressInitCode));
    }
    const std::vector<PouInfo*> inits = fb->kind == ast::PouKind::FunctionBlock ? fbInitChain(fb) : std::vector<PouInfo*>{};
    if (inits.empty()) return;
    PouInfo* init = inits.back();  // the declaration's arguments are the most derived FB_init's
    // One resolved call per instance: cap them (docs/limits.md) so that an
    // array of ten million such blocks is an error, not gigabytes and minutes.
    if (model_.initCalls.size() >= kMaxFbInitCalls) {
        if (!fbInitLimitReported_)
            error(diag::E0007, declSpec ? declSpec->loc : init->ast->loc,
                  fmt::format("more than {} instances of function blocks with FB_init (the limit per project)", kMaxFbInitCalls));
        fbInitLimitReported_ = true;
        return;
    }
    ast::Expr call = fbInitCall(*init, declSpec, declSpec ? declSpec->loc : init->ast->loc);
    auto* instance = pool().make<exec::AbsVar<void>>(addr);
    instance->type = t;
    // The arguments on a declaration inside a block or program (reached
    // through its instance by the walk above) may name that instance's
    // variables (TcUnit: `logger : FB_Logger(TestResults);`): they are
    // checked in its scope and run with it as THIS (decision 0313).
    const bool inEnclosing = enclosing && declSpec && (!declSpec->initArgs.empty() || !declSpec->enumValues.empty());
    PouInfo* savedPou = pou_;
    if (inEnclosing) pou_ = enclosing;
    std::vector<exec::Stmt*> runs;
    Checked c = callUserFunction(init, call, instance);
    for (size_t k = 0; c.ok && k + 1 < inits.size(); ++k) {  // the bases' FB_init first (decision 0461)
        ast::Expr baseCall = baseFbInitCall(*inits[k], call);
        Checked b = callUserFunction(inits[k], baseCall, instance);
        if (b.ok) runs.push_back(pool().make<exec::EvalStmt>(b.node, exec::EvalStmt::Rep::Int));
    }
    pou_ = savedPou;
    if (!c.ok) return;
    runs.push_back(pool().make<exec::EvalStmt>(c.node, exec::EvalStmt::Rep::Int));
    const std::vector<const VarSym*> declared = declInit ? membersDeclaredInLiterals(fb, *declInit) : std::vector<const VarSym*>{};
    // FB_init sees the block's own initial values of those members, and the
    // declaration's are assigned after it, as CODESYS documents (attribute
    // call_after_init: `fbDoIt.FB_Init(); fbDoIt.in1 := 99;`; decision 0476).
    for (const VarSym* m : declared)
        if (fb->instanceInit.size() >= m->offset + m->type->size) {
            const uint8_t* own = fb->instanceInit.data() + m->offset;
            model_.initCalls.push_back(pool().make<exec::WriteBytes>(addr + m->offset, std::vector<uint8_t>(own, own + m->type->size)));
        }
    for (exec::Stmt* run : runs) model_.initCalls.push_back(inEnclosing ? pool().make<exec::WithSelf>(enclosingAddr, run) : run);
    for (const VarSym* m : declared) {  // the initial image holds the declared value
        uint8_t* at = addr + m->offset;
        model_.initCalls.push_back(pool().make<exec::WriteBytes>(at, std::vector<uint8_t>(at, at + m->type->size)));
    }
}

// Whether an initial value is written out in literals, enumeration values and
// constants only, so that the instance's initial image holds it.
bool Checker::isLiteralInit(const ast::Init& init) {
    switch (init.kind) {
        case ast::InitKind::Expr: {
            const ast::Expr* e = init.expr.get();
            while (e && e->kind == ast::ExprKind::Unary && !e->kids.empty()) e = e->kids[0].get();
            if (!e) return false;
            if (e->kind == ast::ExprKind::Literal) return true;
            if (e->kind == ast::ExprKind::Name) {  // an enumeration value or a constant
                const VarSym* v = lookupVar(upper(e->name));
                return !v || (v->constant && v->hasConstValue);
            }
            if (e->kind == ast::ExprKind::Member) {  // Enum.Value, Namespace.Enum.Value
                const ast::Expr* root = e;
                while (root->kind == ast::ExprKind::Member && !root->kids.empty()) root = root->kids[0].get();
                return root->kind == ast::ExprKind::Name && !lookupVar(upper(root->name));
            }
            return false;
        }
        case ast::InitKind::Array:
            for (const ast::ArrayInitItem& item : init.items)
                if (item.callForm || (item.value && !isLiteralInit(*item.value))) return false;
            return true;
        case ast::InitKind::Struct:
            for (const ast::StructInitItem& item : init.fields)
                if (item.value && !isLiteralInit(*item.value)) return false;
            return true;
    }
    return false;
}

// The members of `fb` that a declaration's structured initial value
// (`fb : FB(1) := (in1 := 99)`) gives in literals, enumeration values or
// constants: the instance's initial image holds their declared values.
// Struckig's tests give the limits its FB_init defaults to infinity this way.
std::vector<const VarSym*> Checker::membersDeclaredInLiterals(PouInfo* fb, const ast::Init& declInit) {
    std::vector<const VarSym*> members;
    if (declInit.kind != ast::InitKind::Struct) return members;
    for (const ast::StructInitItem& item : declInit.fields) {
        if (!item.value || !isLiteralInit(*item.value)) continue;
        const std::string name = upper(item.name);
        const VarSym* member = nullptr;
        for (PouInfo* p = fb; p && !member; p = p->parent)
            if (auto it = p->vars.find(name); it != p->vars.end() && it->second->storage == Storage::Self && !it->second->byRef)
                member = it->second;
        if (member && member->type && member->type->size > 0) members.push_back(member);
    }
    return members;
}

// The elements of an array, with the FB_init arguments written after its
// element type (decision 0330): `ARRAY[1..2] OF FB_X(a := 1)` gives every
// element the same arguments, `ARRAY[1..2] OF FB_X[(a := 1), (a := 2)]` one
// list per element in storage order (row-major for several dimensions).
// Like those of a single instance, they are checked and run in the scope of
// the block or program that declares the array.
void Checker::collectArrayFbInits(const Type* t, uint8_t* addr, const ast::TypeSpec* declSpec, int depth, PouInfo* enclosing,
                                  uint8_t* enclosingAddr) {
    const ast::TypeSpec* elemSpec = declSpec && declSpec->kind == ast::TypeSpecKind::Array ? declSpec->elem.get() : nullptr;
    const auto* perElement = elemSpec && !elemSpec->elementInitArgs.empty() ? &elemSpec->elementInitArgs : nullptr;
    if (perElement && perElement->size() != t->elemCount) {
        error(diag::E0402, elemSpec->loc,
              fmt::format("{} FB_init argument list(s) for an array of {} element(s): write one per element", perElement->size(), t->elemCount));
        return;
    }
    for (uint64_t k = 0; k < t->elemCount && !fbInitLimitReported_; ++k) {
        ast::TypeSpec one;  // this element's own arguments, as on a single declaration
        const ast::TypeSpec* spec = elemSpec;
        if (perElement) {
            one.kind = ast::TypeSpecKind::Named;
            one.loc = elemSpec->loc;
            one.name = elemSpec->name;
            for (const ast::Arg& a : (*perElement)[k]) one.initArgs.push_back(ast::cloneArg(a));
            spec = &one;
        }
        collectFbInits(t->elem, addr + k * t->elem->size, spec, depth + 1, spec ? enclosing : nullptr, spec ? enclosingAddr : nullptr);
    }
}

void Checker::buildFbInitCalls() {
    model_.names.push_back("FB_init");
    currentPouName_ = &model_.names.back();
    pou_ = nullptr;
    frameTop_ = 0;
    for (const RuntimeInit& g : globalAddressInits_)
        if (exec::Stmt* st = addressInitStmt(g)) model_.initCalls.push_back(st);
    for (const RuntimeInit& s : staticInits_) {  // after the globals they may read
        PouInfo* owner = s.var->owner;
        NameScopeGuard scope(*this, owner->ast->nameSpace, owner->ast->loc.file);
        pou_ = owner;
        if (exec::Stmt* st = addressInitStmt(s)) model_.initCalls.push_back(st);
        pou_ = nullptr;
    }
    for (VarSym* g : model_.globals)
        if (g->abs) collectFbInits(g->type, g->abs, g->decl ? g->decl->type.get() : nullptr, 0, nullptr, nullptr,
                                   g->decl ? g->decl->init.get() : nullptr);
    for (auto& prog : model_.programs) collectFbInits(prog.pou->instanceType, prog.memory, nullptr, 0);
    // Temporaries of the FB_init calls (aggregate results) live in the frame they run in.
    model_.maxFrameSize = std::max(model_.maxFrameSize, (frameTop_ + 15) / 16 * 16);
    currentPouName_ = nullptr;
}

}  // namespace strun::sema
