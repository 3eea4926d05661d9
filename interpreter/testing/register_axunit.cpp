#include "interpreter/testing/register_axunit.h"

#include <fmt/format.h>

#include "interpreter/sema/checker.h"
#include "interpreter/exec/value_nodes.h"
#include "interpreter/testing/axunit_nodes.h"
#include "interpreter/testing/native_call_args.h"

namespace strun::testing {

using sema::BuiltinFn;
using sema::CallArgs;
using sema::Checked;
using sema::Checker;
using sema::TK;

namespace {

bool placeOf(Checker& ck, const Checked& file, const Checked& line, const char* shown, CallerPlace& out) {
    if (!file.type || !sema::isStringType(file.type->kind)) {
        ck.error(diag::E0201, file.loc, fmt::format("{}: the file must be a STRING or WSTRING, not {}", shown, sema::typeName(file.type)));
        return false;
    }
    Checked l = ck.coerce(line, ck.types().elementary(TK::LInt), line.loc, shown);
    if (!l.ok) return false;
    out.file = file.node;
    out.fileType = file.type;
    out.line = l.node;
    return true;
}

}  // namespace

void registerAxUnit(Checker& ck, TestRegistry& reg) {
    ck.addBuiltin("AXUNIT_SUCCEED", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!native_call::bindArgs(ck, call, {}, a)) return ck.bad(call.loc);
        return native_call::result(ck, ck.pool().make<exec::ConstInt>(0), TK::Void, call);
    });
    struct FailData { TestRegistry* regp; };
    ck.addBuiltin("AXUNIT_FAIL", BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [regp] = self.data<FailData>();
        TestRegistry& reg = *regp;
        std::vector<Checked> a;
        if (!native_call::bindArgs(ck, call, {{"message", true}, {"file", true}, {"line", true}}, a)) return ck.bad(call.loc);
        if (!a[0].type || !sema::isStringType(a[0].type->kind)) {
            ck.error(diag::E0201, a[0].loc, fmt::format("axunit_Fail: the message must be a STRING or WSTRING, not {}", sema::typeName(a[0].type)));
            return ck.bad(call.loc);
        }
        auto* n = ck.pool().make<AxFailNode>();
        n->reg = &reg;
        n->message = a[0].node;
        n->messageType = a[0].type;
        if (!placeOf(ck, a[1], a[2], "axunit_Fail", n->place)) return ck.bad(call.loc);
        return native_call::result(ck, n, TK::Void, call);
    }, FailData{&reg}));
    static const std::pair<const char*, AxCompareNode::Kind> comparisons[] = {
        {"__AXUNIT_EQUAL", AxCompareNode::Kind::Equal},
        {"__AXUNIT_NOT_EQUAL", AxCompareNode::Kind::NotEqual},
        {"__AXUNIT_LESS", AxCompareNode::Kind::Less},
        {"__AXUNIT_GREATER", AxCompareNode::Kind::Greater},
    };
    for (const auto& [name, kind] : comparisons) {
        const AxCompareNode::Kind k = kind;
        const char* shown = name;
        struct CompareData { TestRegistry* regp; AxCompareNode::Kind k; const char* shown; };
        ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
            const auto [regp, k, shown] = self.data<CompareData>();
            TestRegistry& reg = *regp;
            std::vector<Checked> a;
            if (!native_call::bindArgs(ck, call, {{"a", true}, {"b", true}, {"file", true}, {"line", true}}, a)) return ck.bad(call.loc);
            // The ST assertions pass two values of one elementary type (their overload's).
            Checked x = ck.settle(a[0]), y = ck.settle(a[1]);
            if (!x.ok || !y.ok) return ck.bad(call.loc);
            if (!x.type || !y.type || !sema::isElementary(x.type->kind) || x.type->kind != y.type->kind) {
                ck.error(diag::E0201, call.loc, fmt::format("{}: needs two values of one elementary type, not {} and {}", shown,
                                                            sema::typeName(x.type), sema::typeName(y.type)));
                return ck.bad(call.loc);
            }
            auto* n = ck.pool().make<AxCompareNode>();
            n->reg = &reg;
            n->kind = k;
            n->a = {x.node, x.type};
            n->b = {y.node, y.type};
            if (!placeOf(ck, a[2], a[3], shown, n->place)) return ck.bad(call.loc);
            return native_call::result(ck, n, TK::Void, call);
        }, CompareData{&reg, k, shown}));
    }
}

}  // namespace strun::testing
