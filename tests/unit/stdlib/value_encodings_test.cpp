#include <catch2/catch.hpp>

#include <limits>

#include "stdlib/calendar.h"
#include "stdlib/value_encodings.h"

using namespace strun::stdlib;

TEST_CASE("TIME is int32 milliseconds", "[value_encodings]") {
    CHECK(timeValueToNs(-250) == -250 * kNsPerMs);
    CHECK(timeValueToNs(std::numeric_limits<int32_t>::max()) == int64_t{2147483647} * kNsPerMs);
    CHECK(nsToTimeValue(1500 * kNsPerMs).value() == 1500);
    CHECK(nsToTimeValue(-250 * kNsPerMs).value() == -250);
    CHECK(nsToTimeValue(1'900'000).value() == 1);    // T#1.9ms -> 1 ms
    CHECK(nsToTimeValue(-1'900'000).value() == -1);  // truncation toward zero
    CHECK(nsToTimeValue(int64_t{2147483647} * kNsPerMs).value() == 2147483647);
    CHECK(nsToTimeValue(int64_t{-2147483648} * kNsPerMs).value() == -2147483647 - 1);
    CHECK_FALSE(nsToTimeValue(int64_t{2147483648} * kNsPerMs).ok());
    CHECK_FALSE(nsToTimeValue(INT64_MIN).ok());
}

TEST_CASE("DATE is uint32 seconds at midnight", "[value_encodings]") {
    CHECK(dateValueToNs(86400) == kNsPerDay);
    CHECK(nsToDateValue(20484 * kNsPerDay).value() == 20484u * 86400u);
    CHECK(nsToDateValue(20484 * kNsPerDay + 5 * kNsPerHour).value() == 20484u * 86400u);  // time dropped
    CHECK(nsToDateValue(0).value() == 0);
    CHECK_FALSE(nsToDateValue(-kNsPerDay).ok());
    CHECK_FALSE(nsToDateValue(-1).ok());
    CHECK(nsToDateValue(int64_t{49710} * kNsPerDay).value() == 49710u * 86400u);  // 2106-02-07
    CHECK_FALSE(nsToDateValue(int64_t{49711} * kNsPerDay).ok());
}

TEST_CASE("TOD is uint32 milliseconds since midnight", "[value_encodings]") {
    CHECK(todValueToNs(1000) == kNsPerSecond);
    CHECK(nsToTodValue(13 * kNsPerHour + 250 * kNsPerMs).value() == 13u * 3600000u + 250u);
    CHECK(nsToTodValue(kNsPerDay - 1).value() == 86399999u);
    CHECK_FALSE(nsToTodValue(kNsPerDay).ok());
    CHECK_FALSE(nsToTodValue(-1).ok());
}

TEST_CASE("DT is uint32 seconds", "[value_encodings]") {
    CHECK(dtValueToNs(1) == kNsPerSecond);
    CHECK(nsToDtValue(kNsPerDay + 1500 * kNsPerMs).value() == 86401u);  // sub-second dropped
    CHECK(nsToDtValue(int64_t{4294967295} * kNsPerSecond).value() == 4294967295u);
    CHECK_FALSE(nsToDtValue(int64_t{4294967296} * kNsPerSecond).ok());
    CHECK_FALSE(nsToDtValue(-1).ok());
    CHECK(nsToDtValue(-1).error().find("LDT") != std::string::npos);
}
