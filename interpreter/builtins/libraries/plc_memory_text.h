// Reading what a library block is handed as an address (a POINTER or the
// ADR of a STRING, carried as an integer): the JSON blocks of Tc3_JsonXml
// take documents, names and paths this way. Every read stays inside the
// project's memory map.
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>

#include "interpreter/exec/node.h"

namespace strun::stdlib::bind {

inline uint8_t* plcAddress(int64_t v) { return reinterpret_cast<uint8_t*>(static_cast<intptr_t>(v)); }

// The NUL-terminated text at `a`; false when it does not lie inside the project's memory.
inline bool readPlcText(exec::Ctx& c, int64_t a, std::string_view& out) {
    const uint8_t* p = plcAddress(a);
    if (!p || !c.m->memory.contains(p, 1)) return false;
    const size_t n = std::strlen(reinterpret_cast<const char*>(p));
    if (!c.m->memory.contains(p, n + 1)) return false;
    out = std::string_view(reinterpret_cast<const char*>(p), n);
    return true;
}

}  // namespace strun::stdlib::bind
