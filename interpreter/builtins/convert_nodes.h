// Evaluator nodes of the conversions the checker leaves to the library:
// number/time <-> STRING/WSTRING (decisions 0032, 0034, 0035), BCD and byte
// order (decision 0036), IS_VALID. The value text comes from stdlib/
// (value_format, conversions, text_encoding); nothing is re-implemented here.
#pragma once

#include <cmath>
#include <string>

#include "interpreter/exec/node.h"
#include "interpreter/builtins/string_nodes.h"
#include "stdlib/conversions.h"

namespace strun::stdlib::bind {

// How a source or target value is encoded (decision 0030).
enum class ValueClass : uint8_t {
    Bool, Signed, Unsigned, Real, LReal,
    Time, LTime, Date, LDate, Tod, LTod, Dt, LDt,
    Char, WChar, String, WString,
    RealTwinCat, LRealTwinCat,  // REAL / LREAL in a TwinCAT project: "24.0" (decision 0336)
    LTimeUnsigned,              // LTIME in a TwinCAT project: unsigned nanoseconds (decision 0367)
    TimeUnsigned,               // TIME in a TwinCAT project: unsigned milliseconds (decision 0367)
};

// The text of a value as *_TO_STRING writes it (UTF-8 / raw bytes).
std::string valueText(ValueClass k, Expr* a, Ctx& c);

// X_TO_STRING / X_TO_WSTRING: Ch is the target's character type.
template <class Ch>
struct ToStringNode final : Expr {
    Expr* a;
    ValueClass from;
    uint32_t off = 0, maxLen = 0;
    ToStringNode(Expr* x, ValueClass k) : a(x), from(k) {}
    uint8_t* addr(Ctx& c) override;
};
template <>
uint8_t* ToStringNode<char>::addr(Ctx& c);
template <>
uint8_t* ToStringNode<char16_t>::addr(Ctx& c);

// STRING_TO_X / WSTRING_TO_X: `wide` tells the source kind; bits/isSigned
// describe an integer target.
struct FromStringNode final : Expr {
    Expr* a;
    bool wide;
    ValueClass to;
    int bits;
    bool isSigned;
    FromStringNode(Expr* x, bool w, ValueClass k, int b, bool s) : a(x), wide(w), to(k), bits(b), isSigned(s) {}
    int64_t i(Ctx& c) override;
    double f(Ctx& c) override;
};

// BCD: `bytes` of the BCD bit string; the integer side wraps to its width.
struct BcdToIntNode final : Expr {
    Expr* a;
    int bytes, bits;
    bool isSigned;
    BcdToIntNode(Expr* x, int n, int b, bool s) : a(x), bytes(n), bits(b), isSigned(s) {}
    int64_t i(Ctx& c) override {
        uint64_t v = stdlib::bcdToInteger(static_cast<uint64_t>(a->i(c)), bytes);
        return static_cast<int64_t>(stdlib::wrapToWidth(v, bits, isSigned));
    }
};

struct IntToBcdNode final : Expr {
    Expr* a;
    int bytes;
    explicit IntToBcdNode(Expr* x, int n) : a(x), bytes(n) {}
    int64_t i(Ctx& c) override {
        return static_cast<int64_t>(stdlib::integerToBcd(static_cast<uint64_t>(a->i(c)), bytes));
    }
};

struct IsValidBcdNode final : Expr {
    Expr* a;
    int bytes;
    IsValidBcdNode(Expr* x, int n) : a(x), bytes(n) {}
    int64_t i(Ctx& c) override { return stdlib::isValidBcd(static_cast<uint64_t>(a->i(c)), bytes); }
};

struct IsValidRealNode final : Expr {
    Expr* a;
    explicit IsValidRealNode(Expr* x) : a(x) {}
    int64_t i(Ctx& c) override { return std::isfinite(a->f(c)); }
};

enum class ByteOrderFn : uint8_t { ToBig, FromBig, ToLittle, FromLittle };

// Byte order of an integer / bit-string value of `bytes` bytes; the result
// keeps the type, so it is wrapped back (sign-extended for signed types).
struct ByteOrderNode final : Expr {
    Expr* a;
    ByteOrderFn fn;
    int bytes;
    bool isSigned;
    ByteOrderNode(Expr* x, ByteOrderFn f, int n, bool s) : a(x), fn(f), bytes(n), isSigned(s) {}
    int64_t i(Ctx& c) override {
        uint64_t v = stdlib::wrapToWidth(static_cast<uint64_t>(a->i(c)), bytes * 8, false);
        switch (fn) {
            case ByteOrderFn::ToBig: v = stdlib::toBigEndian(v, bytes); break;
            case ByteOrderFn::FromBig: v = stdlib::fromBigEndian(v, bytes); break;
            case ByteOrderFn::ToLittle: v = stdlib::toLittleEndian(v, bytes); break;
            case ByteOrderFn::FromLittle: v = stdlib::fromLittleEndian(v, bytes); break;
        }
        return static_cast<int64_t>(stdlib::wrapToWidth(v, bytes * 8, isSigned));
    }
};

}  // namespace strun::stdlib::bind
