// ConstDivisor (decision 0490): / and MOD by a constant computed by
// multiplying must give exactly C++'s / and % for every dividend and every
// divisor the checker hands over (all but 0 and, signed, -1). Checked against
// the hardware division over the edges of each width and a pseudo-random
// sweep of dividends and divisors.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <vector>

#include "interpreter/exec/const_divisor.h"

using strun::exec::ConstDivisor;

namespace {

// xorshift64: a fixed, reproducible sweep.
struct Sweep {
    uint64_t s = 0x9E3779B97F4A7C15ull;
    uint64_t next() {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        return s;
    }
};

template <class T>
std::vector<T> edgeValues() {
    using L = std::numeric_limits<T>;
    std::vector<T> v = {L::max(), static_cast<T>(L::max() - 1), static_cast<T>(L::max() / 2), static_cast<T>(L::max() / 2 + 1),
                        static_cast<T>(L::max() / 3)};
    for (int64_t small : {0, 1, 2, 3, 7, 10, 97, 100, 1000}) v.push_back(static_cast<T>(small));
    for (unsigned b = 1; b < sizeof(T) * 8; ++b) {
        v.push_back(static_cast<T>(static_cast<uint64_t>(1) << b));  // wraps to MIN at the sign bit
        v.push_back(static_cast<T>((static_cast<uint64_t>(1) << b) - 1));
        v.push_back(static_cast<T>((static_cast<uint64_t>(1) << b) + 1));
    }
    if constexpr (std::is_signed_v<T>) {
        size_t n = v.size();
        for (size_t i = 0; i < n; ++i) v.push_back(static_cast<T>(0 - static_cast<std::make_unsigned_t<T>>(v[i])));
        v.push_back(L::min());
        v.push_back(static_cast<T>(L::min() + 1));
    }
    return v;
}

template <class T>
bool usableDivisor(T d) {
    if (d == 0) return false;
    if constexpr (std::is_signed_v<T>) return d != -1;
    return true;
}

template <class T>
void checkAgainstHardware(T a, T d) {
    ConstDivisor<T> k(d);
    INFO("a = " << static_cast<int64_t>(a) << " (u " << static_cast<uint64_t>(a) << "), d = " << static_cast<int64_t>(d));
    REQUIRE(k.quotient(a) == static_cast<T>(a / d));
    REQUIRE(k.remainder(a) == static_cast<T>(a % d));
}

template <class T>
void checkWidth() {
    std::vector<T> edges = edgeValues<T>();
    for (T d : edges)
        if (usableDivisor(d))
            for (T a : edges) checkAgainstHardware(a, d);
    Sweep rnd;
    for (int i = 0; i < 20000; ++i) {
        // Divisors of every magnitude: a random value shifted down by a random amount.
        T d = static_cast<T>(rnd.next() >> (rnd.next() % (sizeof(T) * 8)));
        if (!usableDivisor(d)) continue;
        for (int j = 0; j < 8; ++j) checkAgainstHardware(static_cast<T>(rnd.next()), d);
        for (T a : {T(0), std::numeric_limits<T>::min(), std::numeric_limits<T>::max(), d, static_cast<T>(d - 1)}) checkAgainstHardware(a, d);
    }
}

}  // namespace

TEST_CASE("a constant divisor divides as the hardware does, every width", "[exec][divide]") {
    checkWidth<int8_t>();
    checkWidth<uint8_t>();
    checkWidth<int16_t>();
    checkWidth<uint16_t>();
    checkWidth<int32_t>();
    checkWidth<uint32_t>();
    checkWidth<int64_t>();
    checkWidth<uint64_t>();
}

TEST_CASE("a constant divisor: every 16-bit dividend by a set of divisors", "[exec][divide]") {
    for (int d : {1, 2, 3, 5, 7, 10, 97, 255, 256, 1000, 32767, -2, -3, -7, -1000, -32768}) {
        ConstDivisor<int32_t> k(d);
        for (int32_t a = -70000; a <= 70000; ++a) {
            REQUIRE(k.quotient(a) == a / d);
            REQUIRE(k.remainder(a) == a % d);
        }
    }
}
