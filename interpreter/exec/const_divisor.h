// Integer / and MOD by a divisor fixed at check time, computed by multiplying
// instead of dividing (decision 0490). A compiler does this for a divisor it
// sees; the interpreter's divisor is data, so `x MOD 97` used the hardware
// divide, 20-40 cycles of latency against about 10 for the multiplies, in
// code where divisions by constants are everywhere (MOD 2, / 10, MOD 1000).
//
// Same results as C++'s / and % on T: the quotient truncated toward zero,
// the remainder with the dividend's sign (IEC's DIV and MOD). Exact for
// every dividend of T and every divisor except 0 and, for a signed T, -1,
// which the checker never hands over (it reports or wraps those itself).
#pragma once

#include <cstdint>
#include <type_traits>

namespace strun::exec {

template <class T>
struct ConstDivisor {
    static_assert(std::is_integral_v<T>);
    static constexpr bool kWide = sizeof(T) == 8;
    // The magnitudes are divided, unsigned; the signs are applied after.
    using UT = std::conditional_t<kWide, uint64_t, uint32_t>;
    using U128 = unsigned __int128;

    // Narrow T (up to 32 bits): Lemire, Kaser and Kurz, "Faster remainder by
    // direct computation" (2019): with M = ceil(2^64 / d), n / d is the high
    // 64 bits of M * n and n mod d the high 64 bits of (M * n mod 2^64) * d,
    // for every 32-bit n and d. M does not fit for d = 1 (it is 0 then, which
    // still gives the remainder 0); `one` passes the dividend through instead.
    // Wide T: Granlund and Montgomery, "Division by invariant integers using
    // multiplication" (1994), figure 4.1: with l = ceil(log2 d) and
    // m = floor(2^64 * (2^l - d) / d) + 1, t = high 64 bits of m * n,
    // n / d = (t + ((n - t) >> min(l, 1))) >> max(l - 1, 0).
    uint64_t magic = 0;
    UT d = 1;       // |divisor|
    UT one = 0;     // narrow: all ones when d = 1
    UT negate = 0;  // all ones when the divisor is negative
    uint8_t shift1 = 0, shift2 = 0;  // wide only

    ConstDivisor() = default;
    explicit ConstDivisor(T k) {
        const bool negative = std::is_signed_v<T> && k < 0;
        negate = negative ? ~UT(0) : UT(0);
        d = negative ? UT(0) - UT(k) : UT(k);
        if constexpr (kWide) {
            unsigned l = 0;
            while (l < 64 && (U128(1) << l) < d) ++l;
            magic = static_cast<uint64_t>((((U128(1) << l) - d) << 64) / d + 1);
            shift1 = l < 1 ? l : 1;
            shift2 = l > 1 ? l - 1 : 0;
        } else {
            magic = d == 1 ? 0 : UINT64_MAX / d + 1;
            one = d == 1 ? ~UT(0) : UT(0);
        }
    }

    UT quotientOf(UT n) const {
        if constexpr (kWide) {
            UT t = static_cast<UT>((U128(magic) * n) >> 64);
            return (t + ((n - t) >> shift1)) >> shift2;
        } else {
            return static_cast<UT>((U128(magic) * n) >> 64) | (n & one);
        }
    }
    UT remainderOf(UT n) const {
        if constexpr (kWide) return n - quotientOf(n) * d;
        else return static_cast<UT>((U128(magic * n) * d) >> 64);
    }

    T quotient(T a) const {
        if constexpr (std::is_signed_v<T>) {
            const UT sign = a < 0 ? ~UT(0) : UT(0);
            const UT q = quotientOf((UT(a) ^ sign) - sign);
            const UT flip = sign ^ negate;
            return static_cast<T>((q ^ flip) - flip);
        } else {
            return static_cast<T>(quotientOf(UT(a)));
        }
    }
    T remainder(T a) const {
        if constexpr (std::is_signed_v<T>) {
            const UT sign = a < 0 ? ~UT(0) : UT(0);
            const UT r = remainderOf((UT(a) ^ sign) - sign);
            return static_cast<T>((r ^ sign) - sign);
        } else {
            return static_cast<T>(remainderOf(UT(a)));
        }
    }
};

}  // namespace strun::exec
