// Time and date functions: ADD_TIME ... DIV_LTIME, CONCAT_DATE_TOD ...
// CONCAT_LDT, SPLIT_DATE ... SPLIT_LDT, DAY_OF_WEEK; the time arithmetic of
// the generic ADD/SUB/MUL/DIV; the PLC-clock functions of the timer blocks.
#include <span>

#include <fmt/format.h>

#include "interpreter/builtins/bind_support.h"
#include "interpreter/builtins/register_groups.h"
#include "interpreter/builtins/time_arith.h"
#include "interpreter/builtins/time_nodes.h"

namespace strun::stdlib::bind {

namespace {

enum class Family { None, Dur, Date, Tod, Dt };

Family familyOf(const Checked& c) {
    if (c.untypedInt || c.untypedReal) return Family::None;
    switch (c.type->kind) {
        case TK::Time: case TK::LTime: return Family::Dur;
        case TK::Date: case TK::LDate: return Family::Date;
        case TK::Tod: case TK::LTod: return Family::Tod;
        case TK::Dt: case TK::LDt: return Family::Dt;
        default: return Family::None;
    }
}

bool isLong(TK k) { return k == TK::LTime || k == TK::LDate || k == TK::LTod || k == TK::LDt; }

int64_t unitOf(TK k) {
    switch (k) {
        case TK::Time: case TK::Tod: return stdlib::kNsPerMs;
        case TK::Date: case TK::Dt: return stdlib::kNsPerSecond;
        default: return 1;
    }
}

TK kindOf(Family f, bool isLongType) {
    switch (f) {
        case Family::Dur: return isLongType ? TK::LTime : TK::Time;
        case Family::Date: return isLongType ? TK::LDate : TK::Date;
        case Family::Tod: return isLongType ? TK::LTod : TK::Tod;
        default: return isLongType ? TK::LDt : TK::Dt;
    }
}

Checked notDefined(Checker& ck, const CallArgs& call, const Checked& a, const Checked& b) {
    ck.error(diag::E0202, call.loc, fmt::format("{} is not defined for {} and {}", call.name, sema::typeName(a.type), sema::typeName(b.type)));
    return ck.bad(call.loc);
}

}  // namespace

Checked timeArithmetic(Checker& ck, const CallArgs& call, TimeOp op, Checked a, Checked b) {
    Family fa = familyOf(a), fb = familyOf(b);
    std::vector<Checked> args = {a, b};
    if (op == TimeOp::Mul || op == TimeOp::Div) {
        if (op == TimeOp::Mul && fa == Family::None && fb == Family::Dur) std::swap(a, b), std::swap(fa, fb);
        if (fa != Family::Dur || fb != Family::None || !isNumArg(b)) return notDefined(ck, call, a, b);
        auto* n = ck.pool().make<TimeScaleNode>();
        n->t = a.node;
        n->realFactor = b.untypedReal || sema::isReal(b.type->kind);
        Checked k = ck.settle(b);
        n->k = k.node;
        n->divide = op == TimeOp::Div;
        n->bits = sema::bitWidth(a.type->kind);
        n->isUnsigned = a.type->unsignedDuration;
        n->site = ck.site(call.loc);
        bool fold = !(op == TimeOp::Div && !n->realFactor && k.isConst && k.constInt == 0);
        return makeResult(ck, n, a.type, call, args, fold);
    }
    if (op == TimeOp::Add && fa == Family::Dur && (fb == Family::Tod || fb == Family::Dt)) std::swap(a, b), std::swap(fa, fb);
    Family result = Family::None;
    // DATE +- TIME (`dDate + T#1S` in Beckhoff's OPC UA server sample) is not
    // in CODESYS' or TwinCAT's table, but TwinCAT compiles it: taken as
    // DT +- TIME on the DATE's seconds, without --strict (decision 0368).
    const bool dateAndDuration = !ck.compileOptions().strict && fa == Family::Date && fb == Family::Dur;
    if (op == TimeOp::Add) {
        if (fb == Family::Dur && (fa == Family::Dur || fa == Family::Tod || fa == Family::Dt)) result = fa;
        else if (dateAndDuration) result = fa;
    } else {
        if (fb == Family::Dur && (fa == Family::Dur || fa == Family::Tod || fa == Family::Dt)) result = fa;
        else if (fa == fb && (fa == Family::Date || fa == Family::Tod || fa == Family::Dt)) result = Family::Dur;
        else if (dateAndDuration) result = fa;
    }
    if (result == Family::None) return notDefined(ck, call, a, b);
    TK rk = kindOf(result, isLong(a.type->kind) || isLong(b.type->kind));
    const Type* rt = ck.types().elementary(rk);
    auto* n = ck.pool().make<TimeCombineNode>();
    n->a = a.node;
    n->b = b.node;
    n->unitA = unitOf(a.type->kind);
    n->unitB = unitOf(b.type->kind);
    n->unitR = unitOf(rk);
    n->subtract = op == TimeOp::Sub;
    n->dayModulo = result == Family::Tod;
    n->floorResult = result != Family::Dur;
    TK view = sema::integerView(rk);
    n->bits = sema::bitWidth(view);
    n->isSigned = sema::isSignedInt(view) && !rt->unsignedDuration;  // a TwinCAT TIME/LTIME is unsigned (decision 0367)
    return makeResult(ck, n, rt, call, args);
}

namespace {

// ADD_TIME(IN1, IN2) and friends: both inputs converted to their declared types first.
void addNamedArith(Checker& ck, const char* name, TimeOp op, TK in1, TK in2) {
    struct NamedArithData { TimeOp op; TK in1; TK in2; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [op, in1, in2] = self.data<NamedArithData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN1"}, {"IN2"}}, a)) return ck.bad(call.loc);
        Checked x = ck.coerce(a[0], ck.types().elementary(in1), a[0].loc, call.name.c_str());
        if (!x.ok) return x;
        Checked y = a[1];
        if (in2 != TK::Void) {
            y = ck.coerce(a[1], ck.types().elementary(in2), a[1].loc, call.name.c_str());
            if (!y.ok) return y;
        } else if (!isNumArg(y)) {
            return argError(ck, y, call.name, "IN2 must be a number");
        }
        return timeArithmetic(ck, call, op, x, y);
    }, NamedArithData{op, in1, in2}));
}

void addConcat(Checker& ck, const char* name, CalendarFn fn, TK result, std::span<const Formal> fs) {
    struct ConcatData { CalendarFn fn; TK result; std::span<const Formal> fs; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [fn, result, fs] = self.data<ConcatData>();
        std::vector<Checked> a;
        bool ok = false;
        switch (fs.size()) {
            case 2: ok = bindFixed(ck, call, {fs[0], fs[1]}, a); break;
            case 3: ok = bindFixed(ck, call, {fs[0], fs[1], fs[2]}, a); break;
            case 4: ok = bindFixed(ck, call, {fs[0], fs[1], fs[2], fs[3]}, a); break;
            default: ok = bindFixed(ck, call, {fs[0], fs[1], fs[2], fs[3], fs[4], fs[5], fs[6]}, a); break;
        }
        if (!ok) return ck.bad(call.loc);
        auto* n = ck.pool().make<ConcatCalendarNode>();
        n->fn = fn;
        n->unitR = unitOf(result);
        n->narrow = !isLong(result);
        if (fn == CalendarFn::DateTod) {
            bool longForm = isLong(result);
            Checked d = ck.coerce(a[0], ck.types().elementary(longForm ? TK::LDate : TK::Date), a[0].loc, call.name.c_str());
            Checked t = ck.coerce(a[1], ck.types().elementary(longForm ? TK::LTod : TK::Tod), a[1].loc, call.name.c_str());
            if (!d.ok || !t.ok) return ck.bad(call.loc);
            n->in = {d.node, t.node};
            n->unitIn0 = unitOf(d.type->kind);
            n->unitIn1 = unitOf(t.type->kind);
        } else {
            for (auto& v : a) {
                if (!isIntegerArg(v) && !isBitArg(v)) return argError(ck, v, call.name, "the inputs must be integers");
                v = ck.settle(v);
                n->in.push_back(v.node);
            }
        }
        return makeResult(ck, n, ck.types().elementary(result), call, a);
    }, ConcatData{fn, result, fs}));
}

// SPLIT_*(IN, outputs...): outputs connected with '=>' by name, or given by position after IN.
// The outputs are the formals of the matching CONCAT_* (one name each).
void addSplit(Checker& ck, const char* name, SplitFn fn, TK input, std::span<const Formal> outputs) {
    struct SplitData { SplitFn fn; TK input; std::span<const Formal> outputs; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [fn, input, outputs] = self.data<SplitData>();
        Checked in;
        bool haveIn = false;
        std::vector<Checked> targets(outputs.size());
        std::vector<bool> given(outputs.size(), false);
        size_t positional = 0;
        for (size_t k = 0; k < call.args.size(); ++k) {
            const ast::Arg& arg = call.call->args[k];
            const std::string& nm = call.names[k];
            if (nm.empty()) {
                if (positional == 0) { in = call.args[k]; haveIn = true; }
                else if (positional - 1 < outputs.size()) { targets[positional - 1] = call.args[k]; given[positional - 1] = true; }
                else {
                    ck.error(diag::E0301, call.loc, fmt::format("too many arguments for '{}'", call.name));
                    return ck.bad(call.loc);
                }
                ++positional;
                continue;
            }
            if (nm == "IN") {
                if (arg.output) { ck.error(diag::E0303, arg.loc, fmt::format("'IN' is an input of '{}'; connect it with ':='", call.name)); return ck.bad(call.loc); }
                in = call.args[k];
                haveIn = true;
                continue;
            }
            size_t idx = outputs.size();
            for (size_t j = 0; j < outputs.size(); ++j)
                if (nm == outputs[j].names) idx = j;
            if (idx == outputs.size()) {
                ck.error(diag::E0302, arg.loc, fmt::format("'{}' has no parameter '{}'", call.name, arg.name));
                return ck.bad(call.loc);
            }
            if (!arg.output) {
                ck.error(diag::E0303, arg.loc, fmt::format("'{}' is an output of '{}'; connect it with '=>'", arg.name, call.name));
                return ck.bad(call.loc);
            }
            targets[idx] = call.args[k];
            given[idx] = true;
        }
        if (!haveIn) {
            ck.error(diag::E0301, call.loc, fmt::format("'{}' is missing its input 'IN'", call.name));
            return ck.bad(call.loc);
        }
        Checked x = ck.coerce(in, ck.types().elementary(input), in.loc, call.name.c_str());
        if (!x.ok) return x;
        auto* n = ck.pool().make<SplitNode>();
        n->in = x.node;
        n->fn = fn;
        n->unit = unitOf(input);
        n->off = ck.allocTemp(7 * sizeof(int64_t));
        size_t slot = 0;
        for (size_t j = 0; j < outputs.size(); ++j) {
            // SPLIT_TOD's fields are slots 0..3; the date forms start with year/month/day.
            slot = j;
            if (!given[j]) continue;
            const Checked& t = targets[j];
            if (!t.isPlace || t.readOnly) {
                ck.error(diag::E0206, t.loc, fmt::format("output '{}' of '{}' needs a variable that can be written", outputs[j].names, call.name));
                return ck.bad(call.loc);
            }
            if (!sema::isInteger(t.type->kind) && !sema::isBitString(t.type->kind)) {
                ck.error(diag::E0201, t.loc, fmt::format("output '{}' of '{}' must be an integer variable, not {}", outputs[j].names, call.name, sema::typeName(t.type)));
                return ck.bad(call.loc);
            }
            exec::Expr* field = sema::makeByRep<exec::FrameVar>(ck.pool(), Rep::I64, n->off + static_cast<uint32_t>(8 * slot));
            field->type = t.type;
            n->stores.push_back(ck.storeTo(t.node, t.type, field));
        }
        n->type = ck.types().voidType();
        Checked r;
        r.ok = true;
        r.loc = call.loc;
        r.type = ck.types().voidType();
        r.node = n;
        r.hasCall = true;
        return r;
    }, SplitData{fn, input, outputs}));
}

Checked checkDayOfWeek(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
    Family f = familyOf(a[0]);
    if (f != Family::Date && f != Family::Dt) return argError(ck, a[0], call.name, "the input must be a DATE, LDATE, DT or LDT");
    auto* n = ck.pool().make<DayOfWeekNode>(a[0].node, unitOf(a[0].type->kind));
    return makeResult(ck, n, ck.types().elementary(TK::USInt), call, a);
}

}  // namespace

void registerTime(Checker& ck) {
    // The operators `+` and `-` on dates and times of day use the very rule of
    // ADD_DT_TIME / SUB_DT_TIME (issue 8, defect 9). The names contain a space,
    // so no ST program can call them.
    struct DateOperatorData { TimeOp op; };
    for (TimeOp op : {TimeOp::Add, TimeOp::Sub})
        ck.addBuiltin(op == TimeOp::Add ? Checker::kDateAddOperator : Checker::kDateSubOperator, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
            const auto [op] = self.data<DateOperatorData>();
            return timeArithmetic(ck, call, op, call.args[0], call.args[1]);
        }, DateOperatorData{op}));
    addNamedArith(ck, "ADD_TIME", TimeOp::Add, TK::Time, TK::Time);
    addNamedArith(ck, "ADD_LTIME", TimeOp::Add, TK::LTime, TK::LTime);
    addNamedArith(ck, "ADD_TOD_TIME", TimeOp::Add, TK::Tod, TK::Time);
    addNamedArith(ck, "ADD_LTOD_LTIME", TimeOp::Add, TK::LTod, TK::LTime);
    addNamedArith(ck, "ADD_DT_TIME", TimeOp::Add, TK::Dt, TK::Time);
    addNamedArith(ck, "ADD_LDT_LTIME", TimeOp::Add, TK::LDt, TK::LTime);
    addNamedArith(ck, "SUB_TIME", TimeOp::Sub, TK::Time, TK::Time);
    addNamedArith(ck, "SUB_LTIME", TimeOp::Sub, TK::LTime, TK::LTime);
    addNamedArith(ck, "SUB_DATE_DATE", TimeOp::Sub, TK::Date, TK::Date);
    addNamedArith(ck, "SUB_LDATE_LDATE", TimeOp::Sub, TK::LDate, TK::LDate);
    addNamedArith(ck, "SUB_TOD_TIME", TimeOp::Sub, TK::Tod, TK::Time);
    addNamedArith(ck, "SUB_LTOD_LTIME", TimeOp::Sub, TK::LTod, TK::LTime);
    addNamedArith(ck, "SUB_TOD_TOD", TimeOp::Sub, TK::Tod, TK::Tod);
    addNamedArith(ck, "SUB_LTOD_LTOD", TimeOp::Sub, TK::LTod, TK::LTod);
    addNamedArith(ck, "SUB_DT_TIME", TimeOp::Sub, TK::Dt, TK::Time);
    addNamedArith(ck, "SUB_LDT_LTIME", TimeOp::Sub, TK::LDt, TK::LTime);
    addNamedArith(ck, "SUB_DT_DT", TimeOp::Sub, TK::Dt, TK::Dt);
    addNamedArith(ck, "SUB_LDT_LDT", TimeOp::Sub, TK::LDt, TK::LDt);
    addNamedArith(ck, "MUL_TIME", TimeOp::Mul, TK::Time, TK::Void);
    addNamedArith(ck, "MUL_LTIME", TimeOp::Mul, TK::LTime, TK::Void);
    addNamedArith(ck, "DIV_TIME", TimeOp::Div, TK::Time, TK::Void);
    addNamedArith(ck, "DIV_LTIME", TimeOp::Div, TK::LTime, TK::Void);

    // The formals and outputs are static: the built-ins keep pointing at them.
    static constexpr Formal kDateTodFormals[] = {{"IN1|DATE"}, {"IN2|TOD"}};
    static constexpr Formal kDateFormals[] = {{"YEAR"}, {"MONTH"}, {"DAY"}};
    static constexpr Formal kTodFormals[] = {{"HOUR"}, {"MINUTE"}, {"SECOND"}, {"MILLISECOND"}};
    static constexpr Formal kDtFormals[] = {{"YEAR"}, {"MONTH"}, {"DAY"}, {"HOUR"}, {"MINUTE"}, {"SECOND"}, {"MILLISECOND"}};
    addConcat(ck, "CONCAT_DATE_TOD", CalendarFn::DateTod, TK::Dt, kDateTodFormals);
    addConcat(ck, "CONCAT_LDATE_LTOD", CalendarFn::DateTod, TK::LDt, kDateTodFormals);
    addConcat(ck, "CONCAT_DATE", CalendarFn::Date, TK::Date, kDateFormals);
    addConcat(ck, "CONCAT_LDATE", CalendarFn::Date, TK::LDate, kDateFormals);
    addConcat(ck, "CONCAT_TOD", CalendarFn::Tod, TK::Tod, kTodFormals);
    addConcat(ck, "CONCAT_LTOD", CalendarFn::Tod, TK::LTod, kTodFormals);
    addConcat(ck, "CONCAT_DT", CalendarFn::Dt, TK::Dt, kDtFormals);
    addConcat(ck, "CONCAT_LDT", CalendarFn::Dt, TK::LDt, kDtFormals);

    addSplit(ck, "SPLIT_DATE", SplitFn::Date, TK::Date, kDateFormals);
    addSplit(ck, "SPLIT_LDATE", SplitFn::Date, TK::LDate, kDateFormals);
    addSplit(ck, "SPLIT_TOD", SplitFn::Tod, TK::Tod, kTodFormals);
    addSplit(ck, "SPLIT_LTOD", SplitFn::Tod, TK::LTod, kTodFormals);
    addSplit(ck, "SPLIT_DT", SplitFn::Dt, TK::Dt, kDtFormals);
    addSplit(ck, "SPLIT_LDT", SplitFn::Dt, TK::LDt, kDtFormals);
    ck.addBuiltin("DAY_OF_WEEK", checkDayOfWeek);
}

void registerClock(Checker& ck) {
    // Internal: the timer blocks of stdlib/st/timers.st read the PLC clock through these.
    ck.addBuiltin("__PLC_TIME", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {}, a)) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<PlcTimeMsNode>(), ck.types().elementary(TK::Time), call, a, false);
    });
    // CODESYS/TwinCAT TIME(): the PLC time since start, in milliseconds;
    // LTIME(): the same in nanoseconds (decision 0435). Operators IEC 61131-3
    // does not have.
    ck.addBuiltin("TIME", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (ck.refusedByStrict(diag::E0105, call.loc, "TIME() is a CODESYS/TwinCAT operator, not IEC 61131-3 (--strict)")) return ck.bad(call.loc);
        if (!bindFixed(ck, call, {}, a)) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<PlcTimeMsNode>(), ck.types().elementary(TK::Time), call, a, false);
    });
    ck.addBuiltin("LTIME", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (ck.refusedByStrict(diag::E0105, call.loc, "LTIME() is a CODESYS/TwinCAT operator, not IEC 61131-3 (--strict)")) return ck.bad(call.loc);
        if (!bindFixed(ck, call, {}, a)) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<PlcTimeNsNode>(), ck.types().elementary(TK::LTime), call, a, false);
    });
    ck.addBuiltin("__PLC_LTIME", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {}, a)) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<PlcTimeNsNode>(), ck.types().elementary(TK::LTime), call, a, false);
    });
    ck.addBuiltin("__PLC_LTIME_MS", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {}, a)) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<PlcTimeWholeMsNode>(), ck.types().elementary(TK::LTime), call, a, false);
    });
}

}  // namespace strun::stdlib::bind
