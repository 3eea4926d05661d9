// Initial values that are not known at compile time (docs/decisions/0275).
//
// A declaration's initial value is normally folded into the initial image of
// the instance, frame or global list. TwinCAT and CODESYS also accept
// initialisers over earlier declarations of the same POU (`b : BYTE := a + 1;`,
// `arr : ARRAY[1..2] OF BYTE := [a, b];`), over other globals, and function
// calls (`y : INT := F(3);`, `s : ST_X := F_MakeX();`). Such a part becomes an
// assignment to the element or member it initialises, run at initialisation in
// declaration order: once per instance and global before the first cycle, at
// the start of every call for a FUNCTION's or METHOD's locals. Addresses
// (`p : POINTER TO INT := ADR(x)`) took this way before and share it.
#include <fmt/format.h>

#include "interpreter/ast/ast_clone.h"
#include "interpreter/ast/synthesized_expr.h"
#include "interpreter/sema/checker.h"

namespace strun::sema {

namespace {
// Run-time initialisers of one variable (`arr : ARRAY[1..100000] OF INT := [100000(n)]`
// would be one assignment per element): beyond this the declaration is an error.
constexpr size_t kMaxRuntimeInitsPerVar = 4096;
}  // namespace

void Checker::writeVarInitial(uint8_t* p, VarSym* v, std::vector<RuntimeInit>* runtime) {
    if (!v->decl || !v->decl->init) return;
    // Laying out a type named in the initialiser may write other variables'
    // initial values: keep and restore this variable's context.
    auto* savedList = runtimeInits_;
    VarSym* savedVar = runtimeInitVar_;
    auto savedPath = std::move(initPath_);
    // A constant is folded into its uses, so it must be known at compile time.
    runtimeInits_ = v->constant ? nullptr : runtime;
    runtimeInitVar_ = v;
    initPath_.clear();
    writeInitial(p, v->type, v->decl->init.get(), v->decl->loc);
    runtimeInits_ = savedList;
    runtimeInitVar_ = savedVar;
    initPath_ = std::move(savedPath);
}

// Records `value` as the run-time initialiser of the part of the variable
// that initPath_ names; false when this variable cannot have one.
bool Checker::deferInitial(const ast::Expr& value) {
    if (!runtimeInits_ || !runtimeInitVar_) return false;
    size_t mine = 0;
    for (const RuntimeInit& r : *runtimeInits_) mine += r.var == runtimeInitVar_;
    if (mine >= kMaxRuntimeInitsPerVar) {
        if (mine == kMaxRuntimeInitsPerVar)
            error(diag::E0007, value.loc, fmt::format("more than {} parts of '{}' are initialised at run time", kMaxRuntimeInitsPerVar,
                                         runtimeInitVar_->name));
        runtimeInits_->push_back({runtimeInitVar_, nullptr, nullptr});  // counts, never runs
        return true;
    }
    RuntimeInit init;
    init.var = runtimeInitVar_;
    init.value = &value;
    if (!initPath_.empty()) {
        ast::ExprPtr target = ast::nameExpr(runtimeInitVar_->name, value.loc);
        for (const InitPathStep& step : initPath_) {
            auto next = std::make_unique<ast::Expr>();
            next->loc = value.loc;
            next->kids.push_back(std::move(target));
            if (!step.array) {
                next->kind = ast::ExprKind::Member;
                next->name = step.member;
                next->nameLoc = value.loc;
            } else {
                next->kind = ast::ExprKind::Index;
                // The flat position in row-major order, back to one index per dimension.
                const auto& dims = step.array->dims;
                std::vector<int64_t> index(dims.size());
                uint64_t rest = step.element;
                for (size_t d = dims.size(); d-- > 0;) {
                    const uint64_t count = static_cast<uint64_t>(dims[d].count());
                    index[d] = dims[d].lo + static_cast<int64_t>(count ? rest % count : 0);
                    rest = count ? rest / count : 0;
                }
                for (int64_t i : index) next->kids.push_back(ast::integerExpr(i, value.loc));
            }
            target = std::move(next);
        }
        init.target = std::move(target);
    }
    runtimeInits_->push_back(std::move(init));
    return true;
}

// `v := <its initialiser>` (REF= for a REFERENCE), or `v.part := <value>`,
// checked in the POU that declares v.
exec::Stmt* Checker::addressInitStmt(const RuntimeInit& init) {
    VarSym* v = init.var;
    if (!init.value) return nullptr;
    ast::Stmt st;
    st.kind = !init.target && v->type->kind == TK::Reference ? ast::StmtKind::RefAssign : ast::StmtKind::Assign;
    st.loc = init.target || !v->decl || !v->decl->init ? init.value->loc : v->decl->init->loc;
    st.target = init.target ? ast::cloneExpr(*init.target) : ast::nameExpr(v->name, v->loc);
    st.expr = ast::cloneExpr(*init.value);
    // A method's VAR_INST lives in the block's instance but is named only in
    // the method, whose THIS^ is the same instance: check it there.
    PouInfo* savedPou = pou_;
    if (v->owner && pou_ && v->owner != pou_ && v->owner->owner == pou_) pou_ = v->owner;
    exec::Stmt* out = checkStmt(st);
    pou_ = savedPou;
    return out;
}

}  // namespace strun::sema
