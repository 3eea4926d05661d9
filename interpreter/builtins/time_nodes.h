// Evaluator nodes of the time and date functions. Values are combined in
// nanoseconds (stdlib/value_encodings.h gives each type's unit) and brought
// back to the result's encoding, so every mix of short and long types goes
// through one path.
#pragma once

#include <vector>

#include "interpreter/exec/operator_nodes.h"
#include "stdlib/calendar.h"
#include "stdlib/conversions.h"

namespace strun::stdlib::bind {

using exec::Ctx;
using exec::Expr;

// a +- b. Units are ns per unit of each encoding. A TOD result is taken
// modulo one day, a date result is floored to its unit, then the result
// wraps at its width (decision 0053).
struct TimeCombineNode final : Expr {
    Expr *a, *b;
    int64_t unitA, unitB, unitR;
    bool subtract, dayModulo, floorResult;
    int bits;
    bool isSigned;
    int64_t i(Ctx& c) override {
        uint64_t x = static_cast<uint64_t>(a->i(c)) * static_cast<uint64_t>(unitA);
        uint64_t y = static_cast<uint64_t>(b->i(c)) * static_cast<uint64_t>(unitB);
        int64_t r = static_cast<int64_t>(subtract ? x - y : x + y);
        if (dayModulo) r = stdlib::floorMod(r, stdlib::kNsPerDay);
        r = floorResult ? stdlib::floorDiv(r, unitR) : r / unitR;
        return static_cast<int64_t>(stdlib::wrapToWidth(static_cast<uint64_t>(r), bits, isSigned));
    }
};

// Duration * or / a number, in the duration's own unit. Integer factors
// wrap like integer arithmetic; a zero integer divisor reports DIV_BY_ZERO
// and uses 1; REAL factors round to nearest (ties to even).
struct TimeScaleNode final : Expr {
    Expr *t, *k;
    bool realFactor, divide;
    bool isUnsigned = false;  // a TwinCAT TIME/LTIME (decisions 0367, 0389): the duration's bits unsigned
    int bits;
    exec::Site site;
    int64_t i(Ctx& c) override {
        int64_t v = t->i(c);
        if (realFactor) {
            double f = k->f(c);
            double tv = isUnsigned ? static_cast<double>(static_cast<uint64_t>(v)) : static_cast<double>(v);
            double r = divide ? tv / f : tv * f;
            return static_cast<int64_t>(stdlib::realToInteger(r, bits, !isUnsigned));
        }
        int64_t n = k->i(c);
        if (divide) {
            if (__builtin_expect(n == 0, 0)) {
                exec::reportDivByZero(c, site);
                n = 1;
            }
            if (isUnsigned && n > 0) return static_cast<int64_t>(static_cast<uint64_t>(v) / static_cast<uint64_t>(n));
            if (n == -1) return static_cast<int64_t>(stdlib::wrapToWidth(0 - static_cast<uint64_t>(v), bits, !isUnsigned));
            return static_cast<int64_t>(stdlib::wrapToWidth(static_cast<uint64_t>(v / n), bits, !isUnsigned));
        }
        return static_cast<int64_t>(stdlib::wrapToWidth(static_cast<uint64_t>(v) * static_cast<uint64_t>(n), bits, !isUnsigned));
    }
};

enum class CalendarFn : uint8_t { Date, Tod, Dt, DateTod };

// CONCAT_DATE / _TOD / _DT / _DATE_TOD and their L-forms. Invalid fields
// give 0 (1970-01-01, 00:00): IEC leaves them an error, CODESYS returns 0.
struct ConcatCalendarNode final : Expr {
    CalendarFn fn;
    std::vector<Expr*> in;
    int64_t unitR;        // ns per unit of the result
    int64_t unitIn0 = 1;  // CONCAT_DATE_TOD: units of the date and the TOD input
    int64_t unitIn1 = 1;
    bool narrow;          // 32-bit result (DATE, TOD, DT): must fit uint32
    int64_t i(Ctx& c) override {
        stdlib::Result<int64_t> r = stdlib::Result<int64_t>::failure("unset");
        auto v = [&](size_t k) { return in[k]->i(c); };
        switch (fn) {
            case CalendarFn::Date: r = stdlib::concatDate(v(0), v(1), v(2)); break;
            case CalendarFn::Tod: r = stdlib::concatTimeOfDay(v(0), v(1), v(2), v(3)); break;
            case CalendarFn::Dt: r = stdlib::concatDateTime(v(0), v(1), v(2), v(3), v(4), v(5), v(6)); break;
            case CalendarFn::DateTod: r = stdlib::concatDateAndTimeOfDay(v(0) * unitIn0, v(1) * unitIn1); break;
        }
        if (!r.ok()) return 0;
        int64_t out = stdlib::floorDiv(r.value(), unitR);
        if (narrow && (out < 0 || out > 0xFFFFFFFFll)) return 0;
        return out;
    }
};

enum class SplitFn : uint8_t { Date, Tod, Dt };

// SPLIT_DATE / _TOD / _DT (and L-forms): computes the fields into int64
// slots of a caller-frame temporary, then runs the stores to the connected outputs.
struct SplitNode final : Expr {
    Expr* in = nullptr;
    SplitFn fn = SplitFn::Date;
    int64_t unit = 1;
    uint32_t off = 0;
    std::vector<exec::Stmt*> stores;
    int64_t i(Ctx& c) override {
        int64_t ns = static_cast<int64_t>(static_cast<uint64_t>(in->i(c)) * static_cast<uint64_t>(unit));
        int64_t fields[7] = {};
        if (fn == SplitFn::Tod) {
            stdlib::TimeOfDayParts p = stdlib::splitTimeOfDay(ns);
            fields[0] = p.hour;
            fields[1] = p.minute;
            fields[2] = p.second;
            fields[3] = p.millisecond();
        } else {
            stdlib::DateTimeParts p = stdlib::splitDateTime(ns);
            int64_t all[7] = {p.year, p.month, p.day, p.hour, p.minute, p.second, p.millisecond()};
            for (int k = 0; k < 7; ++k) fields[k] = all[k];
        }
        std::memcpy(c.frame + off, fields, sizeof fields);
        for (exec::Stmt* s : stores) s->exec(c);
        return 0;
    }
};

// DAY_OF_WEEK: 0 = Sunday .. 6 = Saturday.
struct DayOfWeekNode final : Expr {
    Expr* in;
    int64_t unit;
    DayOfWeekNode(Expr* x, int64_t u) : in(x), unit(u) {}
    int64_t i(Ctx& c) override {
        int64_t ns = static_cast<int64_t>(static_cast<uint64_t>(in->i(c)) * static_cast<uint64_t>(unit));
        return stdlib::dayOfWeek(stdlib::floorDiv(ns, stdlib::kNsPerDay));
    }
};

// The PLC clock of the running task (virtual or real), read by the ST timer
// blocks: TIME in whole milliseconds (like CODESYS TIME()), LTIME in ns.
struct PlcTimeMsNode final : Expr {
    int64_t i(Ctx& c) override {
        int64_t ms = stdlib::floorDiv(c.m->handler->currentTime(), stdlib::kNsPerMs);
        return static_cast<int64_t>(stdlib::wrapToWidth(static_cast<uint64_t>(ms), 32, true));
    }
};

struct PlcTimeNsNode final : Expr {
    int64_t i(Ctx& c) override { return c.m->handler->currentTime(); }
};

// LTIME floored to whole milliseconds (RTC: immune to the statement-cost
// jitter of the virtual clock inside one task activation).
struct PlcTimeWholeMsNode final : Expr {
    int64_t i(Ctx& c) override {
        return stdlib::floorDiv(c.m->handler->currentTime(), stdlib::kNsPerMs) * stdlib::kNsPerMs;
    }
};

}  // namespace strun::stdlib::bind
