// Values as the debugger shows them: ST literals (TRUE, 42, T#1s500ms,
// 'text', E_State#Run), and the members of arrays, structures and FB
// instances for expanding them. Built on the --dump encoder
// (project::valueToJson), so both show the same value the same way.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "interpreter/sema/types.h"

namespace strun::editors::dap {

// The value stored at `p` as an ST literal; `bit` >= 0: one bit of the byte
// at p (BOOL at %IX0.3). Aggregates give a short summary.
std::string stLiteral(const sema::Type* t, const uint8_t* p, int bit = -1);
// Arrays, structures and FB instances: shown with members.
bool expandable(const sema::Type* t);

struct Member {
    std::string name;  // "count", "[3]"
    std::string path;  // appended to the parent's expression: ".count", "[3]"
    const sema::Type* type = nullptr;
    uint8_t* address = nullptr;
};
// The members of the aggregate at `p` (at most `limit`).
std::vector<Member> membersOf(const sema::Type* t, uint8_t* p, size_t limit = 1000);

}  // namespace strun::editors::dap
