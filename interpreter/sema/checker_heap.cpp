// CODESYS/TwinCAT dynamic memory and pointer queries (docs/decisions/0300,
// 0301): `__NEW(T)`, `__NEW(T, n)`, `__DELETE(p)`, `__QUERYPOINTER(itf, p)`.
// The blocks live on the project's bounded heap (runtime/heap.h), inside its
// memory map; the nodes are in interpreter/exec/heap_nodes.h.
#include <fmt/format.h>

#include "interpreter/ast/ast_clone.h"
#include "interpreter/exec/call_nodes.h"
#include "interpreter/exec/heap_nodes.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/fb_init_call.h"

namespace strun::sema {

namespace {
constexpr int kMaxHeapInitNesting = 64;            // instances inside instances, as for FB_init at start-up
constexpr size_t kMaxInitStmts = 10000;    // start-up statements of one __NEW instance
}  // namespace

// The start-up code of a value of type `t` at `place` created by __NEW: what
// collectFbInits (checker_fb_init.cpp) does for declared instances, but at an
// address known only at run time. Embedded instances first, then the
// instance's run-time initialisers (base blocks' first), then its FB_init.
void Checker::heapInitStmts(const Type* t, exec::Expr* place, const ast::TypeSpec* declSpec, int depth, std::vector<exec::Stmt*>& out) {
    if (!t || depth > kMaxHeapInitNesting || !holdsFbInit(t) || out.size() > kMaxInitStmts) return;
    auto at = [&](uint64_t offset, const Type* type) {
        auto* p = pool().make<exec::OffsetPlace>(place, static_cast<uint32_t>(offset));
        p->type = type;
        return p;
    };
    if (t->kind == TK::Array) {
        if (t->elem && (t->elem->kind == TK::FunctionBlock || t->elem->kind == TK::Struct || t->elem->kind == TK::Array))
            for (uint64_t k = 0; k < t->elemCount && out.size() <= kMaxInitStmts; ++k)
                heapInitStmts(t->elem, at(k * t->elem->size, t->elem), nullptr, depth + 1, out);
        return;
    }
    if (t->kind == TK::Struct) {
        for (const Type* p = t; p; p = p->parent)
            for (const auto& f : p->fields) heapInitStmts(f.type, at(f.offset, f.type), nullptr, depth + 1, out);
        return;
    }
    if (t->kind != TK::FunctionBlock || !t->pou) return;
    PouInfo* fb = t->pou;
    for (PouInfo* p = fb; p; p = p->parent)
        for (auto& v : p->ownedVars)
            if (v->storage == Storage::Self && !v->byRef)
                heapInitStmts(v->type, at(v->offset, v->type), v->decl ? v->decl->type.get() : nullptr, depth + 1, out);
    std::vector<PouInfo*> chain;
    for (PouInfo* p = fb; p && chain.size() <= static_cast<size_t>(kMaxHeapInitNesting); p = p->parent) chain.insert(chain.begin(), p);
    for (PouInfo* p : chain) {
        if (p->addressInits.empty()) continue;
        // Built here, not shared with start-up's cached block: its temporaries
        // belong to the frame of the POU that calls __NEW.
        PouInfo* savedPou = pou_;
        pou_ = p;
        auto* block = pool().make<exec::Block>();
        for (const RuntimeInit& init : p->addressInits)
            if (exec::Stmt* st = addressInitStmt(init)) block->stmts.push_back(st);
        pou_ = savedPou;
        out.push_back(pool().make<exec::WithSelfAt>(place, block));
    }
    const std::vector<PouInfo*> inits = fb->kind == ast::PouKind::FunctionBlock ? fbInitChain(fb) : std::vector<PouInfo*>{};
    if (inits.empty()) return;
    PouInfo* init = inits.back();
    ast::Expr call = fbInitCall(*init, declSpec, declSpec ? declSpec->loc : init->ast->loc);
    place->type = t;
    Checked c = callUserFunction(init, call, place);
    if (!c.ok) return;
    for (size_t k = 0; k + 1 < inits.size(); ++k) {  // the bases' FB_init first (decision 0461)
        Checked b = callUserFunction(inits[k], baseFbInitCall(*inits[k], call), place);
        if (b.ok) out.push_back(pool().make<exec::EvalStmt>(b.node, exec::EvalStmt::Rep::Int));
    }
    out.push_back(pool().make<exec::EvalStmt>(c.node, exec::EvalStmt::Rep::Int));
}

Checked Checker::heapCall(const std::string& key, const ast::Expr& e, bool& handled) {
    handled = key == "__NEW" || key == "__DELETE" || key == "__QUERYPOINTER";
    if (!handled) return bad(e.loc);
    for (const auto& a : e.args)
        if (!a.value) {
            error(diag::E0301, a.loc, "missing argument value");
            return bad(e.loc);
        }

    if (key == "__NEW") {
        if (e.args.empty() || e.args.size() > 2) {
            error(diag::E0301, e.loc, "__NEW takes a type and an optional element count: __NEW(T) or __NEW(T, n)");
            return bad(e.loc);
        }
        const ast::Expr& written = *e.args[0].value;
        // `__NEW(FB_List(Initial_Capacity := 0))` (TwinCAT): the arguments of the instance's FB_init.
        const bool withInitArgs = written.kind == ast::ExprKind::Call && !written.kids.empty() && written.kids[0]->kind == ast::ExprKind::Name;
        const ast::Expr& typeArg = withInitArgs ? *written.kids[0] : written;
        if (typeArg.kind != ast::ExprKind::Name) {
            error(diag::E0201, typeArg.loc, "__NEW needs a type name as its first argument");
            return bad(e.loc);
        }
        const Type* t = resolveNamedType(typeArg.name, typeArg.loc);
        if (!t) return bad(e.loc);
        if (typeArg.pointerTo) t = types().pointer(t);  // __NEW(POINTER TO T, n): n pointers
        if (t->kind == TK::FunctionBlock && t->pou && t->pou->kind != ast::PouKind::FunctionBlock) {
            error(diag::E0107, typeArg.loc, fmt::format("'{}' is a PROGRAM; __NEW creates function blocks and data types", typeArg.name));
            return bad(e.loc);
        }
        if (t->kind == TK::Interface || t->kind == TK::Void || (t->kind == TK::Array && t->flexible)) {
            error(diag::E0201, typeArg.loc, fmt::format("__NEW creates function blocks and data types, not {}", typeName(t)));
            return bad(e.loc);
        }
        if (t->kind == TK::FunctionBlock && t->pou && t->pou->ast && t->pou->ast->abstract) {
            error(diag::E0405, typeArg.loc, fmt::format("'{}' is ABSTRACT: __NEW cannot create an instance of it", typeArg.name));
            return bad(e.loc);
        }
        auto* node = pool().make<exec::HeapNew>(t, t->size);
        if (e.args.size() == 2) {
            if (t->kind == TK::FunctionBlock) {
                error(diag::E0301, e.args[1].value->loc,
                      fmt::format("__NEW of function block '{}' takes no element count: blocks are created one at a time", typeArg.name));
                return bad(e.loc);
            }
            Checked n = checkExpr(*e.args[1].value);
            if (!n.ok) return bad(e.loc);
            if (!isIntRep(n.type) || !isInteger(n.type->kind)) {
                error(diag::E0201, e.args[1].value->loc, fmt::format("the element count of __NEW must be an integer, not {}", typeName(n.type)));
                return bad(e.loc);
            }
            node->count = n.node;
        }
        if (t->kind != TK::FunctionBlock && holdsFbInit(t)) {
            // A structure or array holding instances that need start-up code:
            // run it for each element would need a loop per __NEW; refuse instead.
            if (e.args.size() == 2) {
                error(diag::E0201, e.args[1].value->loc,
                      fmt::format("__NEW of several {} is not supported: it holds function blocks with FB_init or address initialisers", typeName(t)));
                return bad(e.loc);
            }
        }
        ast::TypeSpec initSpec;
        if (withInitArgs) {
            if (t->kind != TK::FunctionBlock || !t->pou || !findMethod(t->pou, "FB_INIT")) {
                error(diag::E0301, written.loc, fmt::format("'{}' has no FB_init method to take these arguments", typeArg.name));
                return bad(e.loc);
            }
            initSpec.loc = written.loc;
            for (const auto& a : written.args) initSpec.initArgs.push_back(ast::cloneArg(a));
        }
        if (holdsFbInit(t)) {
            auto* current = pool().make<exec::HeapCurrent>(node);
            current->type = t;
            std::vector<exec::Stmt*> stmts;
            heapInitStmts(t, current, withInitArgs ? &initSpec : nullptr, 0, stmts);
            if (stmts.size() > kMaxInitStmts) {
                error(diag::E0007, typeArg.loc, fmt::format("__NEW of '{}' needs more than {} start-up calls (FB_init of embedded instances)", typeArg.name, kMaxInitStmts));
                return bad(e.loc);
            }
            auto* block = pool().make<exec::Block>();
            block->stmts = std::move(stmts);
            node->init = block;
        }
        Checked r;
        r.ok = true;
        r.loc = e.loc;
        r.hasCall = true;
        r.type = types().pointer(t);
        r.node = node;
        node->type = r.type;
        return r;
    }

    if (key == "__DELETE") {
        if (e.args.size() != 1) {
            error(diag::E0301, e.loc, "__DELETE takes one pointer");
            return bad(e.loc);
        }
        Checked p = checkExpr(*e.args[0].value);
        if (!p.ok) return bad(e.loc);
        if (p.type->kind != TK::Pointer) {
            error(diag::E0201, e.args[0].value->loc, fmt::format("__DELETE needs a POINTER, not {}", typeName(p.type)));
            return bad(e.loc);
        }
        // A variable is set to 0; a value (`__DELETE(THIS)`, as TwinCAT code releases itself) is only released.
        auto* node = pool().make<exec::HeapDelete>(p.node, p.isPlace && !p.readOnly, site(e.loc));
        const Type* target = p.type->target;
        PouInfo* exitMethod = target && target->kind == TK::FunctionBlock && target->pou && target->pou->kind == ast::PouKind::FunctionBlock
                                  ? findMethod(target->pou, "FB_EXIT") : nullptr;
        if (exitMethod) {
            auto* current = pool().make<exec::HeapDeleteCurrent>(node);
            current->type = target;
            ast::Expr call = implicitMethodCall("FB_exit", e.loc);
            Checked c = callUserFunction(exitMethod, call, current);
            if (!c.ok) return bad(e.loc);
            node->exit = pool().make<exec::EvalStmt>(c.node, exec::EvalStmt::Rep::Int);
        }
        Checked r;
        r.ok = true;
        r.loc = e.loc;
        r.hasCall = true;
        r.type = types().elementary(TK::Bool);
        r.node = node;
        node->type = r.type;
        return r;
    }

    // __QUERYPOINTER(itf, p): p := the instance behind the interface, TRUE when there is one.
    if (e.args.size() != 2) {
        error(diag::E0301, e.loc, "__QUERYPOINTER takes a source interface and a destination pointer");
        return bad(e.loc);
    }
    Checked src = checkExpr(*e.args[0].value);
    Checked dst = checkExpr(*e.args[1].value);
    if (!src.ok || !dst.ok) return bad(e.loc);
    if (src.type->kind != TK::Interface) {
        error(diag::E0405, e.args[0].value->loc, fmt::format("__QUERYPOINTER needs an interface as source, not {}", typeName(src.type)));
        return bad(e.loc);
    }
    if (!(dst.type->kind == TK::Pointer || isInteger(dst.type->kind) || isBitString(dst.type->kind)) || dst.type->size != 8 || !dst.isPlace || dst.readOnly) {
        error(diag::E0206, e.args[1].value->loc, "__QUERYPOINTER needs a pointer variable as destination");
        return bad(e.loc);
    }
    Checked r;
    r.ok = true;
    r.loc = e.loc;
    r.type = types().elementary(TK::Bool);
    r.node = pool().make<exec::QueryInterface>(src.node, dst.node);
    r.node->type = r.type;
    return r;
}

}  // namespace strun::sema
