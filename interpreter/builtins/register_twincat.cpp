// TwinCAT library functions application and test code calls (Tc2_System):
// ADSLOGSTR, ADSLOGDINT, ADSLOGLREAL write their message to stderr (the
// TwinCAT error list's stand-in), one line each, with the argument in place
// of the format's %s / %d / %f. They return 0 like TwinCAT.
#include <cstdio>
#include <cstring>

#include "interpreter/builtins/bind_support.h"
#include "interpreter/builtins/register_groups.h"
#include "interpreter/builtins/string_nodes.h"

namespace strun::stdlib::bind {

namespace {

enum class LogArg : uint8_t { String, Dint, Lreal };

struct AdsLogNode final : exec::Expr {
    Expr* format;
    Expr* arg;
    LogArg kind;
    AdsLogNode(Expr* f, Expr* a, LogArg k) : format(f), arg(a), kind(k) {}
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
        // The first %x of the format takes the value (TwinCAT: %s, %d, %f).
        size_t at = f.find('%');
        std::fputs("ADSLOG: ", stderr);
        if (at == std::string_view::npos || at + 1 >= f.size()) {
            std::fwrite(f.data(), 1, f.size(), stderr);
        } else {
            std::fwrite(f.data(), 1, at, stderr);
            std::fwrite(value.data(), 1, value.size(), stderr);
            std::fwrite(f.data() + at + 2, 1, f.size() - at - 2, stderr);
        }
        std::fputc('\n', stderr);
        return 0;
    }
};

void addAdsLog(Checker& ck, const char* name, LogArg kind) {
    ck.addBuiltin(name, [kind](Checker& ck, CallArgs& call) -> Checked {
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
        auto* n = ck.pool().make<AdsLogNode>(format.node, arg.node, kind);
        return makeResult(ck, n, ck.types().elementary(TK::DInt), call, a, false);
    });
}

}  // namespace

void registerTwinCat(Checker& ck) {
    addAdsLog(ck, "ADSLOGSTR", LogArg::String);
    addAdsLog(ck, "ADSLOGDINT", LogArg::Dint);
    addAdsLog(ck, "ADSLOGLREAL", LogArg::Lreal);
}

}  // namespace strun::stdlib::bind
