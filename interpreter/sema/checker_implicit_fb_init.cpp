// `inst.FB_init(FALSE, FALSE)`, `THIS^.FB_init(...)` on a function block that
// declares no FB_init (decision 0457): every block has an FB_init, the
// implicit one that writes the instance's initial values; TwinCAT and CODESYS
// let code call it (fisothemes FsTime resets an instance that way after an
// error). The call writes the initial values of the instance's class again.
#include <algorithm>

#include <fmt/format.h>

#include "interpreter/exec/reinit_nodes.h"
#include "interpreter/sema/checker.h"

namespace strun::sema {

bool Checker::isImplicitFbInit(const Type* instance, const std::string& member) {
    return instance && instance->kind == TK::FunctionBlock && instance->pou && upper(member) == "FB_INIT" &&
           !findMethod(instance->pou, "FB_INIT");
}

Checked Checker::implicitFbInitCall(const Checked& base, const ast::Expr& call) {
    // FB_init(bInitRetains : BOOL; bInCopyCode : BOOL) : BOOL; the arguments
    // change nothing for the implicit one (there is no copy code), but are checked.
    static const char* const kParams[] = {"BINITRETAINS", "BINCOPYCODE"};
    bool ok = true;
    for (size_t k = 0; k < call.args.size(); ++k) {
        const ast::Arg& a = call.args[k];
        const bool known = a.name.empty() ? k < 2 : std::any_of(std::begin(kParams), std::end(kParams), [&](const char* p) {
            return upper(a.name) == p;
        });
        if (!known || a.output || !a.value) {
            error(a.name.empty() ? diag::E0301 : diag::E0302, a.loc, a.name.empty() ? fmt::format("FB_init takes two inputs (bInitRetains, bInCopyCode), not {}", call.args.size())
                                                     : fmt::format("FB_init has no input '{}' (its inputs are bInitRetains, bInCopyCode)", a.name));
            ok = false;
            continue;
        }
        Checked v = coerce(checkExpr(*a.value), types().elementary(TK::Bool), a.loc, "argument");
        ok = ok && v.ok;
    }
    if (!ok) return bad(call.loc);
    auto* node = pool().make<exec::ReinitInstance>(base.node);
    // The class the instance has at run time: its static type, or a block extending it.
    for (PouInfo* p : pouOrder_) {
        bool extendsBase = false;
        for (const PouInfo* q = p; q && !extendsBase; q = q->parent) extendsBase = q == base.type->pou;
        if (!extendsBase || !p->classDesc || p->instanceInit.empty()) continue;
        exec::ReinitInstance::ClassImage k;
        k.desc = p->classDesc;
        k.image = &p->instanceInit;
        for (const PouInfo* q = p; q; q = q->parent)
            for (const RuntimeInit& init : q->addressInits)
                if (init.var && init.var->storage == Storage::Self && init.var->type)
                    k.kept.emplace_back(init.var->offset, init.var->offset + init.var->type->size);
        std::sort(k.kept.begin(), k.kept.end());
        node->classes.push_back(std::move(k));
    }
    Checked c;
    c.ok = true;
    c.loc = call.loc;
    c.type = types().elementary(TK::Bool);
    c.node = node;
    c.node->type = c.type;
    c.hasCall = true;
    return c;
}

}  // namespace strun::sema
