// Evaluator nodes of the numeric functions (ABS, SQRT ... ATAN2, EXPT) and
// the bit-shift functions. T is the storage type of the result: REAL work
// is done in float, LREAL in double, integers at their own width.
#pragma once

#include <cmath>
#include <type_traits>

#include "interpreter/exec/operator_nodes.h"

namespace strun::stdlib::bind {

using exec::Ctx;
using exec::Expr;

enum class MathFn : uint8_t { Sqrt, Ln, Log, Exp, Sin, Cos, Tan, Asin, Acos, Atan };

template <class T, MathFn F>
inline T applyMath(T x) {
    if constexpr (F == MathFn::Sqrt) return std::sqrt(x);
    else if constexpr (F == MathFn::Ln) return std::log(x);
    else if constexpr (F == MathFn::Log) return std::log10(x);
    else if constexpr (F == MathFn::Exp) return std::exp(x);
    else if constexpr (F == MathFn::Sin) return std::sin(x);
    else if constexpr (F == MathFn::Cos) return std::cos(x);
    else if constexpr (F == MathFn::Tan) return std::tan(x);
    else if constexpr (F == MathFn::Asin) return std::asin(x);
    else if constexpr (F == MathFn::Acos) return std::acos(x);
    else return std::atan(x);
}

template <class T, MathFn F>
struct MathNode final : Expr {
    Expr* a;
    explicit MathNode(Expr* x) : a(x) {}
    double f(Ctx& c) override { return static_cast<double>(applyMath<T, F>(static_cast<T>(a->f(c)))); }
};

template <class T>
struct Atan2Node final : Expr {
    Expr *y, *x;
    Atan2Node(Expr* a, Expr* b) : y(a), x(b) {}
    double f(Ctx& c) override { return static_cast<double>(std::atan2(static_cast<T>(y->f(c)), static_cast<T>(x->f(c)))); }
};

// EXPT(IN1, IN2): IN1 ** IN2 computed in T; an integer exponent is exact
// (repeated multiplication by std::pow's integer path).
template <class T>
struct ExptNode final : Expr {
    Expr *base, *exponent;
    bool intExponent;
    ExptNode(Expr* b, Expr* e, bool i) : base(b), exponent(e), intExponent(i) {}
    double f(Ctx& c) override {
        T b = static_cast<T>(base->f(c));
        if (intExponent) return static_cast<double>(static_cast<T>(std::pow(b, static_cast<double>(exponent->i(c)))));
        return static_cast<double>(std::pow(b, static_cast<T>(exponent->f(c))));
    }
};

// ABS on integers wraps like the operators: ABS(SINT#-128) = -128.
template <class T>
struct AbsI final : Expr {
    Expr* a;
    explicit AbsI(Expr* x) : a(x) {}
    int64_t i(Ctx& c) override {
        T v = static_cast<T>(a->i(c));
        if constexpr (std::is_signed_v<T>) {
            if (v < 0) return exec::wrapI(static_cast<T>(static_cast<exec::U<T>>(0) - static_cast<exec::U<T>>(v)));
        }
        return exec::wrapI(v);
    }
};

template <class T>
struct AbsF final : Expr {
    Expr* a;
    explicit AbsF(Expr* x) : a(x) {}
    double f(Ctx& c) override { return static_cast<double>(std::fabs(static_cast<T>(a->f(c)))); }
};

// SHL / SHR / ROL / ROR on the width of T (decision 0051): a shift count
// outside 0..width-1 shifts everything out (SHR of a signed value fills
// with its sign bit, as CODESYS documents); rotations take the count modulo the width.
enum class ShiftFn : uint8_t { Shl, Shr, Rol, Ror };

template <class T, ShiftFn F>
struct ShiftNode final : Expr {
    Expr *in, *n;
    ShiftNode(Expr* a, Expr* b) : in(a), n(b) {}
    int64_t i(Ctx& c) override {
        using UT = std::make_unsigned_t<T>;
        constexpr int64_t W = sizeof(T) * 8;
        T value = static_cast<T>(in->i(c));
        UT bits = static_cast<UT>(value);
        int64_t count = n->i(c);
        if constexpr (F == ShiftFn::Rol || F == ShiftFn::Ror) {
            int64_t r = ((count % W) + W) % W;
            if (r == 0) return exec::wrapI(value);
            UT out = F == ShiftFn::Rol ? static_cast<UT>((bits << r) | (bits >> (W - r)))
                                       : static_cast<UT>((bits >> r) | (bits << (W - r)));
            return exec::wrapI(static_cast<T>(out));
        } else if constexpr (F == ShiftFn::Shl) {
            if (count < 0 || count >= W) return 0;
            return exec::wrapI(static_cast<T>(static_cast<UT>(bits << count)));
        } else {
            if constexpr (std::is_signed_v<T>) {
                if (count < 0 || count >= W) return value < 0 ? -1 : 0;
                return exec::wrapI(static_cast<T>(value >> count));
            } else {
                if (count < 0 || count >= W) return 0;
                return exec::wrapI(static_cast<T>(bits >> count));
            }
        }
    }
};

}  // namespace strun::stdlib::bind
