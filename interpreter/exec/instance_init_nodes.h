// Start-up code that is not an FB_init call: a declaration's own values
// written again once FB_init has run (decision 0476). Runs once per instance
// before the first cycle, never in a scan.
#pragma once

#include <cstring>
#include <utility>
#include <vector>

#include "interpreter/exec/node.h"

namespace strun::exec {

// Writes the bytes `value` (a member's declared initial value, taken from
// the initial image) at `at`, a place in an instance's memory.
struct WriteBytes final : Stmt {
    uint8_t* at;
    std::vector<uint8_t> value;
    WriteBytes(uint8_t* a, std::vector<uint8_t> v) : at(a), value(std::move(v)) {}
    Flow exec(Ctx&) override {
        std::memcpy(at, value.data(), value.size());
        return Flow::Next;
    }
};

}  // namespace strun::exec
