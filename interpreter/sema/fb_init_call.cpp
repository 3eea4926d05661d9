#include "interpreter/sema/fb_init_call.h"

#include "interpreter/ast/ast_clone.h"
#include "interpreter/ast/synthesized_expr.h"
#include "interpreter/sema/types.h"
#include "stdlib/ascii_case.h"

namespace strun::sema {

ast::Expr implicitMethodCall(const char* name, const ast::Loc& loc) {
    ast::Expr call;
    call.kind = ast::ExprKind::Call;
    call.loc = loc;
    call.kids.push_back(ast::nameExpr(name, loc));
    return call;
}

ast::Expr fbInitCall(const PouInfo& init, const ast::TypeSpec* declSpec, const ast::Loc& loc) {
    ast::Expr call = implicitMethodCall("FB_init", loc);
    if (!declSpec) return call;
    for (const auto& a : declSpec->initArgs) call.args.push_back(ast::cloneArg(a));
    for (const auto& ev : declSpec->enumValues) {  // `FB(a := 1)` arrives as a typed-enumeration spec
        ast::Arg a;
        a.loc = ev.loc;
        if (ev.value) {
            a.name = ev.name;
            a.value = ast::cloneExpr(*ev.value);
        } else {
            a.value = ast::nameExpr(ev.name, ev.loc);
        }
        call.args.push_back(std::move(a));
    }
    size_t implicit = 0;
    for (const VarSym* p : init.params)
        if (upper(p->name) == "BINITRETAINS" || upper(p->name) == "BINCOPYCODE") ++implicit;
    if (implicit == 2)
        for (auto& a : call.args)
            if (a.name.empty()) {
                size_t index = &a - &call.args.front() + implicit;
                if (index < init.params.size()) a.name = init.params[index]->name;
            }
    return call;
}

std::vector<PouInfo*> fbInitChain(PouInfo* fb) {
    std::vector<PouInfo*> chain;
    for (PouInfo* p = fb; p; p = p->parent) {
        auto it = p->methods.find("FB_INIT");
        if (it != p->methods.end()) chain.insert(chain.begin(), it->second);
    }
    return chain;
}

ast::Expr baseFbInitCall(const PouInfo& base, const ast::Expr& derivedCall) {
    ast::Expr call = implicitMethodCall("FB_init", derivedCall.loc);
    for (size_t k = 0; k < derivedCall.args.size(); ++k) {
        const ast::Arg& a = derivedCall.args[k];
        bool declared = a.name.empty() && k < base.params.size();
        for (const VarSym* p : base.params) declared = declared || (!a.name.empty() && stdlib::equalsIgnoreCase(p->name, a.name));
        if (declared) call.args.push_back(ast::cloneArg(a));
    }
    return call;
}

}  // namespace strun::sema
