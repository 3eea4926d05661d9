#include "interpreter/sema/fb_init_call.h"

#include "interpreter/ast/ast_clone.h"
#include "interpreter/sema/types.h"

namespace strun::sema {

ast::Expr implicitMethodCall(const char* name, const ast::Loc& loc) {
    ast::Expr call;
    call.kind = ast::ExprKind::Call;
    call.loc = loc;
    auto callee = std::make_unique<ast::Expr>();
    callee->kind = ast::ExprKind::Name;
    callee->loc = loc;
    callee->name = name;
    call.kids.push_back(std::move(callee));
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
            a.value = std::make_unique<ast::Expr>();
            a.value->kind = ast::ExprKind::Name;
            a.value->loc = ev.loc;
            a.value->name = ev.name;
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

}  // namespace strun::sema
