// PowerOfTwoDivisor (decision 0490): / and MOD by +-2^k computed by shifts
// must give exactly C++'s / and % for every dividend of every width. Checked
// against the hardware division for every power-of-two divisor of each
// width, over edge dividends and a reproducible pseudo-random sweep.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <vector>

#include "interpreter/exec/power_of_two_divisor.h"

using strun::exec::PowerOfTwoDivisor;

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
std::vector<T> edgeDividends() {
    using L = std::numeric_limits<T>;
    std::vector<T> v = {L::min(), L::max(), static_cast<T>(L::min() + 1), static_cast<T>(L::max() - 1)};
    for (int64_t small : {0, 1, 2, 3, 7, 8, 9, 100}) v.push_back(static_cast<T>(small));
    for (unsigned b = 1; b < sizeof(T) * 8; ++b)
        for (int64_t delta : {-1, 0, 1}) {
            const uint64_t p = (uint64_t(1) << b) + static_cast<uint64_t>(delta);
            v.push_back(static_cast<T>(p));
            v.push_back(static_cast<T>(0 - p));
        }
    return v;
}

template <class T>
std::vector<T> powerOfTwoDivisors() {
    std::vector<T> v;
    for (unsigned b = 1; b < sizeof(T) * 8; ++b) {
        v.push_back(static_cast<T>(uint64_t(1) << b));  // the sign bit: MIN for a signed T
        if constexpr (std::is_signed_v<T>) v.push_back(static_cast<T>(0 - (uint64_t(1) << b)));
    }
    return v;
}

template <class T>
void checkWidth() {
    Sweep rnd;
    for (T d : powerOfTwoDivisors<T>()) {
        REQUIRE(PowerOfTwoDivisor<T>::fits(d));
        PowerOfTwoDivisor<T> k(d);
        std::vector<T> dividends = edgeDividends<T>();
        for (int i = 0; i < 2000; ++i) dividends.push_back(static_cast<T>(rnd.next() >> (rnd.next() % (sizeof(T) * 8))));
        for (T a : dividends) {
            INFO("a = " << static_cast<int64_t>(a) << " (u " << static_cast<uint64_t>(a) << "), d = " << static_cast<int64_t>(d));
            REQUIRE(k.quotient(a) == static_cast<T>(a / d));
            REQUIRE(k.remainder(a) == static_cast<T>(a % d));
        }
    }
    for (int64_t other : {0, 1, 3, 6, 7, 10, 1000, 65535}) CHECK_FALSE(PowerOfTwoDivisor<T>::fits(static_cast<T>(other)));
    if constexpr (std::is_signed_v<T>) {
        CHECK_FALSE(PowerOfTwoDivisor<T>::fits(static_cast<T>(-1)));
        CHECK_FALSE(PowerOfTwoDivisor<T>::fits(static_cast<T>(-3)));
    }
}

}  // namespace

TEST_CASE("a power-of-two divisor divides by shifts as the hardware divides, every width", "[exec][divide]") {
    checkWidth<int8_t>();
    checkWidth<uint8_t>();
    checkWidth<int16_t>();
    checkWidth<uint16_t>();
    checkWidth<int32_t>();
    checkWidth<uint32_t>();
    checkWidth<int64_t>();
    checkWidth<uint64_t>();
}

TEST_CASE("a power-of-two divisor: every dividend in -70000..70000", "[exec][divide]") {
    for (int d : {2, 4, 256, 65536, -2, -8, -65536}) {
        PowerOfTwoDivisor<int32_t> k(d);
        for (int32_t a = -70000; a <= 70000; ++a) {
            REQUIRE(k.quotient(a) == a / d);
            REQUIRE(k.remainder(a) == a % d);
        }
    }
}
