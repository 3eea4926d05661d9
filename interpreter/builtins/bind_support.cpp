#include "interpreter/builtins/bind_support.h"

#include <algorithm>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "interpreter/exec/value_nodes.h"
#include "interpreter/sema/parameter_named_twice.h"
#include "stdlib/string_functions.h"

namespace strun::stdlib::bind {

namespace {

bool matchesFormal(const char* names, const std::string& upperName) {
    std::string_view all(names);
    while (!all.empty()) {
        size_t bar = all.find('|');
        std::string_view one = all.substr(0, bar);
        if (one == upperName) return true;
        if (bar == std::string_view::npos) break;
        all.remove_prefix(bar + 1);
    }
    return false;
}

std::string firstName(const char* names) {
    std::string_view all(names);
    return std::string(all.substr(0, all.find('|')));
}

bool rejectOutputs(Checker& ck, CallArgs& call) {
    for (size_t k = 0; k < call.args.size(); ++k) {
        const ast::Arg& a = call.call->args[k];
        if (a.output) {
            ck.error(diag::E0302, a.loc, fmt::format("'{}' has no output '{}'", call.name, a.name));
            return false;
        }
    }
    return true;
}

bool isScalarConst(const Checked& a) {
    if (!a.isConst || !a.type) return false;
    if (sema::isIntRep(a.type) || sema::isRealRep(a.type)) return true;
    return exec::nodeCast<exec::ConstBytes>(a.node) != nullptr;
}

}  // namespace

bool bindFixed(Checker& ck, CallArgs& call, std::initializer_list<Formal> formals, std::vector<Checked>& out) {
    if (!rejectOutputs(ck, call)) return false;
    const size_t n = formals.size();
    const Formal* f = formals.begin();
    out.assign(n, Checked{});
    std::vector<bool> given(n, false), named(n, false);
    for (size_t k = 0; k < call.args.size(); ++k) {
        const ast::Arg& a = call.call->args[k];
        size_t idx = n;
        if (call.names[k].empty()) {
            // By its position in the call, also after named ones (decision 0204).
            if (k >= n) {
                ck.error(diag::E0301, call.loc, fmt::format("too many arguments for '{}' (it takes {})", call.name, n));
                return false;
            }
            idx = k;
        } else {
            for (size_t j = 0; j < n; ++j)
                if (matchesFormal(f[j].names, call.names[k])) idx = j;
            if (idx == n) {
                ck.error(diag::E0302, a.loc, fmt::format("'{}' has no parameter '{}'", call.name, a.name));
                return false;
            }
        }
        if (given[idx]) {
            // Named twice: as for a user POU, W0044 and the last value (decision 0426);
            // a positional argument landing on a given input stays an error (0204).
            if (named[idx] && !call.names[k].empty()) {
                if (!sema::rebindNamedTwice(ck, call, a.loc, firstName(f[idx].names), out[idx], call.args[k])) return false;
                continue;
            }
            ck.error(diag::E0302, a.loc, fmt::format("parameter '{}' of '{}' given twice", firstName(f[idx].names), call.name));
            return false;
        }
        given[idx] = true;
        named[idx] = !call.names[k].empty();
        out[idx] = call.args[k];
    }
    for (size_t j = 0; j < n; ++j)
        if (!given[j]) {
            ck.error(diag::E0301, call.loc, fmt::format("'{}' needs {} input(s); '{}' is missing", call.name, n, firstName(f[j].names)));
            return false;
        }
    return true;
}

bool bindExtensible(Checker& ck, CallArgs& call, std::initializer_list<Formal> leading, const char* prefix, int firstIndex,
                    size_t minCount, std::vector<Checked>& out) {
    if (!rejectOutputs(ck, call)) return false;
    const size_t nLead = leading.size();
    const Formal* f = leading.begin();
    std::vector<Checked> lead(nLead);
    std::vector<bool> leadGiven(nLead, false);
    std::map<long, Checked> named;
    std::vector<Checked> positional;
    const std::string pre = prefix;
    for (size_t k = 0; k < call.args.size(); ++k) {
        const ast::Arg& a = call.call->args[k];
        const std::string& nm = call.names[k];
        if (nm.empty()) {
            positional.push_back(call.args[k]);
            continue;
        }
        bool placed = false;
        for (size_t j = 0; j < nLead && !placed; ++j)
            if (matchesFormal(f[j].names, nm)) {
                if (leadGiven[j]) {
                    if (!sema::rebindNamedTwice(ck, call, a.loc, firstName(f[j].names), lead[j], call.args[k])) return false;
                } else {
                    lead[j] = call.args[k];
                }
                leadGiven[j] = true;
                placed = true;
            }
        if (placed) continue;
        bool numbered = nm.size() > pre.size() && nm.compare(0, pre.size(), pre) == 0 && nm.size() - pre.size() <= 4 &&
                        std::all_of(nm.begin() + static_cast<long>(pre.size()), nm.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (!numbered) {
            ck.error(diag::E0302, a.loc, fmt::format("'{}' has no parameter '{}'", call.name, a.name));
            return false;
        }
        long index = std::stol(nm.substr(pre.size())) - firstIndex;
        if (index < 0) {
            ck.error(diag::E0302, a.loc, fmt::format("'{}' has no parameter '{}'", call.name, a.name));
            return false;
        }
        if (auto again = named.find(index); again != named.end()) {
            if (!sema::rebindNamedTwice(ck, call, a.loc, fmt::format("{}{}", pre, index + firstIndex), again->second, call.args[k]))
                return false;
            continue;
        }
        named[index] = call.args[k];
    }
    // Positional arguments fill the leading formals first, then IN<first>, IN<first+1>, ...
    size_t p = 0;
    for (size_t j = 0; j < nLead; ++j)
        if (!leadGiven[j]) {
            if (p >= positional.size()) {
                ck.error(diag::E0301, call.loc, fmt::format("'{}' is missing its input '{}'", call.name, firstName(f[j].names)));
                return false;
            }
            lead[j] = positional[p++];
        }
    out = lead;
    if (!named.empty() && p < positional.size()) {
        ck.error(diag::E0302, call.loc, fmt::format("'{}': give the inputs either all by position or all by name", call.name));
        return false;
    }
    if (!named.empty()) {
        long expect = 0;
        for (auto& [index, value] : named) {
            if (index != expect) {
                ck.error(diag::E0301, call.loc, fmt::format("'{}' is missing its input '{}{}'", call.name, pre, expect + firstIndex));
                return false;
            }
            out.push_back(value);
            ++expect;
        }
    } else {
        for (; p < positional.size(); ++p) out.push_back(positional[p]);
    }
    if (out.size() - nLead < minCount) {
        ck.error(diag::E0301, call.loc, fmt::format("'{}' needs at least {} inputs", call.name, minCount + nLead));
        return false;
    }
    return true;
}

bool isIntegerArg(const Checked& a) { return a.untypedInt || sema::isInteger(a.type->kind); }
bool isBitArg(const Checked& a) { return !a.untypedInt && sema::isBitString(a.type->kind); }
bool isNumArg(const Checked& a) { return a.untypedInt || a.untypedReal || sema::isNumeric(a.type->kind); }
bool isStringArg(const Checked& a, bool wide) { return a.type && a.type->kind == (wide ? TK::WString : TK::String); }

const Type* stringResultType(Checker& ck, bool wide, int64_t maxLen) {
    maxLen = std::clamp<int64_t>(maxLen, 1, stdlib::kMaxStringLength);
    return ck.types().string(static_cast<uint32_t>(maxLen), wide);
}

const Type* commonTypeOf(Checker& ck, std::vector<Checked>& args, const ast::Loc& loc, const std::string& fn) {
    bool anyString = false;
    for (const auto& a : args) anyString = anyString || sema::isStringType(a.type->kind);
    if (anyString) {
        TK kind = args[0].type->kind;
        int64_t maxLen = 0;
        for (const auto& a : args) {
            if (a.type->kind != kind) {
                ck.error(diag::E0202, a.loc, fmt::format("{}: cannot mix {} and {}", fn, sema::typeName(args[0].type), sema::typeName(a.type)));
                return nullptr;
            }
            maxLen = std::max<int64_t>(maxLen, a.type->maxLen);
        }
        return stringResultType(ck, kind == TK::WString, maxLen);
    }
    if (allUntyped(args)) {
        bool real = false, wide = false;
        for (const auto& a : args) {
            real = real || a.untypedReal;
            wide = wide || a.constInt < std::numeric_limits<int32_t>::min() || a.constInt > std::numeric_limits<int32_t>::max();
        }
        return ck.types().elementary(real ? TK::LReal : wide ? TK::LInt : TK::DInt);
    }
    Checked probe = args[0];
    for (size_t k = 1; k < args.size(); ++k) {
        Checked next = args[k];
        // MIN(nCode, E_Mode.HIGH): an enumeration among integers takes part as its base
        // integer; its conversion then warns (an error with --strict), decision 0334.
        auto integral = [](const Checked& c) { return c.untypedInt || sema::isInteger(c.type->kind) || isBitArg(c); };
        if (probe.type && probe.type->kind == TK::Enum && probe.type->base && integral(next)) probe.type = probe.type->base;
        if (next.type && next.type->kind == TK::Enum && next.type->base && integral(probe)) next.type = next.type->base;
        const Type* t = ck.commonType(probe, next, loc, false);
        if (!t) {
            ck.error(diag::E0202, args[k].loc, fmt::format("{}: arguments of types {} and {} need an explicit conversion", fn,
                                              sema::typeName(probe.type), sema::typeName(args[k].type)));
            return nullptr;
        }
        bool bothUntyped = (probe.untypedInt || probe.untypedReal) && (next.untypedInt || next.untypedReal);
        if (bothUntyped) {
            if (next.untypedReal) probe = next;
            continue;
        }
        Checked typed;
        typed.ok = true;
        typed.type = t;
        typed.loc = loc;
        probe = typed;
    }
    if (probe.untypedInt || probe.untypedReal) probe = ck.settle(probe);
    return probe.type;
}

const Type* literalType(Checker& ck, const std::vector<Checked>& args) {
    bool real = false, exactFloat = true, negative = false;
    int64_t lo = 0, hi = 0;
    for (const auto& a : args) {
        real = real || a.untypedReal;
        double v = a.untypedReal ? a.constReal : static_cast<double>(a.constInt);
        exactFloat = exactFloat && static_cast<double>(static_cast<float>(v)) == v;
        if (a.untypedInt) {
            lo = std::min(lo, a.constInt);
            hi = std::max(hi, a.constInt);
            negative = negative || a.constInt < 0;
        }
    }
    if (real) return ck.types().elementary(exactFloat ? TK::Real : TK::LReal);
    if (negative) {
        auto fits = [&](int bits) { return lo >= -(int64_t(1) << (bits - 1)) && hi < (int64_t(1) << (bits - 1)); };
        return ck.types().elementary(fits(8) ? TK::SInt : fits(16) ? TK::Int : fits(32) ? TK::DInt : TK::LInt);
    }
    return ck.types().elementary(hi <= 0xFF ? TK::USInt : hi <= 0xFFFF ? TK::UInt : hi <= 0xFFFFFFFFll ? TK::UDInt : TK::ULInt);
}

bool coerceAll(Checker& ck, std::vector<Checked>& args, const Type* t, const std::string& fn) {
    std::string what = fmt::format("argument of {}", fn);
    for (auto& a : args) {
        if (sema::isStringType(t->kind)) continue;
        a = ck.coerce(a, t, a.loc, what.c_str());
        if (!a.ok) return false;
    }
    return true;
}

const Type* realTypeFor(Checker& ck, const Checked& a) {
    if (a.untypedReal || a.untypedInt) return ck.types().elementary(TK::LReal);
    TK k = a.type->kind;
    if (sema::isReal(k)) return a.type;
    if (sema::isInteger(k) && sema::bitWidth(k) <= 16) return ck.types().elementary(TK::Real);
    return ck.types().elementary(TK::LReal);
}

bool allConst(const std::vector<Checked>& args) {
    for (const auto& a : args)
        if (!isScalarConst(a)) return false;
    return true;
}

bool allUntyped(const std::vector<Checked>& args) {
    for (const auto& a : args)
        if (!(a.untypedInt || a.untypedReal)) return false;
    return !args.empty();
}

Checked makeResult(Checker& ck, exec::Expr* node, const Type* t, const CallArgs& call, const std::vector<Checked>& args,
                   bool fold, const std::vector<Checked>* valueArgs) {
    const bool untyped = allUntyped(valueArgs ? *valueArgs : args);
    node->type = t;
    Checked r;
    r.ok = true;
    r.loc = call.loc;
    r.type = t;
    r.node = node;
    for (const auto& a : args) r.hasCall = r.hasCall || a.hasCall;
    // SEL(g, 1, 2): computed from untyped literals only, it takes the type it is assigned to.
    if (untyped && !allConst(args) && (sema::isInteger(t->kind) || sema::isReal(t->kind))) r.flexibleLiteral = true;
    if (!fold || args.empty() || !allConst(args)) return r;
    exec::Ctx dummy;
    if (sema::isRealRep(t)) {
        Checked c = ck.constReal(node->f(dummy), t, call.loc);
        if (untyped) {
            c = ck.constReal(c.constReal, ck.types().elementary(TK::LReal), call.loc);
            c.untypedReal = true;
        }
        return c;
    }
    if (sema::isIntRep(t) && t->kind != TK::Void) {
        Checked c = ck.constInt(node->i(dummy), t, call.loc);
        if (untyped && sema::isInteger(t->kind)) {
            c.untypedInt = true;
            bool narrow = c.constInt >= std::numeric_limits<int32_t>::min() && c.constInt <= std::numeric_limits<int32_t>::max();
            c.type = ck.types().elementary(narrow ? TK::DInt : TK::LInt);
            c.node->type = c.type;
        }
        return c;
    }
    return r;
}

Checked argError(Checker& ck, const Checked& a, const std::string& fn, const std::string& what) {
    ck.error(diag::E0201, a.loc, fmt::format("{}: {}, not {}", fn, what, sema::typeName(a.type)));
    return ck.bad(a.loc);
}

void addAll(Checker& ck, std::initializer_list<const char*> names, const sema::BuiltinFn& fn) {
    for (const char* n : names) ck.addBuiltin(n, fn);
}

}  // namespace strun::stdlib::bind
