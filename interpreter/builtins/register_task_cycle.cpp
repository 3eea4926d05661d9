// GetCurrentTaskCycle / SetCurrentTaskCycle (M241 Toolbox Advance, seed 003):
// read and change the period of the cyclic task that calls them, in ms.
// Only on a target that has them (--target m241); elsewhere a compile error
// naming that target. The scheduler checks the new period against the
// target's interval rules (>= 4 ms, a multiple of 4 ms) and refuses others.
#include <fmt/format.h>

#include "interpreter/builtins/bind_support.h"
#include "interpreter/builtins/register_groups.h"

namespace strun::stdlib::bind {

namespace {

constexpr int64_t kNsPerMs = 1'000'000;

using exec::Ctx;
using exec::Expr;

// UDINT: the calling task's period in ms; 0 when it is not a cyclic task.
struct GetTaskCycleNode final : Expr {
    int64_t i(Ctx& c) override { return c.m->handler->currentTaskInterval() / kNsPerMs; }
};

// BOOL: TRUE when the new period (ms) was accepted.
struct SetTaskCycleNode final : Expr {
    Expr* ms;
    explicit SetTaskCycleNode(Expr* m) : ms(m) {}
    int64_t i(Ctx& c) override {
        int64_t value = ms->i(c);
        return value > 0 && c.m->handler->setCurrentTaskInterval(value * kNsPerMs) ? 1 : 0;
    }
};

bool available(Checker& ck, const CallArgs& call, const char* name) {
    if (ck.profile().taskCycleFunctions) return true;
    const rt::PlcProfile* owner = rt::profileWithTaskCycleFunctions();
    ck.error(diag::E0602, call.loc, fmt::format("{} exists only with --target {} ({}); the target is {}", name,
                                   owner ? owner->id : "m241", owner ? owner->description : "Modicon M241",
                                   ck.profile().id));
    return false;
}

}  // namespace

void registerTaskCycle(Checker& ck) {
    ck.addBuiltin("GETCURRENTTASKCYCLE", [](Checker& ck, CallArgs& call) -> Checked {
        if (!available(ck, call, "GetCurrentTaskCycle")) return ck.bad(call.loc);
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {}, a)) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<GetTaskCycleNode>(), ck.types().elementary(TK::UDInt), call, a, false);
    });
    ck.addBuiltin("SETCURRENTTASKCYCLE", [](Checker& ck, CallArgs& call) -> Checked {
        if (!available(ck, call, "SetCurrentTaskCycle")) return ck.bad(call.loc);
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"CYCLE|CYCLETIME"}}, a)) return ck.bad(call.loc);
        if (!isIntegerArg(a[0])) return argError(ck, a[0], "SetCurrentTaskCycle", "an integer number of milliseconds");
        if (!coerceAll(ck, a, ck.types().elementary(TK::UDInt), "SetCurrentTaskCycle")) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<SetTaskCycleNode>(a[0].node), ck.types().elementary(TK::Bool), call, a, false);
    });
}

}  // namespace strun::stdlib::bind
