#include "interpreter/testing/register_tcunit.h"

#include <initializer_list>

#include <fmt/format.h>

#include "interpreter/exec/value_nodes.h"
#include "interpreter/sema/checker.h"
#include "interpreter/testing/native_call_args.h"
#include "interpreter/testing/tcunit_nodes.h"

namespace strun::testing {

using sema::BuiltinFn;
using sema::CallArgs;
using sema::Checked;
using sema::Checker;
using sema::TK;
using sema::Type;

namespace {

using native_call::bindArgs;
using native_call::Param;
using native_call::result;
using native_call::written;


// A STRING/WSTRING argument (TestName, Message): the node and its type, or an error.
bool stringInput(Checker& ck, const Checked& a, const CallArgs& call, const char* what, Expr*& node, const Type*& type) {
    if (!a.ok) return true;  // not given: ''
    if (!a.type || !sema::isStringType(a.type->kind)) {
        ck.error(diag::E0201, a.loc, fmt::format("{}: {} must be a STRING, not {}", written(call), what, sema::typeName(a.type)));
        return false;
    }
    node = a.node;
    type = a.type;
    return true;
}

bool deltaInput(Checker& ck, const Checked& a, const Type* t, const CallArgs& call, Expr*& node) {
    if (!a.ok) return true;
    Checked d = ck.coerce(a, ck.types().elementary(t && t->kind == TK::Real ? TK::Real : TK::LReal), a.loc, written(call).c_str());
    if (!d.ok) return false;
    node = d.node;
    return true;
}

// The elementary types that have an AssertEquals_<TYPE> and array asserts, by
// the name used in the function name (TcUnit's, plus every IEC spelling).
const std::vector<std::pair<const char*, TK>>& assertTypes() {
    static const std::vector<std::pair<const char*, TK>> list = {
        {"BOOL", TK::Bool}, {"BYTE", TK::Byte}, {"WORD", TK::Word}, {"DWORD", TK::DWord}, {"LWORD", TK::LWord},
        {"SINT", TK::SInt}, {"INT", TK::Int}, {"DINT", TK::DInt}, {"LINT", TK::LInt},
        {"USINT", TK::USInt}, {"UINT", TK::UInt}, {"UDINT", TK::UDInt}, {"ULINT", TK::ULInt},
        {"REAL", TK::Real}, {"LREAL", TK::LReal}, {"TIME", TK::Time}, {"LTIME", TK::LTime},
        {"DATE", TK::Date}, {"LDATE", TK::LDate}, {"TIME_OF_DAY", TK::Tod}, {"TOD", TK::Tod},
        {"LTIME_OF_DAY", TK::LTod}, {"LTOD", TK::LTod}, {"DATE_AND_TIME", TK::Dt}, {"DT", TK::Dt},
        {"LDATE_AND_TIME", TK::LDt}, {"LDT", TK::LDt}, {"CHAR", TK::Char}, {"WCHAR", TK::WChar},
        {"STRING", TK::String}, {"WSTRING", TK::WString},
    };
    return list;
}

// Prepares the common part of an assertion node (registry, location, message).
bool assertCommon(Checker& ck, TestRegistry& reg, CallArgs& call, const Checked& message, AssertBase* node) {
    node->reg = &reg;
    node->file = call.loc.file;
    node->line = call.loc.line;
    return stringInput(ck, message, call, "Message", node->message, node->messageType);
}

// Expected/Actual of AssertEquals_<TYPE>: coerced to the type (strings keep their length).
bool typedOperand(Checker& ck, const Checked& a, TK kind, const CallArgs& call, Operand& out) {
    if (kind == TK::String || kind == TK::WString) {
        if (!a.type || a.type->kind != kind) {
            ck.error(diag::E0201, a.loc, fmt::format("{}: expected a {}, not {}", written(call), kind == TK::String ? "STRING" : "WSTRING", sema::typeName(a.type)));
            return false;
        }
        out.e = a.node;
        out.t = a.type;
        return true;
    }
    Checked c = ck.coerce(a, ck.types().elementary(kind), a.loc, written(call).c_str());
    if (!c.ok) return false;
    out.e = c.node;
    out.t = c.node->type ? c.node->type : c.type;
    out.t = c.type;
    return true;
}

// An array argument of AssertArray*Equals_<TYPE>.
bool arrayOperand(Checker& ck, const Checked& a, TK kind, size_t dims, const CallArgs& call, ArrayOperand& out, const Type*& elem) {
    const Type* t = a.type;
    if (!t || t->kind != TK::Array || !t->elem || t->elem->kind != kind) {
        ck.error(diag::E0201, a.loc, fmt::format("{}: expected an ARRAY of {}, not {}", written(call), sema::typeName(ck.types().elementary(kind)), sema::typeName(t)));
        return false;
    }
    if (kind == TK::String || kind == TK::WString) {
        if (elem && elem->maxLen != t->elem->maxLen) {
            ck.error(diag::E0407, a.loc, fmt::format("{}: the arrays' string lengths differ", written(call)));
            return false;
        }
    }
    elem = t->elem;
    if (t->flexible) {
        if (!a.flexDesc) {
            ck.error(diag::E0407, a.loc, fmt::format("{}: this ARRAY[*] cannot be compared here", written(call)));
            return false;
        }
        out.desc = a.flexDesc;
        return true;
    }
    if (t->dims.size() != dims) {
        ck.error(diag::E0201, a.loc, fmt::format("{}: expected a {}-dimensional array, not {}", written(call), dims, sema::typeName(t)));
        return false;
    }
    out.place = a.node;
    for (const auto& d : t->dims) {
        out.lo.push_back(d.lo);
        out.hi.push_back(d.hi);
    }
    return true;
}

// What a built-in that needs only the project's test registry holds.
struct RegistryData {
    TestRegistry* regp;
};

void registerTestControl(Checker& ck, TestRegistry& reg) {
    for (bool ordered : {false, true}) {
        struct TestData { TestRegistry* regp; bool ordered; };
        ck.addBuiltin(ordered ? "TEST_ORDERED" : "TEST", BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
            const auto [regp, ordered] = self.data<TestData>();
            TestRegistry& reg = *regp;
            std::vector<Checked> a;
            if (!bindArgs(ck, call, {{"TestName", true}}, a)) return ck.bad(call.loc);
            auto* n = ck.pool().make<BeginTestNode>();
            n->reg = &reg;
            n->ordered = ordered;
            if (!stringInput(ck, a[0], call, "TestName", n->name, n->nameType)) return ck.bad(call.loc);
            // --list names the tests without running them: remember the constant names.
            if (auto* lit = dynamic_cast<exec::ConstBytes*>(n->name); lit && n->nameType->kind == TK::String && ck.currentPouName())
                reg.staticTests.push_back({*ck.currentPouName(),
                                           std::string(reinterpret_cast<const char*>(lit->bytes.data()),
                                                       strnlen(reinterpret_cast<const char*>(lit->bytes.data()), lit->bytes.size())),
                                           call.loc.file, call.loc.line});
            return result(ck, n, ordered ? TK::Bool : TK::Void, call);
        }, TestData{&reg, ordered}));
    }
    ck.addBuiltin("TEST_FINISHED", BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [regp] = self.data<RegistryData>();
        TestRegistry& reg = *regp;
        std::vector<Checked> a;
        if (!bindArgs(ck, call, {}, a)) return ck.bad(call.loc);
        auto* n = ck.pool().make<FinishTestNode>();
        n->reg = &reg;
        return result(ck, n, TK::Bool, call);
    }, RegistryData{&reg}));
    for (bool query : {false, true}) {
        struct FinishedData { TestRegistry* regp; bool query; };
        ck.addBuiltin(query ? "IS_TEST_FINISHED" : "TEST_FINISHED_NAMED", BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
            const auto [regp, query] = self.data<FinishedData>();
            TestRegistry& reg = *regp;
            std::vector<Checked> a;
            if (!bindArgs(ck, call, {{"TestName", true}}, a)) return ck.bad(call.loc);
            Expr* name = nullptr;
            const Type* type = nullptr;
            if (!stringInput(ck, a[0], call, "TestName", name, type)) return ck.bad(call.loc);
            if (query) {
                auto* n = ck.pool().make<IsTestFinishedNode>();
                n->reg = &reg;
                n->name = name;
                n->nameType = type;
                return result(ck, n, TK::Bool, call);
            }
            auto* n = ck.pool().make<FinishNamedTestNode>();
            n->reg = &reg;
            n->name = name;
            n->nameType = type;
            return result(ck, n, TK::Bool, call);
        }, FinishedData{&reg, query}));
    }
    for (bool inSequence : {false, true}) {
        struct RunData { TestRegistry* regp; bool inSequence; };
        ck.addBuiltin(inSequence ? "RUN_IN_SEQUENCE" : "RUN", BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
            const auto [regp, inSequence] = self.data<RunData>();
            TestRegistry& reg = *regp;
            std::vector<Checked> a;
            // RUN_IN_SEQUENCE(TimeBetweenTestSuitesExecution) in TcUnit 1.1 and CfUnit.
            bool ok = inSequence ? bindArgs(ck, call, {{"TimeBetweenTestSuitesExecution", false}}, a) : bindArgs(ck, call, {}, a);
            if (!ok) return ck.bad(call.loc);
            ++reg.runCalls;
            auto* n = ck.pool().make<RunSuitesNode>();
            n->reg = &reg;
            n->inSequence = inSequence;
            if (inSequence && a[0].ok) {
                Checked d = ck.settle(a[0]);
                if (!d.ok) return ck.bad(call.loc);
                if (!d.type || (d.type->kind != TK::Time && d.type->kind != TK::LTime)) {
                    ck.error(diag::E0201, d.loc, fmt::format("{}: expected a TIME, not {}", written(call), sema::typeName(d.type)));
                    return ck.bad(call.loc);
                }
                n->pause = d.node;
                n->scale = d.type->kind == TK::Time ? 1000000 : 1;
            }
            return result(ck, n, TK::Void, call);
        }, RunData{&reg, inSequence}));
    }
    // AWAIT_ASSERTIONS(AwaitTime) / TIMEOUT_FOR_EACH_TEST(Timeout): a duration.
    for (bool await : {true, false}) {
        struct TimeoutData { TestRegistry* regp; bool await; };
        ck.addBuiltin(await ? "AWAIT_ASSERTIONS" : "TIMEOUT_FOR_EACH_TEST", BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
            const auto [regp, await] = self.data<TimeoutData>();
            TestRegistry& reg = *regp;
            std::vector<Checked> a;
            if (!bindArgs(ck, call, {{await ? "AwaitTime" : "Timeout", true}}, a)) return ck.bad(call.loc);
            Checked d = ck.settle(a[0]);
            if (!d.ok) return ck.bad(call.loc);
            if (!d.type || (d.type->kind != TK::Time && d.type->kind != TK::LTime)) {
                ck.error(diag::E0201, d.loc, fmt::format("{}: expected a TIME, not {}", written(call), sema::typeName(d.type)));
                return ck.bad(call.loc);
            }
            const int64_t scale = d.type->kind == TK::Time ? 1000000 : 1;
            if (await) {
                auto* n = ck.pool().make<AwaitAssertionsNode>();
                n->reg = &reg;
                n->duration = d.node;
                n->scale = scale;
                return result(ck, n, TK::Void, call);
            }
            auto* n = ck.pool().make<TestTimeoutNode>();
            n->reg = &reg;
            n->duration = d.node;
            n->scale = scale;
            return result(ck, n, TK::Void, call);
        }, TimeoutData{&reg, await}));
    }
    // The natives behind FB_TestSuite's query methods (stdlib/st/tcunit.st).
    static const std::pair<const char*, SuiteQueryNode::What> queries[] = {
        {"__TCUNIT_NUMBER_OF_TESTS", SuiteQueryNode::What::Tests},
        {"__TCUNIT_NUMBER_OF_FAILED_TESTS", SuiteQueryNode::What::Failed},
        {"__TCUNIT_NUMBER_OF_SKIPPED_TESTS", SuiteQueryNode::What::Skipped},
        {"__TCUNIT_NUMBER_OF_SUCCESSFUL_TESTS", SuiteQueryNode::What::Successful},
        {"__TCUNIT_ALL_TESTS_FINISHED", SuiteQueryNode::What::AllFinished},
        {"__TCUNIT_TEST_FINISHED", SuiteQueryNode::What::TestFinished},
    };
    for (const auto& [name, what] : queries) {
        const SuiteQueryNode::What w = what;
        struct QueryData { TestRegistry* regp; SuiteQueryNode::What w; };
        ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
            const auto [regp, w] = self.data<QueryData>();
            TestRegistry& reg = *regp;
            std::vector<Checked> a;
            const bool named = w == SuiteQueryNode::What::TestFinished;
            bool ok = named ? bindArgs(ck, call, {{"Suite", true}, {"TestName", true}}, a) : bindArgs(ck, call, {{"Suite", true}}, a);
            if (!ok) return ck.bad(call.loc);
            if (!a[0].type || a[0].type->kind != TK::Pointer) {
                ck.error(diag::E0405, a[0].loc, fmt::format("{}: expected THIS", written(call)));
                return ck.bad(call.loc);
            }
            auto* n = ck.pool().make<SuiteQueryNode>();
            n->reg = &reg;
            n->self = a[0].node;
            n->what = w;
            if (named && !stringInput(ck, a[1], call, "TestName", n->name, n->nameType)) return ck.bad(call.loc);
            const bool boolean = w == SuiteQueryNode::What::AllFinished || named;
            return result(ck, n, boolean ? TK::Bool : TK::UInt, call);
        }, QueryData{&reg, w}));
    }
    ck.addBuiltin("TCUNIT_ADSLOGSTR", BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [regp] = self.data<RegistryData>();
        TestRegistry& reg = *regp;
        std::vector<Checked> a;
        if (!bindArgs(ck, call, {{"msgCtrlMask", false}, {"msgFmtStr", true}, {"strArg", false}}, a)) return ck.bad(call.loc);
        auto* n = ck.pool().make<AdsLogNode>();
        n->reg = &reg;
        if (a[0].ok && a[0].node) {
            Checked mask = ck.coerce(a[0], ck.types().elementary(TK::DWord), a[0].loc, "msgCtrlMask");
            if (!mask.ok) return ck.bad(call.loc);
            n->mask = mask.node;
        }
        if (!stringInput(ck, a[1], call, "msgFmtStr", n->format, n->formatType) ||
            !stringInput(ck, a[2], call, "strArg", n->arg, n->argType))
            return ck.bad(call.loc);
        return result(ck, n, TK::DInt, call);
    }, RegistryData{&reg}));
}

void registerAssertions(Checker& ck, TestRegistry& reg) {
    for (bool expected : {true, false}) {
        struct AssertBoolData { TestRegistry* regp; bool expected; };
        ck.addBuiltin(expected ? "ASSERTTRUE" : "ASSERTFALSE", BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
            const auto [regp, expected] = self.data<AssertBoolData>();
            TestRegistry& reg = *regp;
            std::vector<Checked> a;
            if (!bindArgs(ck, call, {{"Condition", true}, {"Message", false}}, a)) return ck.bad(call.loc);
            auto* n = ck.pool().make<AssertConditionNode>();
            if (!assertCommon(ck, reg, call, a[1], n)) return ck.bad(call.loc);
            Checked cond = ck.coerce(a[0], ck.types().elementary(TK::Bool), a[0].loc, written(call).c_str());
            if (!cond.ok) return ck.bad(call.loc);
            n->condition = cond.node;
            n->expected = expected;
            return result(ck, n, TK::Void, call);
        }, AssertBoolData{&reg, expected}));
    }
    // AssertEquals(Expected, Actual, Message): any type; compared by type class, size and bytes.
    ck.addBuiltin("ASSERTEQUALS", BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [regp] = self.data<RegistryData>();
        TestRegistry& reg = *regp;
        std::vector<Checked> a;
        if (!bindArgs(ck, call, {{"Expected", true}, {"Actual", true}, {"Message", false}}, a)) return ck.bad(call.loc);
        auto* n = ck.pool().make<AssertEqualsNode>();
        if (!assertCommon(ck, reg, call, a[2], n)) return ck.bad(call.loc);
        Checked& e = a[0];
        Checked& v = a[1];
        // An untyped literal takes the other side's type (decision 0140).
        bool eLit = e.untypedInt || e.untypedReal || e.flexibleLiteral;
        bool vLit = v.untypedInt || v.untypedReal || v.flexibleLiteral;
        if (eLit && !vLit && v.type && sema::isElementary(v.type->kind)) e = ck.coerce(e, v.type, e.loc, written(call).c_str());
        else if (vLit && !eLit && e.type && sema::isElementary(e.type->kind)) v = ck.coerce(v, e.type, v.loc, written(call).c_str());
        if (!e.ok || !v.ok) return ck.bad(call.loc);
        e = ck.settle(e);
        v = ck.settle(v);
        for (Checked* x : {&e, &v}) {
            TK k = x->type ? x->type->kind : TK::Void;
            if (k == TK::Void) {
                ck.error(diag::E0301, x->loc, fmt::format("{}: this argument has no value", written(call)));
                return ck.bad(call.loc);
            }
        }
        n->generic = true;
        n->expected = {e.node, e.type};
        n->actual = {v.node, v.type};
        return result(ck, n, TK::Void, call);
    }, RegistryData{&reg}));
    // The names are built in one buffer: the registry copies them.
    static constexpr const char* kArrayPrefixes[] = {"ASSERTARRAYEQUALS_", "ASSERTARRAY2DEQUALS_", "ASSERTARRAY3DEQUALS_"};
    std::string name;
    name.reserve(64);
    for (const auto& [typeName, kind] : assertTypes()) {
        const TK k = kind;
        const bool real = k == TK::Real || k == TK::LReal;
        struct AssertTypedData { TestRegistry* regp; TK k; bool real; };
        name.assign("ASSERTEQUALS_").append(typeName);
        ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
            const auto [regp, k, real] = self.data<AssertTypedData>();
            TestRegistry& reg = *regp;
            std::vector<Checked> a;
            bool ok = real ? bindArgs(ck, call, {{"Expected", true}, {"Actual", true}, {"Delta", false}, {"Message", false}}, a)
                           : bindArgs(ck, call, {{"Expected", true}, {"Actual", true}, {"Message", false}}, a);
            if (!ok) return ck.bad(call.loc);
            auto* n = ck.pool().make<AssertEqualsNode>();
            if (!assertCommon(ck, reg, call, a[real ? 3 : 2], n)) return ck.bad(call.loc);
            if (!typedOperand(ck, a[0], k, call, n->expected) || !typedOperand(ck, a[1], k, call, n->actual)) return ck.bad(call.loc);
            if (real && !deltaInput(ck, a[2], ck.types().elementary(k), call, n->delta)) return ck.bad(call.loc);
            // Without a Delta TcUnit compares within 0: equal values pass.
            return result(ck, n, TK::Void, call);
        }, AssertTypedData{&reg, k, real}));
        for (size_t dims = 1; dims <= 3; ++dims) {
            struct AssertArrayData { TestRegistry* regp; TK k; bool real; size_t dims; };
            name.assign(kArrayPrefixes[dims - 1]).append(typeName);
            ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
                const auto [regp, k, real, dims] = self.data<AssertArrayData>();
                TestRegistry& reg = *regp;
                std::vector<Checked> a;
                bool ok = real ? bindArgs(ck, call, {{"Expecteds", true}, {"Actuals", true}, {"Delta", false}, {"Message", false}}, a)
                               : bindArgs(ck, call, {{"Expecteds", true}, {"Actuals", true}, {"Message", false}}, a);
                if (!ok) return ck.bad(call.loc);
                auto* n = ck.pool().make<AssertArrayNode>();
                if (!assertCommon(ck, reg, call, a[real ? 3 : 2], n)) return ck.bad(call.loc);
                n->dims = dims;
                if (!arrayOperand(ck, a[0], k, dims, call, n->expected, n->elem) ||
                    !arrayOperand(ck, a[1], k, dims, call, n->actual, n->elem))
                    return ck.bad(call.loc);
                if (real && !deltaInput(ck, a[2], ck.types().elementary(k), call, n->delta)) return ck.bad(call.loc);
                return result(ck, n, TK::Void, call);
            }, AssertArrayData{&reg, k, real, dims}));
        }
    }
}

}  // namespace

void registerTcUnit(Checker& checker, TestRegistry& registry) {
    registerTestControl(checker, registry);
    registerAssertions(checker, registry);
}

}  // namespace strun::testing
