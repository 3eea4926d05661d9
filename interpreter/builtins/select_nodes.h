// Evaluator nodes of the selection functions (SEL MUX MAX MIN LIMIT) and the
// extensible comparisons (GT GE EQ LE LT NE). The inputs are already
// converted to one common type; T is its storage type, Ch the character
// type of STRING (char) / WSTRING (char16_t) inputs.
#pragma once

#include <vector>

#include "interpreter/exec/operator_nodes.h"

namespace strun::stdlib::bind {

using exec::CmpOp;
using exec::Ctx;
using exec::Expr;

// SEL and MUX evaluate only the selected input (as CODESYS documents: "an
// expression ahead of another input is not processed"); the chosen node
// yields the value in whatever representation the caller asks for.
struct SelNode final : Expr {
    Expr *g, *in0, *in1;
    SelNode(Expr* gate, Expr* a, Expr* b) : g(gate), in0(a), in1(b) {}
    Expr* pick(Ctx& c) { return g->i(c) != 0 ? in1 : in0; }
    int64_t i(Ctx& c) override { return pick(c)->i(c); }
    double f(Ctx& c) override { return pick(c)->f(c); }
    uint8_t* addr(Ctx& c) override { return pick(c)->addr(c); }
};

// MUX(K, IN0..INn-1): K below 0 selects IN0, K above n-1 the last input (decision 0052).
template <class K>
struct MuxNode final : Expr {
    Expr* k;
    std::vector<Expr*> ins;
    explicit MuxNode(Expr* selector) : k(selector) {}
    Expr* pick(Ctx& c) {
        K v = static_cast<K>(k->i(c));
        if (v <= 0) return ins.front();
        if (static_cast<uint64_t>(v) >= ins.size()) return ins.back();
        return ins[static_cast<size_t>(v)];
    }
    int64_t i(Ctx& c) override { return pick(c)->i(c); }
    double f(Ctx& c) override { return pick(c)->f(c); }
    uint8_t* addr(Ctx& c) override { return pick(c)->addr(c); }
};

template <class Ch>
inline int compareStrings(const Ch* a, const Ch* b) {
    using UC = std::make_unsigned_t<Ch>;
    for (;; ++a, ++b) {
        if (*a != *b) return static_cast<UC>(*a) < static_cast<UC>(*b) ? -1 : 1;
        if (*a == 0) return 0;
    }
}

// MAX / MIN over integers (in T), reals (computed in T), strings.
template <class T, bool MAX>
struct ExtremeI final : Expr {
    std::vector<Expr*> ins;
    int64_t i(Ctx& c) override {
        T best = static_cast<T>(ins[0]->i(c));
        for (size_t k = 1; k < ins.size(); ++k) {
            T v = static_cast<T>(ins[k]->i(c));
            if (MAX ? v > best : v < best) best = v;
        }
        return exec::wrapI(best);
    }
};

template <class T, bool MAX>
struct ExtremeF final : Expr {
    std::vector<Expr*> ins;
    double f(Ctx& c) override {
        T best = static_cast<T>(ins[0]->f(c));
        for (size_t k = 1; k < ins.size(); ++k) {
            T v = static_cast<T>(ins[k]->f(c));
            if (MAX ? v > best : v < best) best = v;
        }
        return static_cast<double>(best);
    }
};

template <class Ch, bool MAX>
struct ExtremeStr final : Expr {
    std::vector<Expr*> ins;
    uint8_t* addr(Ctx& c) override {
        uint8_t* best = ins[0]->addr(c);
        for (size_t k = 1; k < ins.size(); ++k) {
            uint8_t* v = ins[k]->addr(c);
            int d = compareStrings(reinterpret_cast<const Ch*>(v), reinterpret_cast<const Ch*>(best));
            if (MAX ? d > 0 : d < 0) best = v;
        }
        return best;
    }
};

// LIMIT(MN, IN, MX) = MIN(MAX(IN, MN), MX): MX wins when MN > MX.
template <class T>
struct LimitI final : Expr {
    Expr *mn, *in, *mx;
    LimitI(Expr* a, Expr* b, Expr* d) : mn(a), in(b), mx(d) {}
    int64_t i(Ctx& c) override {
        T lo = static_cast<T>(mn->i(c)), v = static_cast<T>(in->i(c)), hi = static_cast<T>(mx->i(c));
        if (v < lo) v = lo;
        if (v > hi) v = hi;
        return exec::wrapI(v);
    }
};

template <class T>
struct LimitF final : Expr {
    Expr *mn, *in, *mx;
    LimitF(Expr* a, Expr* b, Expr* d) : mn(a), in(b), mx(d) {}
    double f(Ctx& c) override {
        T lo = static_cast<T>(mn->f(c)), v = static_cast<T>(in->f(c)), hi = static_cast<T>(mx->f(c));
        if (v < lo) v = lo;
        if (v > hi) v = hi;
        return static_cast<double>(v);
    }
};

template <class Ch>
struct LimitStr final : Expr {
    Expr *mn, *in, *mx;
    LimitStr(Expr* a, Expr* b, Expr* d) : mn(a), in(b), mx(d) {}
    uint8_t* addr(Ctx& c) override {
        uint8_t* lo = mn->addr(c);
        uint8_t* v = in->addr(c);
        uint8_t* hi = mx->addr(c);
        auto C = [](uint8_t* x) { return reinterpret_cast<const Ch*>(x); };
        if (compareStrings(C(v), C(lo)) < 0) v = lo;
        if (compareStrings(C(v), C(hi)) > 0) v = hi;
        return v;
    }
};

// GT(a, b, c, ...) = a > b AND b > c AND ...; every input is evaluated once, in order.
template <class T, CmpOp OP>
struct CmpChainI final : Expr {
    std::vector<Expr*> ins;
    int64_t i(Ctx& c) override {
        bool all = true;
        T prev = static_cast<T>(ins[0]->i(c));
        for (size_t k = 1; k < ins.size(); ++k) {
            T v = static_cast<T>(ins[k]->i(c));
            all = all && exec::compare<T, OP>(prev, v);
            prev = v;
        }
        return all;
    }
};

template <class T, CmpOp OP>
struct CmpChainF final : Expr {
    std::vector<Expr*> ins;
    int64_t i(Ctx& c) override {
        bool all = true;
        T prev = static_cast<T>(ins[0]->f(c));
        for (size_t k = 1; k < ins.size(); ++k) {
            T v = static_cast<T>(ins[k]->f(c));
            all = all && exec::compare<T, OP>(prev, v);
            prev = v;
        }
        return all;
    }
};

template <class Ch, CmpOp OP>
struct CmpChainStr final : Expr {
    std::vector<Expr*> ins;
    int64_t i(Ctx& c) override {
        bool all = true;
        const Ch* prev = reinterpret_cast<const Ch*>(ins[0]->addr(c));
        for (size_t k = 1; k < ins.size(); ++k) {
            const Ch* v = reinterpret_cast<const Ch*>(ins[k]->addr(c));
            all = all && exec::compare<int, OP>(compareStrings(prev, v), 0);
            prev = v;
        }
        return all;
    }
};

}  // namespace strun::stdlib::bind
