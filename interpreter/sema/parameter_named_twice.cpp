#include "interpreter/sema/parameter_named_twice.h"

#include <fmt/format.h>

#include "interpreter/exec/value_nodes.h"

namespace strun::sema {

bool acceptNamedTwice(Checker& ck, const ast::Loc& loc, const std::string& twice) {
    return ck.lenient(diag::W0044, loc, ck.compileOptions().strict ? twice : twice + "; the last value is the one passed");
}

bool rebindNamedTwice(Checker& ck, CallArgs& call, const ast::Loc& loc, const std::string& formal, Checked& slot,
                      const Checked& later, const std::string& callee) {
    const std::string& shown = callee.empty() ? call.name : callee;
    if (!acceptNamedTwice(ck, loc, fmt::format("parameter '{}' of '{}' given twice", formal, shown))) return false;
    // Only a call can have an effect; a constant or a variable is simply dropped.
    if (slot.hasCall && slot.node && slot.type) call.replaced.push_back(slot);
    slot = later;
    return true;
}

void sequenceReplaced(Checker& ck, const CallArgs& call, Checked& r) {
    if (call.replaced.empty() || !r.ok || !r.node) return;
    // A folded untyped constant would be re-made from its value where it is
    // used, without the node that runs the calls: it takes its own type and
    // stays convertible, like SEL(g, 1, 2).
    if (r.untypedInt || r.untypedReal) {
        r = ck.settle(r);
        r.flexibleLiteral = true;
    }
    using K = exec::ThenValue::Kind;
    for (auto it = call.replaced.rbegin(); it != call.replaced.rend(); ++it) {
        K kind = isRealRep(it->type) ? K::Real : isIntRep(it->type) ? K::Int : K::Addr;
        exec::Expr* node = ck.pool().make<exec::ThenValue>(it->node, kind, r.node);
        node->type = r.type;
        r.node = node;
    }
    r.hasCall = true;
    r.isConst = false;  // never folded away: the earlier calls must run
    r.isPlace = false;
    r.var = nullptr;
    r.direct = Checked::Direct::None;
}

}  // namespace strun::sema
