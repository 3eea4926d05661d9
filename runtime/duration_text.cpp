#include "runtime/duration_text.h"

#include <cstdint>

namespace strun::rt {

void appendDuration(std::string& out, PlcTime nanos) {
    out += "T#";
    // Work on the magnitude as unsigned so INT64_MIN does not overflow.
    uint64_t rest = nanos < 0 ? uint64_t(0) - uint64_t(nanos) : uint64_t(nanos);
    if (nanos < 0) out += '-';
    if (rest == 0) {
        out += "0s";
        return;
    }
    struct Unit {
        uint64_t nanos;
        const char* suffix;
    };
    static constexpr Unit kUnits[] = {
        {86'400'000'000'000ULL, "d"}, {3'600'000'000'000ULL, "h"}, {60'000'000'000ULL, "m"},
        {1'000'000'000ULL, "s"},      {1'000'000ULL, "ms"},        {1'000ULL, "us"},
        {1ULL, "ns"},
    };
    for (const Unit& unit : kUnits) {
        uint64_t count = rest / unit.nanos;
        if (count == 0) continue;
        rest -= count * unit.nanos;
        out += std::to_string(count);
        out += unit.suffix;
    }
}

std::string formatDuration(PlcTime nanos) {
    std::string text;
    appendDuration(text, nanos);
    return text;
}

}  // namespace strun::rt
