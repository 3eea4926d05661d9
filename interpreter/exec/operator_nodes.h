// Operators, specialised at check time for the storage type of their result.
// Integer arithmetic is done in the unsigned type of the same width and cast
// back, which is exactly two's-complement wrap-around (the contract's rule)
// and free of C++ signed-overflow UB.
#pragma once

#include <cmath>
#include <type_traits>

#include "interpreter/exec/power_of_two_divisor.h"
#include "interpreter/exec/value_nodes.h"

namespace strun::exec {

template <class T>
using U = std::make_unsigned_t<T>;

template <class T>
inline int64_t wrapI(T v) { return static_cast<int64_t>(v); }

// Unsigned of at least `unsigned int` width: a product of two 16-bit
// unsigneds would otherwise be promoted to (signed) int and overflow (UB).
template <class T>
using W = std::common_type_t<U<T>, unsigned>;

// The general integer operators (the two-operand ones below, their
// constant-operand forms, DivPow2K, ModPow2K, DivI, ModI): a fused node with
// a constant reads one of them through OpNode as it reads a fused operator (decision 0486),
// so that `(a + b) MOD k` and the store of it need no node between them.
struct IntOperator : Expr {};

#define STRUN_INT_BINOP(NAME, EXPR)                                                           \
    template <class T>                                                                        \
    struct NAME final : IntOperator {                                                         \
        Expr *l, *r;                                                                          \
        NAME(Expr* a, Expr* b) : l(a), r(b) {}                                                \
        int64_t i(Ctx& c) override {                                                          \
            T a = static_cast<T>(l->i(c));                                                    \
            T b = static_cast<T>(r->i(c));                                                    \
            return wrapI(static_cast<T>(EXPR));                                               \
        }                                                                                     \
    };

STRUN_INT_BINOP(AddI, static_cast<U<T>>(static_cast<U<T>>(a) + static_cast<U<T>>(b)))
STRUN_INT_BINOP(SubI, static_cast<U<T>>(static_cast<U<T>>(a) - static_cast<U<T>>(b)))
STRUN_INT_BINOP(MulI, static_cast<U<T>>(static_cast<W<T>>(a) * static_cast<W<T>>(b)))
STRUN_INT_BINOP(AndI, a & b)
STRUN_INT_BINOP(OrI, a | b)
STRUN_INT_BINOP(XorI, a ^ b)
#undef STRUN_INT_BINOP

// The same operators with a constant right operand (x + 1, i MOD 7, n * 2):
// one virtual call less, and / and MOD skip the zero and -1 checks the
// checker already did.
#define STRUN_INT_BINOP_CONST(NAME, EXPR)                                                     \
    template <class T>                                                                        \
    struct NAME final : IntOperator {                                                         \
        Expr* l;                                                                              \
        T b;                                                                                  \
        NAME(Expr* a, int64_t k) : l(a), b(static_cast<T>(k)) {}                              \
        int64_t i(Ctx& c) override {                                                          \
            T a = static_cast<T>(l->i(c));                                                    \
            return wrapI(static_cast<T>(EXPR));                                               \
        }                                                                                     \
    };
STRUN_INT_BINOP_CONST(AddIK, static_cast<U<T>>(static_cast<U<T>>(a) + static_cast<U<T>>(b)))
STRUN_INT_BINOP_CONST(SubIK, static_cast<U<T>>(static_cast<U<T>>(a) - static_cast<U<T>>(b)))
STRUN_INT_BINOP_CONST(MulIK, static_cast<U<T>>(static_cast<W<T>>(a) * static_cast<W<T>>(b)))
STRUN_INT_BINOP_CONST(DivIK, a / b)  // b is neither 0 nor -1
STRUN_INT_BINOP_CONST(ModIK, a % b)  // b is neither 0 nor -1
STRUN_INT_BINOP_CONST(AndIK, a & b)
STRUN_INT_BINOP_CONST(OrIK, a | b)
STRUN_INT_BINOP_CONST(XorIK, a ^ b)
#undef STRUN_INT_BINOP_CONST

// / and MOD by a constant +-2^k (k >= 1): by shifts (decision 0490).
template <class T, bool MOD>
struct Pow2DivideK final : IntOperator {
    Expr* l;
    PowerOfTwoDivisor<T> b;
    Pow2DivideK(Expr* a, int64_t k) : l(a), b(static_cast<T>(k)) {}
    int64_t i(Ctx& c) override {
        T a = static_cast<T>(l->i(c));
        return wrapI(MOD ? b.remainder(a) : b.quotient(a));
    }
};
template <class T>
using DivPow2K = Pow2DivideK<T, false>;
template <class T>
using ModPow2K = Pow2DivideK<T, true>;

// Changes the unit of a time/date value: * mul, or / div (toward zero) then * mul.
struct ScaleUnits final : Expr {
    Expr* a;
    int64_t mul, div;
    ScaleUnits(Expr* x, int64_t m, int64_t d) : a(x), mul(m), div(d) {}
    int64_t i(Ctx& c) override {
        int64_t v = a->i(c);
        if (div > 1) v /= div;
        return static_cast<int64_t>(static_cast<uint64_t>(v) * static_cast<uint64_t>(mul));
    }
};

// A time of day kept within one day (TOD + TIME wraps at midnight).
struct WrapModulo final : Expr {
    Expr* a;
    int64_t m;
    WrapModulo(Expr* x, int64_t mod) : a(x), m(mod) {}
    int64_t i(Ctx& c) override {
        int64_t v = a->i(c) % m;
        return v < 0 ? v + m : v;
    }
};

// Reports DIV_BY_ZERO for the running task (defined in faults.cpp).
void reportDivByZero(Ctx& c, const Site& site);

// Integer / and MOD: divisor 0 is replaced by 1 after reporting DIV_BY_ZERO;
// MIN / -1 wraps instead of trapping.
template <class T>
struct DivI final : IntOperator {
    Expr *l, *r;
    Site site;
    DivI(Expr* a, Expr* b, Site s) : l(a), r(b), site(s) {}
    int64_t i(Ctx& c) override {
        T a = static_cast<T>(l->i(c));
        T b = static_cast<T>(r->i(c));
        if (__builtin_expect(b == 0, 0)) { reportDivByZero(c, site); b = 1; }
        if constexpr (std::is_signed_v<T>) {
            if (b == -1) return wrapI(static_cast<T>(static_cast<U<T>>(0) - static_cast<U<T>>(a)));
        }
        return wrapI(static_cast<T>(a / b));
    }
};

template <class T>
struct ModI final : IntOperator {
    Expr *l, *r;
    Site site;
    ModI(Expr* a, Expr* b, Site s) : l(a), r(b), site(s) {}
    int64_t i(Ctx& c) override {
        T a = static_cast<T>(l->i(c));
        T b = static_cast<T>(r->i(c));
        if (__builtin_expect(b == 0, 0)) { reportDivByZero(c, site); b = 1; }
        if constexpr (std::is_signed_v<T>) {
            if (b == -1) return 0;
        }
        return wrapI(static_cast<T>(a % b));
    }
};

template <class T>
struct NegI final : Expr {
    Expr* a;
    explicit NegI(Expr* x) : a(x) {}
    int64_t i(Ctx& c) override { return wrapI(static_cast<T>(static_cast<U<T>>(0) - static_cast<U<T>>(static_cast<T>(a->i(c))))); }
};

template <class T>
struct NotBits final : Expr {
    Expr* a;
    explicit NotBits(Expr* x) : a(x) {}
    int64_t i(Ctx& c) override { return wrapI(static_cast<T>(~static_cast<T>(a->i(c)))); }
};

struct NotBool final : Expr {
    Expr* a;
    explicit NotBool(Expr* x) : a(x) {}
    int64_t i(Ctx& c) override { return a->i(c) == 0; }
};

// AND_THEN / OR_ELSE: short-circuit.
struct AndThen final : Expr {
    Expr *l, *r;
    AndThen(Expr* a, Expr* b) : l(a), r(b) {}
    int64_t i(Ctx& c) override { return l->i(c) != 0 && r->i(c) != 0; }
};
struct OrElse final : Expr {
    Expr *l, *r;
    OrElse(Expr* a, Expr* b) : l(a), r(b) {}
    int64_t i(Ctx& c) override { return l->i(c) != 0 || r->i(c) != 0; }
};

// Floating point: computed in T (float for REAL, double for LREAL).
#define STRUN_REAL_BINOP(NAME, EXPR)                                                          \
    template <class T>                                                                        \
    struct NAME final : Expr {                                                                \
        Expr *l, *r;                                                                          \
        NAME(Expr* a, Expr* b) : l(a), r(b) {}                                                \
        double f(Ctx& c) override {                                                           \
            T a = static_cast<T>(l->f(c));                                                    \
            T b = static_cast<T>(r->f(c));                                                    \
            return static_cast<double>(static_cast<T>(EXPR));                                 \
        }                                                                                     \
    };
STRUN_REAL_BINOP(AddF, a + b)
STRUN_REAL_BINOP(SubF, a - b)
STRUN_REAL_BINOP(MulF, a * b)
STRUN_REAL_BINOP(DivF, a / b)
STRUN_REAL_BINOP(PowF, std::pow(a, b))
#undef STRUN_REAL_BINOP

// Floating point with one constant operand (4.0 / x, x * 0.5): LEFT says
// which side the constant is on, for the non-commutative - and /.
enum class RealOp : uint8_t { Add, Sub, Mul, Div };
template <class T, RealOp OP, bool LEFT>
struct RealK final : Expr {
    Expr* x;
    T k;
    RealK(Expr* e, double v) : x(e), k(static_cast<T>(v)) {}
    double f(Ctx& c) override {
        T v = static_cast<T>(x->f(c));
        T a = LEFT ? k : v, b = LEFT ? v : k;
        T r;
        if constexpr (OP == RealOp::Add) r = a + b;
        else if constexpr (OP == RealOp::Sub) r = a - b;
        else if constexpr (OP == RealOp::Mul) r = a * b;
        else r = a / b;
        return static_cast<double>(r);
    }
};

template <class T>
struct NegF final : Expr {
    Expr* a;
    explicit NegF(Expr* x) : a(x) {}
    double f(Ctx& c) override { return static_cast<double>(-static_cast<T>(a->f(c))); }
};

// Comparisons yield BOOL (0/1). Operands are compared in T.
enum class CmpOp : uint8_t { Eq, Ne, Lt, Le, Gt, Ge };

template <class T, CmpOp OP>
inline bool compare(T a, T b) {
    if constexpr (OP == CmpOp::Eq) return a == b;
    else if constexpr (OP == CmpOp::Ne) return a != b;
    else if constexpr (OP == CmpOp::Lt) return a < b;
    else if constexpr (OP == CmpOp::Le) return a <= b;
    else if constexpr (OP == CmpOp::Gt) return a > b;
    else return a >= b;
}

template <class T, CmpOp OP>
struct CmpI final : Expr {
    Expr *l, *r;
    CmpI(Expr* a, Expr* b) : l(a), r(b) {}
    int64_t i(Ctx& c) override {
        T a = static_cast<T>(l->i(c));  // left first (decision 0262)
        return compare<T, OP>(a, static_cast<T>(r->i(c)));
    }
};

template <class T, CmpOp OP>
struct CmpIK final : Expr {
    Expr* l;
    T b;
    CmpIK(Expr* a, int64_t k) : l(a), b(static_cast<T>(k)) {}
    int64_t i(Ctx& c) override { return compare<T, OP>(static_cast<T>(l->i(c)), b); }
};

template <class T, CmpOp OP>
struct CmpF final : Expr {
    Expr *l, *r;
    CmpF(Expr* a, Expr* b) : l(a), r(b) {}
    int64_t i(Ctx& c) override {
        T a = static_cast<T>(l->f(c));  // left first (decision 0262)
        return compare<T, OP>(a, static_cast<T>(r->f(c)));
    }
};

// STRING / WSTRING comparison: lexicographic on code units.
template <class Ch, CmpOp OP>
struct CmpStr final : Expr {
    Expr *l, *r;
    CmpStr(Expr* a, Expr* b) : l(a), r(b) {}
    int64_t i(Ctx& c) override {
        const Ch* a = reinterpret_cast<const Ch*>(l->addr(c));
        const Ch* b = reinterpret_cast<const Ch*>(r->addr(c));
        int d = 0;
        for (;; ++a, ++b) {
            if (*a != *b) { d = (static_cast<std::make_unsigned_t<Ch>>(*a) < static_cast<std::make_unsigned_t<Ch>>(*b)) ? -1 : 1; break; }
            if (*a == 0) break;
        }
        return compare<int, OP>(d, 0);
    }
};

// Aggregate equality (structs, arrays): bytewise.
template <bool EQ>
struct CmpBytes final : Expr {
    Expr *l, *r;
    uint32_t size;
    CmpBytes(Expr* a, Expr* b, uint32_t n) : l(a), r(b), size(n) {}
    int64_t i(Ctx& c) override {
        const uint8_t* a = l->addr(c);  // left first (decision 0262)
        return (std::memcmp(a, r->addr(c), size) == 0) == EQ;
    }
};

// ---- conversions

// Integer representation to another integer width: wraps.
template <class T>
struct ConvIntInt final : Expr {
    Expr* a;
    explicit ConvIntInt(Expr* x) : a(x) {}
    int64_t i(Ctx& c) override { return wrapI(static_cast<T>(a->i(c))); }
};

struct ConvToBool final : Expr {
    Expr* a;
    bool fromReal;
    ConvToBool(Expr* x, bool real) : a(x), fromReal(real) {}
    int64_t i(Ctx& c) override { return fromReal ? (a->f(c) != 0.0) : (a->i(c) != 0); }
};

// Integer to REAL/LREAL. SRC is the source integer type (signedness matters for 64-bit).
template <class T, class SRC>
struct ConvIntReal final : Expr {
    Expr* a;
    explicit ConvIntReal(Expr* x) : a(x) {}
    double f(Ctx& c) override { return static_cast<double>(static_cast<T>(static_cast<SRC>(a->i(c)))); }
};

template <class T>
struct ConvRealReal final : Expr {
    Expr* a;
    explicit ConvRealReal(Expr* x) : a(x) {}
    double f(Ctx& c) override { return static_cast<double>(static_cast<T>(a->f(c))); }
};

// REAL/LREAL to an integer: rounded to nearest (ties per docs/decisions), or truncated.
int64_t realToIntRounded(double v, int bits, bool isSigned);
int64_t realToIntTruncated(double v, int bits, bool isSigned);

struct ConvRealInt final : Expr {
    Expr* a;
    int bits;
    bool isSigned;
    bool truncate;
    ConvRealInt(Expr* x, int b, bool s, bool t) : a(x), bits(b), isSigned(s), truncate(t) {}
    int64_t i(Ctx& c) override {
        double v = a->f(c);
        return truncate ? realToIntTruncated(v, bits, isSigned) : realToIntRounded(v, bits, isSigned);
    }
};

}  // namespace strun::exec
