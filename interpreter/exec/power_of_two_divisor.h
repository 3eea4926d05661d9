// Integer / and MOD by a constant power of two, +-2^k with k >= 1 (decision
// 0490). A compiler divides by a constant power of two with shifts; the
// interpreter's divisor is data, so `x MOD 2`, `x / 4` and `seed MOD 65536`
// (most of the constant divisors of PLC code) ran the hardware divide.
// Other constant divisors keep it (the decision says why).
//
// Same results as C++'s / and % on T: the quotient truncated toward zero,
// the remainder with the dividend's sign (IEC's DIV and MOD): a negative
// dividend is biased by 2^k - 1 before the arithmetic shift. Computed in 64
// bits, where no T overflows (and INT64_MIN + the bias does not).
#pragma once

#include <cstdint>
#include <type_traits>

namespace strun::exec {

// Whether a divisor of magnitude `m` is 2^k with k >= 1 (not 0 or 1).
constexpr bool isPowerOfTwoDivisor(uint64_t m) { return m >= 2 && (m & (m - 1)) == 0; }

template <class T>
struct PowerOfTwoDivisor {
    static_assert(std::is_integral_v<T> && sizeof(T) <= 8);
    uint8_t shift = 1;     // k
    uint64_t low = 1;      // 2^k - 1
    uint64_t negate = 0;   // all ones when the divisor is negative

    // Whether `k` is +-2^k with k >= 1 (not 1, 0 or, signed, -1).
    static bool fits(T k) { return isPowerOfTwoDivisor(magnitude(k)); }
    PowerOfTwoDivisor() = default;
    explicit PowerOfTwoDivisor(T k)
        : shift(static_cast<uint8_t>(__builtin_ctzll(magnitude(k)))), low(magnitude(k) - 1),
          negate(std::is_signed_v<T> && k < 0 ? ~uint64_t(0) : 0) {}

    T quotient(T a) const {
        if constexpr (std::is_signed_v<T>) {
            const int64_t v = a;
            const uint64_t q = static_cast<uint64_t>((v + bias(v)) >> shift);
            return static_cast<T>((q ^ negate) - negate);
        } else {
            return static_cast<T>(a >> shift);
        }
    }
    T remainder(T a) const {
        if constexpr (std::is_signed_v<T>) {
            const int64_t v = a;
            return static_cast<T>(static_cast<uint64_t>(v) - (static_cast<uint64_t>(v + bias(v)) & ~low));
        } else {
            return static_cast<T>(a & low);
        }
    }

private:
    static uint64_t magnitude(T k) {
        if constexpr (std::is_signed_v<T>) return k < 0 ? 0 - static_cast<uint64_t>(static_cast<int64_t>(k)) : static_cast<uint64_t>(k);
        else return static_cast<uint64_t>(k);
    }
    int64_t bias(int64_t v) const { return static_cast<int64_t>(static_cast<uint64_t>(v >> 63) & low); }
};

}  // namespace strun::exec
