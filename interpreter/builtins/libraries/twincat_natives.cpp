// Native functions of the Beckhoff libraries, registered only for projects
// that name one of them (decision 0220):
// Tc2_System: ADSLOGSTR, ADSLOGDINT, ADSLOGLREAL write one line to stderr:
// `ADSLOG <PLC time> <task> <kind>: <message>`, the message being the format
// with its first %x replaced by the argument (TwinCAT: %s, %d, %f); they
// return 0 like TwinCAT. F_GetTaskTime (the task's start) and
// F_GetSystemTime (now) count 100 ns since 1601 from the PLC calendar
// (--start on the virtual clock); GETCURTASKINDEXEX is the running task's
// 1-based place in strun's task list.
// Tc2_EtherCAT: distributed-clock time (F_GetCurDcTaskTime64,
// F_GetCurDcTickTime64, DCTIME64_TO_STRING, STRING_TO_DCTIME64), decision 0095.
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "stdlib/calendar.h"

#include "interpreter/builtins/bind_support.h"
#include "interpreter/builtins/libraries/library_natives.h"
#include "runtime/duration_text.h"
#include "interpreter/builtins/string_nodes.h"
#include "interpreter/exec/value_nodes.h"

namespace strun::stdlib::bind {

namespace {

enum class LogArg : uint8_t { String, Dint, Lreal };

struct AdsLogNode final : exec::Expr {
    Expr* maskExpr;
    Expr* format;
    Expr* arg;
    LogArg kind;
    exec::Site site;
    AdsLogNode(Expr* m, Expr* f, Expr* a, LogArg k, exec::Site s) : maskExpr(m), format(f), arg(a), kind(k), site(s) {}
    int64_t i(Ctx& c) override {
        std::string_view f = viewOf<char>(format, c);
        char number[64];
        std::string_view value;
        if (kind == LogArg::String) {
            value = viewOf<char>(arg, c);
        } else {
            int n = kind == LogArg::Dint ? std::snprintf(number, sizeof number, "%lld", static_cast<long long>(arg->i(c)))
                                         : std::snprintf(number, sizeof number, "%f", arg->f(c));
            value = std::string_view(number, n > 0 ? static_cast<size_t>(n) : 0);
        }
        // The message: the first %x of the format takes the value (TwinCAT: %s, %d, %f).
        std::string message;
        const size_t at = f.find('%');
        if (at == std::string_view::npos || at + 1 >= f.size()) {
            message.assign(f);
        } else {
            message.assign(f.substr(0, at));
            message.append(value);
            message.append(f.substr(at + 2));
        }
        const uint64_t mask = static_cast<uint64_t>(maskExpr->i(c));
        const char* severity = (mask & 0x04) ? "error" : (mask & 0x02) ? "warning" : (mask & 0x01) ? "hint" : "log";
        // ADSLOG <PLC time> <task> <severity>: <message>
        rt::AttentionHandler* h = c.m->handler;
        std::string line = "ADSLOG ";
        rt::appendDuration(line, h ? h->currentTime() : c.m->time());
        const std::string task = h ? h->currentTaskName() : std::string();
        line += ' ';
        line += task.empty() ? "-" : task;
        line += ' ';
        line += severity;
        line += ": ";
        line += message;
        line += '\n';
        std::fwrite(line.data(), 1, line.size(), stderr);
        if (h) exec::reportLog(c, site, std::string(severity) + ": " + message);
        return 0;
    }
};

void addAdsLog(Checker& ck, const char* name, LogArg kind) {
    struct AdsLogData { LogArg kind; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [kind] = self.data<AdsLogData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"MSGCTRLMASK"}, {"MSGFMTSTR"}, {kind == LogArg::String ? "STRARG" : kind == LogArg::Dint ? "DINTARG" : "LREALARG"}}, a))
            return ck.bad(call.loc);
        Checked mask = ck.coerce(a[0], ck.types().elementary(TK::DWord), a[0].loc, call.name.c_str());
        Checked format = a[1];
        if (!mask.ok) return mask;
        if (!isStringArg(format, false)) return argError(ck, format, call.name, "msgFmtStr must be a STRING");
        Checked arg = a[2];
        if (kind == LogArg::String && !isStringArg(arg, false)) return argError(ck, arg, call.name, "strArg must be a STRING");
        if (kind != LogArg::String) {
            arg = ck.coerce(arg, ck.types().elementary(kind == LogArg::Dint ? TK::DInt : TK::LReal), arg.loc, call.name.c_str());
            if (!arg.ok) return arg;
        }
        auto* n = ck.pool().make<AdsLogNode>(mask.node, format.node, arg.node, kind, ck.site(call.loc));
        return makeResult(ck, n, ck.types().elementary(TK::DInt), call, a, false);
    }, AdsLogData{kind}));
}

// The DC clock counts ns since 2000-01-01-00:00:00; FILETIME (F_GetTaskTime)
// counts 100 ns since 1601-01-01. Both from calendar ns since 1970.
constexpr int64_t kDcEpochFrom1970 = 946'684'800LL * stdlib::kNsPerSecond;
constexpr int64_t kFileTimeEpochTo1970 = 11'644'473'600LL * 10'000'000LL;

enum class Clock : uint8_t { TaskFileTime, SystemFileTime, TaskDc, TickDc, TaskStartPlc };

struct TwinCatClockNode final : exec::Expr {
    Clock which;
    explicit TwinCatClockNode(Clock w) : which(w) {}
    int64_t i(Ctx& c) override {
        rt::AttentionHandler& h = *c.m->handler;
        // PLC time (ns) at which the running activation started: the simulated
        // axes of Tc2_MC2 advance to it, as an NC task's cycle would.
        if (which == Clock::TaskStartPlc) return h.currentTime() - (h.calendarNanos() - h.taskStartCalendarNanos());
        int64_t calendar = which == Clock::TickDc || which == Clock::SystemFileTime ? h.calendarNanos() : h.taskStartCalendarNanos();
        if (which == Clock::TaskFileTime || which == Clock::SystemFileTime) return calendar / 100 + kFileTimeEpochTo1970;
        int64_t dc = calendar - kDcEpochFrom1970;
        // A calendar before 2000 (the default --start is 1970): the DC clock
        // starts at 0 with the PLC, so differences still measure PLC time.
        return dc >= 0 ? dc : (which == Clock::TickDc ? h.currentTime() : calendar - (h.calendarNanos() - h.currentTime()));
    }
};

// 'YYYY-MM-DD-hh:mm:ss.nnnnnnnnn' of a DC time (T_DCTIME64, unsigned ns since 2000).
struct DcTimeToStringNode final : exec::Expr {
    Expr* in;
    uint32_t off;
    DcTimeToStringNode(Expr* e, uint32_t o) : in(e), off(o) {}
    uint8_t* addr(Ctx& c) override {
        auto dc = static_cast<uint64_t>(in->i(c));
        // Seconds and nanoseconds apart: 2^64 ns since 2000 do not fit int64 ns since 1970.
        auto seconds = static_cast<int64_t>(dc / 1'000'000'000ULL) + kDcEpochFrom1970 / stdlib::kNsPerSecond;
        auto ns = static_cast<int64_t>(dc % 1'000'000'000ULL);
        stdlib::CivilDate d = stdlib::civilFromDays(stdlib::floorDiv(seconds, stdlib::kSecondsPerDay));
        int64_t sod = stdlib::floorMod(seconds, stdlib::kSecondsPerDay);
        char text[48];
        int n = std::snprintf(text, sizeof text, "%04lld-%02d-%02d-%02d:%02d:%02d.%09lld", static_cast<long long>(d.year), d.month, d.day,
                              static_cast<int>(sod / 3600), static_cast<int>(sod / 60 % 60), static_cast<int>(sod % 60), static_cast<long long>(ns));
        return writeString<char>(c, off, 29, std::string_view(text, n > 0 ? static_cast<size_t>(n) : 0));
    }
};

// STRING_TO_DCTIME64: the same format back ('.' or ':' before the
// nanoseconds, fewer digits allowed); text that is no such date gives 0.
struct StringToDcTimeNode final : exec::Expr {
    Expr* in;
    explicit StringToDcTimeNode(Expr* e) : in(e) {}
    int64_t i(Ctx& c) override {
        std::string_view view = viewOf<char>(in, c);
        char text[64];
        size_t len = std::min<size_t>(view.size(), sizeof text - 1);
        std::memcpy(text, view.data(), len);
        text[len] = 0;
        long long y = 0;
        int mo = 0, d = 0, h = 0, mi = 0, s = 0, fracStart = 0, fracEnd = 0;
        char sep = 0;
        if (std::sscanf(text, "%4lld-%2d-%2d-%2d:%2d:%2d%c%n%*9[0-9]%n", &y, &mo, &d, &h, &mi, &s, &sep, &fracStart, &fracEnd) < 6) return 0;
        auto date = stdlib::concatDateTime(y, mo, d, h, mi, s, 0);
        if (!date.ok()) return 0;
        int64_t frac = 0;
        if ((sep == '.' || sep == ':') && fracEnd > fracStart) {
            int digits = fracEnd - fracStart;
            for (int k = fracStart; k < fracEnd; ++k) frac = frac * 10 + (text[k] - '0');
            for (; digits < 9; ++digits) frac *= 10;
        }
        // Before 2000 there is no DC time. From 2000 on, unsigned: the
        // fraction of a date late in 2262 takes the sum past INT64_MAX, which
        // a T_DCTIME64 (ULINT) holds (signed, it overflowed).
        if (date.value() < kDcEpochFrom1970) return 0;
        return static_cast<int64_t>(static_cast<uint64_t>(date.value() - kDcEpochFrom1970) + static_cast<uint64_t>(frac));
    }
};

void addClock(Checker& ck, const char* name, Clock which) {
    struct ClockData { Clock which; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [which] = self.data<ClockData>();
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {}, a)) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<TwinCatClockNode>(which), ck.types().elementary(TK::ULInt), call, a, false);
    }, ClockData{which}));
}

struct TaskIndexNode final : exec::Expr {
    int64_t i(Ctx& c) override { return c.m->handler ? c.m->handler->currentTaskIndex() : 0; }
};

// F_CheckMemoryArea(pData, nSize): E_TcMemoryArea Dynamic (2) for a block of
// the __NEW heap, Static (1) for the project's other memory (its frames
// included: strun does not tell them apart), Unknown (0) otherwise, for a
// null address, or for a size of 0.
struct MemoryAreaNode final : exec::Expr {
    exec::Expr* data;
    exec::Expr* size;
    MemoryAreaNode(exec::Expr* d, exec::Expr* s) : data(d), size(s) {}
    int64_t i(Ctx& c) override {
        const auto* p = reinterpret_cast<const uint8_t*>(static_cast<intptr_t>(data->i(c)));
        const auto n = static_cast<size_t>(static_cast<uint32_t>(size->i(c)));
        if (!p || n == 0) return 0;
        if (c.m->memory.isDynamic(p, n)) return 2;
        return c.m->memory.contains(p, n) ? 1 : 0;
    }
};

}  // namespace

void registerTc2SystemNatives(Checker& ck) {
    addClock(ck, "F_GETTASKTIME", Clock::TaskFileTime);
    addClock(ck, "F_GETSYSTEMTIME", Clock::SystemFileTime);
    ck.addBuiltin("GETCURTASKINDEXEX", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {}, a)) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<TaskIndexNode>(), ck.types().elementary(TK::Byte), call, a, false);
    });
    ck.addBuiltin("F_STRUN_MEMORYAREA", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"PDATA"}, {"NSIZE"}}, a)) return ck.bad(call.loc);
        Checked address = ck.coerce(a[0], ck.types().elementary(TK::ULInt), a[0].loc, call.name.c_str());
        Checked size = ck.coerce(a[1], ck.types().elementary(TK::UDInt), a[1].loc, call.name.c_str());
        if (!address.ok || !size.ok) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<MemoryAreaNode>(address.node, size.node), ck.types().elementary(TK::UDInt), call, a, false);
    });
    addAdsLog(ck, "ADSLOGSTR", LogArg::String);
    addAdsLog(ck, "ADSLOGDINT", LogArg::Dint);
    addAdsLog(ck, "ADSLOGLREAL", LogArg::Lreal);
    registerTc2SystemFileNatives(ck);
}

void registerTc2Mc2Natives(Checker& ck) {
    ck.addBuiltin("F_STRUN_TASKSTARTNANOS", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {}, a)) return ck.bad(call.loc);
        return makeResult(ck, ck.pool().make<TwinCatClockNode>(Clock::TaskStartPlc), ck.types().elementary(TK::LInt), call, a, false);
    });
}

void registerTc2EtherCatNatives(Checker& ck) {
    addClock(ck, "F_GETCURDCTASKTIME64", Clock::TaskDc);
    addClock(ck, "F_GETCURDCTICKTIME64", Clock::TickDc);
    ck.addBuiltin("DCTIME64_TO_STRING", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
        Checked in = ck.coerce(a[0], ck.types().elementary(TK::ULInt), a[0].loc, call.name.c_str());
        if (!in.ok) return in;
        const Type* t = ck.types().string(29, false);
        auto* n = ck.pool().make<DcTimeToStringNode>(in.node, ck.allocTemp(t->size));
        return makeResult(ck, n, t, call, a, false);
    });
    ck.addBuiltin("STRING_TO_DCTIME64", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"IN"}}, a)) return ck.bad(call.loc);
        if (!isStringArg(a[0], false)) return argError(ck, a[0], call.name, "in must be a STRING");
        return makeResult(ck, ck.pool().make<StringToDcTimeNode>(a[0].node), ck.types().elementary(TK::ULInt), call, a, false);
    });
}

}  // namespace strun::stdlib::bind
