#include <catch2/catch.hpp>

#include "runtime/diag_buffer.h"

using namespace strun::rt;

TEST_CASE("the diagnostic ring keeps the newest entries in order", "[diagnostics]") {
    DiagBuffer buffer(3);
    for (int i = 0; i < 7; ++i) buffer.add({PlcTime(i), DiagCode::DivByZero, "T", "P", i, "m"});
    const auto& entries = buffer.entries();
    REQUIRE(entries.size() == 3);
    CHECK(entries[0].time == 4);
    CHECK(entries[1].time == 5);
    CHECK(entries[2].time == 6);
    CHECK(buffer.dropped() == 4);
}

TEST_CASE("a ring of capacity 0 keeps nothing but counts", "[diagnostics]") {
    DiagBuffer buffer(0);
    buffer.add({});
    CHECK(buffer.entries().empty());
    CHECK(buffer.dropped() == 1);
}
