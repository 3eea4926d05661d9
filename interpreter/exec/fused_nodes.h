// Fused nodes: the patterns that dominate PLC code, executed with fewer
// virtual dispatches. A tree interpreter's time follows its node dispatches,
// not its instructions (decision 0151), so an operand that is a local
// variable or a constant is read inside its operator instead of through a
// child node. Every fused node computes exactly what the unfused nodes it
// replaces compute (same widths, same wrap-around, same fault rules); the
// checker only builds one where that holds (interpreter/sema/fuse.cpp).
#pragma once

#include <typeinfo>

#include "interpreter/exec/power_of_two_divisor.h"
#include "interpreter/exec/stmt_nodes.h"

namespace strun::exec {

// ---- operands read inside a fused node, as the computation type T

// The context pointer an element operand is based on (the instance or the
// frame), as data: a pointer to the Ctx member (decision 0262).
using CtxBase = uint8_t* Ctx::*;
template <BaseKind B>
constexpr CtxBase ctxBase() {
    if constexpr (B == BaseKind::Self) return &Ctx::self;
    else if constexpr (B == BaseKind::Frame) return &Ctx::frame;
    else return &Ctx::pending;
}

// Any expression: one virtual call, as the unfused node does.
template <class T>
struct OpNode {
    Expr* e;
    T get(Ctx& c) const {
        if constexpr (std::is_floating_point_v<T>) return static_cast<T>(e->f(c));
        else return static_cast<T>(e->i(c));
    }
};
// A variable of storage type T in the current instance (B = Self) or frame
// (B = Frame). The base stays a template parameter here: as data (a Ctx
// member pointer) it cost one load more per operand, up to 7 % more
// instructions in arithmetic loops (decision 0262).
template <class T, BaseKind B>
struct OpVar {
    uint32_t off;
    T get(Ctx& c) const { return loadAs<T>(baseOf<B>(c, nullptr) + off); }
};
template <class T>
struct OpConst {
    T k;
    T get(Ctx&) const { return k; }
};
// The constant right operand +-2^k (k >= 1) of an integer / or MOD: evalBin
// divides by shifts (decision 0490).
template <class T>
struct OpPow2Divisor {
    PowerOfTwoDivisor<T> divisor;
};
// a[i + k]: an element of storage type T of a one-dimensional array variable
// of the instance or frame, the subscript a DINT variable of the instance or
// frame plus a constant, computed in DINT with wrap-around and bounds-checked
// exactly as Index1Var does (value_nodes.h): out of range reports
// ARRAY_BOUNDS and reads the zeroed fault sink.
template <class T>
struct OpElem {
    CtxBase base;
    uint32_t off;
    CtxBase indexBase;
    uint32_t indexOff;
    int32_t indexAdd;
    int64_t lo, count;
    uint64_t stride;
    const Site* site;  // the Index1Var's, for the fault report
    // Always inlined: left to GCC, an unrelated edit to the node headers
    // once made it call this out of line from IfCompare (bubble_sort +2.6 %
    // instructions).
    // The subscript `i + k`, added in 32 bits with wrap-around as DINT is.
    [[gnu::always_inline]] int64_t subscript(Ctx& c) const {
        return static_cast<int32_t>(static_cast<uint32_t>(loadAs<int32_t>(c.*indexBase + indexOff)) + static_cast<uint32_t>(indexAdd));
    }
    [[gnu::always_inline]] T get(Ctx& c) const {
        int64_t i = subscript(c);
        int64_t k = static_cast<int64_t>(static_cast<uint64_t>(i) - static_cast<uint64_t>(lo));
        if (__builtin_expect(static_cast<uint64_t>(k) >= static_cast<uint64_t>(count), 0)) return loadAs<T>(indexFault(c, *site, i, lo, count));
        return loadAs<T>(c.*base + off + static_cast<uint64_t>(k) * stride);
    }
};

// ---- binary operators over fused operands

enum class BinOp : uint8_t { Add, Sub, Mul, Div, Mod, And, Or, Xor, Eq, Ne, Lt, Le, Gt, Ge };

constexpr bool isCompare(BinOp op) { return op >= BinOp::Eq; }

// The result of `a OP b` computed as the unfused nodes do: integers in the
// unsigned type of the same width (wrap-around), reals in T; comparisons 0/1.
// Integer Div and Mod are only fused with a constant divisor that is neither 0 nor -1.
template <class T, BinOp OP>
inline auto applyBin(T a, T b) {
    if constexpr (OP == BinOp::Eq) return static_cast<int64_t>(a == b);
    else if constexpr (OP == BinOp::Ne) return static_cast<int64_t>(a != b);
    else if constexpr (OP == BinOp::Lt) return static_cast<int64_t>(a < b);
    else if constexpr (OP == BinOp::Le) return static_cast<int64_t>(a <= b);
    else if constexpr (OP == BinOp::Gt) return static_cast<int64_t>(a > b);
    else if constexpr (OP == BinOp::Ge) return static_cast<int64_t>(a >= b);
    else if constexpr (std::is_floating_point_v<T>) {
        T r;
        if constexpr (OP == BinOp::Add) r = a + b;
        else if constexpr (OP == BinOp::Sub) r = a - b;
        else if constexpr (OP == BinOp::Mul) r = a * b;
        else r = a / b;
        return static_cast<double>(r);
    } else {
        T r;
        if constexpr (OP == BinOp::Add) r = static_cast<T>(static_cast<U<T>>(static_cast<U<T>>(a) + static_cast<U<T>>(b)));
        else if constexpr (OP == BinOp::Sub) r = static_cast<T>(static_cast<U<T>>(static_cast<U<T>>(a) - static_cast<U<T>>(b)));
        else if constexpr (OP == BinOp::Mul) r = static_cast<T>(static_cast<U<T>>(static_cast<W<T>>(a) * static_cast<W<T>>(b)));
        else if constexpr (OP == BinOp::Div) r = static_cast<T>(a / b);
        else if constexpr (OP == BinOp::Mod) r = static_cast<T>(a % b);
        else if constexpr (OP == BinOp::And) r = static_cast<T>(a & b);
        else if constexpr (OP == BinOp::Or) r = static_cast<T>(a | b);
        else r = static_cast<T>(a ^ b);
        return wrapI(r);
    }
}

// l OP r with the left operand read first, as the unfused nodes do (a fault
// or a call in either operand happens in source order).
template <class T, BinOp OP, class L, class R>
inline auto evalBin(Ctx& c, const L& l, const R& r) {
    T a = l.get(c);
    if constexpr (std::is_same_v<R, OpPow2Divisor<T>>) {
        static_assert(OP == BinOp::Div || OP == BinOp::Mod);
        return wrapI(OP == BinOp::Div ? r.divisor.quotient(a) : r.divisor.remainder(a));
    } else {
        T b = r.get(c);
        return applyBin<T, OP>(a, b);
    }
}

// REAL/LREAL -> integer of `bits` bits (signed or not), rounded half to even
// or truncated: inline below 2^52 in magnitude, where adding and removing
// 2^52 rounds exactly to the nearest even integer in the default rounding
// mode; anything else (huge, infinite, NaN) takes the generic routine. The
// result wraps to the width as static_cast<T> would.
struct RealToIntForm {
    uint8_t bits;
    bool isSigned;
    bool truncate;
    // Always inline: GCC kept it out of line, a call per conversion.
    __attribute__((always_inline)) int64_t apply(double v) const {
        constexpr double kTwoPow52 = 4503599627370496.0;
        if (__builtin_expect(v > -kTwoPow52 && v < kTwoPow52, 1)) {
            double whole = v;  // the cast below truncates toward zero
            if (!truncate) {
                // Without -ffast-math the compiler keeps (v + 2^52) - 2^52 as written.
                double shifted = v >= 0 ? v + kTwoPow52 : v - kTwoPow52;
                whole = v >= 0 ? shifted - kTwoPow52 : shifted + kTwoPow52;
            }
            const unsigned shift = 64u - bits;
            uint64_t w = static_cast<uint64_t>(static_cast<int64_t>(whole)) << shift;
            return isSigned ? static_cast<int64_t>(w) >> shift : static_cast<int64_t>(w >> shift);
        }
        return truncate ? realToIntTruncated(v, bits, isSigned) : realToIntRounded(v, bits, isSigned);
    }
};

// A fused comparison can become the condition of the IF or WHILE that tests
// it, so that the branch reads its operands itself (decision 0154).
struct FusedCompare : Expr {
    virtual Stmt* makeIf(NodePool& pool, Block* then, Stmt* otherwise) = 0;  // otherwise: see If1Stmt
    virtual Stmt* makeWhile(NodePool& pool, Block* body) = 0;
};

// A fused arithmetic node can become the assignment that stores its result
// into a variable of the instance or frame of exactly its computation type
// (`storage`), computing it inline (decision 0154); null for other targets.
// A REAL/LREAL one can also become the conversion of its result to an
// integer (REAL_TO_DINT(x * 10.0), decision 0262); null where it cannot.
struct FusedArith : Expr {
    virtual Stmt* makeAssignLocal(NodePool& pool, bool frame, uint32_t off, const std::type_info& storage) = 0;
    virtual Expr* makeRealToInt(NodePool& pool, RealToIntForm form) = 0;
};

template <class T, BinOp OP, class L, class R>
struct FusedBin final : std::conditional_t<isCompare(OP), FusedCompare, FusedArith> {
    L l;
    R r;
    FusedBin(L a, R b) : l(a), r(b) {}
    int64_t i(Ctx& c) override {
        if constexpr (isCompare(OP) || !std::is_floating_point_v<T>) return evalBin<T, OP>(c, l, r);
        else return 0;
    }
    double f(Ctx& c) override {
        if constexpr (std::is_floating_point_v<T> && !isCompare(OP)) return evalBin<T, OP>(c, l, r);
        else return 0;
    }
    Stmt* makeIf(NodePool& pool, Block* then, Stmt* otherwise);
    Stmt* makeWhile(NodePool& pool, Block* body);
    Stmt* makeAssignLocal(NodePool& pool, bool frame, uint32_t off, const std::type_info& storage);
    Expr* makeRealToInt(NodePool& pool, RealToIntForm form);
};

// x := l OP r with x of type T in the instance (FRAME = false) or frame: as
// AssignLocal<T> over the FusedBin, without the dispatch between them.
template <class T, BinOp OP, class L, class R, bool FRAME>
struct AssignBinLocal final : Stmt {
    uint32_t off;
    L l;
    R r;
    AssignBinLocal(uint32_t o, L x, R y) : off(o), l(x), r(y) {}
    Flow exec(Ctx& c) override {
        T v = static_cast<T>(evalBin<T, OP>(c, l, r));
        storeAs<T>((FRAME ? c.frame : c.self) + off, v);
        return Flow::Next;
    }
};

template <class T, BinOp OP, class L, class R>
Stmt* FusedBin<T, OP, L, R>::makeAssignLocal(NodePool& pool, bool frame, uint32_t off, const std::type_info& storage) {
    if constexpr (isCompare(OP)) return nullptr;
    else {
        if (storage != typeid(T)) return nullptr;
        if (frame) return pool.make<AssignBinLocal<T, OP, L, R, true>>(off, l, r);
        return pool.make<AssignBinLocal<T, OP, L, R, false>>(off, l, r);
    }
}

// INT_TYPE(l OP r) for REAL/LREAL l OP r (ConvRealIntT over the FusedBin).
template <class T, BinOp OP, class L, class R>
struct RealBinToInt final : Expr {
    L l;
    R r;
    RealToIntForm form;
    RealBinToInt(L x, R y, RealToIntForm f) : l(x), r(y), form(f) {}
    int64_t i(Ctx& c) override { return form.apply(evalBin<T, OP>(c, l, r)); }
};

template <class T, BinOp OP, class L, class R>
Expr* FusedBin<T, OP, L, R>::makeRealToInt(NodePool& pool, RealToIntForm form) {
    if constexpr (isCompare(OP) || !std::is_floating_point_v<T> || std::is_same_v<L, OpNode<T>> || std::is_same_v<R, OpNode<T>>) return nullptr;
    else return pool.make<RealBinToInt<T, OP, L, R>>(l, r, form);
}

// IF l OP r THEN ... [ELSE ...] END_IF with the comparison inline.
template <class T, BinOp OP, class L, class R>
struct IfCompare final : Stmt {
    L l;
    R r;
    Body then;
    Stmt* otherwise;  // may be null; see If1Stmt
    IfCompare(L a, R b, Block* t, Stmt* e) : l(a), r(b), then(t), otherwise(e) {}
    Flow exec(Ctx& c) override {
        if (evalBin<T, OP>(c, l, r)) return then.runOutOfLine(c);  // decision 0410
        return otherwise ? otherwise->exec(c) : Flow::Next;
    }
};

// WHILE l OP r DO ... END_WHILE with the comparison inline (as WhileStmt).
template <class T, BinOp OP, class L, class R>
struct WhileCompare final : Stmt {
    L l;
    R r;
    Body body;
    WhileCompare(L a, R b, Block* d) : l(a), r(b), body(d) {}
    Flow exec(Ctx& c) override {
        return runWhile(c, body, [this](Ctx& k) { return evalBin<T, OP>(k, l, r) != 0; });
    }
};

template <class T, BinOp OP, class L, class R>
Stmt* FusedBin<T, OP, L, R>::makeIf(NodePool& pool, Block* then, Stmt* otherwise) {
    if constexpr (isCompare(OP)) return pool.make<IfCompare<T, OP, L, R>>(l, r, then, otherwise);
    else return nullptr;
}
template <class T, BinOp OP, class L, class R>
Stmt* FusedBin<T, OP, L, R>::makeWhile(NodePool& pool, Block* body) {
    if constexpr (isCompare(OP)) return pool.make<WhileCompare<T, OP, L, R>>(l, r, body);
    else return nullptr;
}

// IF b THEN ... for a BOOL variable or a BOOL array element (`IF flags[i]`)
// read inline (O is OpVar<uint8_t, B> or OpElem<uint8_t>): true when its byte is
// not 0, as If1Stmt over the variable node tests it.
// The THEN branch is held as a Body (decision 0353; it was a Block*, the one
// IF form decision 0266 had left running its Block).
template <class O>
struct IfBool final : Stmt {
    O cond;
    Body then;
    Stmt* otherwise;  // may be null; see If1Stmt
    IfBool(O k, Block* t, Stmt* e) : cond(k), then(t), otherwise(e) {}
    Flow exec(Ctx& c) override {
        if (cond.get(c)) return then.run(c);
        return otherwise ? otherwise->exec(c) : Flow::Next;
    }
};

// IF a AND b / IF a OR b / IF a XOR b on BOOL operands (stored as bytes):
// both operands evaluated, left first, and combined as AndI/OrI/XorI<uint8_t>
// combine them, without the operator node's call and frame between the IF
// and its operands (decision 0485).
template <BinOp OP>
struct IfLogic final : Stmt {
    static_assert(OP == BinOp::And || OP == BinOp::Or || OP == BinOp::Xor);
    Expr* l;
    Expr* r;
    Body then;
    Stmt* otherwise;  // may be null; see If1Stmt
    IfLogic(Expr* a, Expr* b, Block* t, Stmt* e) : l(a), r(b), then(t), otherwise(e) {}
    Flow exec(Ctx& c) override {
        const uint8_t a = static_cast<uint8_t>(l->i(c));
        const uint8_t b = static_cast<uint8_t>(r->i(c));
        if (applyBin<uint8_t, OP>(a, b)) return then.runOutOfLine(c);  // as IfCompare (decision 0410)
        return otherwise ? otherwise->exec(c) : Flow::Next;
    }
};

// ---- statements

// x := x + k (k may be negative: x - k) on a variable of the instance or
// frame. Adding in the storage width wraps exactly as computing in DINT and
// storing would: addition commutes with truncation modulo 2^n.
template <class T, BaseKind B>
struct AddConstLocal final : Stmt {
    uint32_t off;
    U<T> k;
    AddConstLocal(uint32_t o, int64_t add) : off(o), k(static_cast<U<T>>(add)) {}
    Flow exec(Ctx& c) override {
        uint8_t* p = baseOf<B>(c, nullptr) + off;
        storeAs<T>(p, static_cast<T>(static_cast<U<T>>(static_cast<U<T>>(loadAs<T>(p)) + k)));
        return Flow::Next;
    }
};

// place := constant (flags, counters reset, `a[j] := TRUE`): the stored
// pattern is computed once by the checker, as Assign<T> would convert it.
template <class T>
struct AssignConst final : Stmt {
    Expr* place;
    T k;
    AssignConst(Expr* p, T v) : place(p), k(v) {}
    Flow exec(Ctx& c) override {
        storeAs<T>(place->addr(c), k);
        return Flow::Next;
    }
};
template <class T, BaseKind B>
struct AssignConstLocal final : Stmt {
    uint32_t off;
    T k;
    AssignConstLocal(uint32_t o, T v) : off(o), k(v) {}
    Flow exec(Ctx& c) override {
        storeAs<T>(baseOf<B>(c, nullptr) + off, k);
        return Flow::Next;
    }
};

// An argument bound into the frame of the call being set up (Ctx::pending):
// a direct typed store, as AssignLocal does for the instance and frame.
template <class T>
struct AssignPending final : Stmt {
    uint32_t off;
    Expr* value;
    AssignPending(uint32_t o, Expr* v) : off(o), value(v) {}
    Flow exec(Ctx& c) override {
        uint8_t* p = c.pending + off;
        if constexpr (std::is_floating_point_v<T>) storeAs<T>(p, static_cast<T>(value->f(c)));
        else if constexpr (std::is_same_v<T, bool>) storeAs<uint8_t>(p, value->i(c) != 0);
        else storeAs<T>(p, static_cast<T>(value->i(c)));
        return Flow::Next;
    }
};

// a[i] := value (A as in Assign<A>: bool stores 0/1 in a byte): the value
// first, then the element's address, as Assign<A> on an Index1Var does.
template <class A, BaseKind B, IndexFrom IX>
struct AssignIndex1 final : Stmt, Index1Fields {
    Expr* value;
    AssignIndex1(const Index1Fields& f, Expr* v) : Index1Fields(f), value(v) {}
    Flow exec(Ctx& c) override {
        if constexpr (std::is_floating_point_v<A>) {
            A v = static_cast<A>(value->f(c));
            storeAs<A>(index1Address<B, IX>(c, *this), v);
        } else if constexpr (std::is_same_v<A, bool>) {
            uint8_t v = value->i(c) != 0;
            storeAs<uint8_t>(index1Address<B, IX>(c, *this), v);
        } else {
            A v = static_cast<A>(value->i(c));
            storeAs<A>(index1Address<B, IX>(c, *this), v);
        }
        return Flow::Next;
    }
};

// a[i] := constant: the stored bytes computed once.
template <class T, BaseKind B, IndexFrom IX>
struct AssignConstIndex1 final : Stmt, Index1Fields {
    T k;
    AssignConstIndex1(const Index1Fields& f, T v) : Index1Fields(f), k(v) {}
    Flow exec(Ctx& c) override {
        storeAs<T>(index1Address<B, IX>(c, *this), k);
        return Flow::Next;
    }
};

template <class T, BaseKind B, IndexFrom IX>
Stmt* Index1Var<T, B, IX>::makeStore(NodePool& pool, Expr* value, bool boolean) {
    if constexpr (std::is_void_v<T>) return nullptr;
    else {
        const Index1Fields& fields = *this;
        if (boolean && !std::is_same_v<T, uint8_t>) return nullptr;
        if (nodeCast<ConstInt>(value) || nodeCast<ConstReal>(value)) {
            Ctx none;  // constants read nothing from the context
            T k;
            if (boolean) k = static_cast<T>(value->i(none) != 0);
            else if constexpr (std::is_floating_point_v<T>) k = static_cast<T>(value->f(none));
            else k = static_cast<T>(value->i(none));
            return pool.make<AssignConstIndex1<T, B, IX>>(fields, k);
        }
        if (boolean) return pool.make<AssignIndex1<bool, B, IX>>(fields, value);
        return pool.make<AssignIndex1<T, B, IX>>(fields, value);
    }
}

// IF c THEN ... [ELSE ...] END_IF without a vector walk. An ELSIF chain is a
// chain of these: `otherwise` is then the next link (an If1Stmt or
// IfCompare), run directly as a part of the same statement (no tick).
struct If1Stmt final : Stmt {
    Expr* cond;
    Body then;
    Stmt* otherwise;  // may be null
    If1Stmt(Expr* k, Block* t, Stmt* e) : cond(k), then(t), otherwise(e) {}
    Flow exec(Ctx& c) override {
        if (cond->i(c)) return then.run(c);
        return otherwise ? otherwise->exec(c) : Flow::Next;
    }
};

// ---- REAL/LREAL -> integer T: the IEC rounding (half to even) or truncation
// inline for every value below 2^52 in magnitude, as RealToIntForm, with the
// width and the rounding fixed in the type (the plain conversion is common
// enough to keep its few instructions fewer).
template <class T, bool TRUNCATE>
struct ConvRealIntT final : Expr {
    Expr* a;
    int bits;
    bool isSigned;
    ConvRealIntT(Expr* x, int b, bool s) : a(x), bits(b), isSigned(s) {}
    int64_t i(Ctx& c) override {
        double v = a->f(c);
        constexpr double kTwoPow52 = 4503599627370496.0;
        if (__builtin_expect(v > -kTwoPow52 && v < kTwoPow52, 1)) {
            double whole;
            if constexpr (TRUNCATE) whole = v;  // the cast below truncates toward zero
            else {
                // Without -ffast-math the compiler keeps (v + 2^52) - 2^52 as written.
                double shifted = v >= 0 ? v + kTwoPow52 : v - kTwoPow52;
                whole = v >= 0 ? shifted - kTwoPow52 : shifted + kTwoPow52;
            }
            return wrapI(static_cast<T>(static_cast<int64_t>(whole)));
        }
        return TRUNCATE ? realToIntTruncated(v, bits, isSigned) : realToIntRounded(v, bits, isSigned);
    }
};

}  // namespace strun::exec
