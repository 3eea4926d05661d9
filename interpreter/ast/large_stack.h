// Runs a function on a helper thread with a large stack. The parser and the
// tree builder recurse once per nesting level; nesting is capped (see
// nesting_guard.h), and this gives that cap a wide safety margin whatever
// thread parseFile is called from.
#pragma once

#include <cstddef>
#include <functional>

namespace strun::ast {

inline constexpr std::size_t kParserStackBytes = std::size_t{256} << 20;

// Runs `work` to completion on a thread whose stack is `stackBytes` (the
// memory is reserved, and only committed as it is used). Falls back to the
// calling thread if such a thread cannot be created. `work` must not throw.
void runWithLargeStack(const std::function<void()>& work, std::size_t stackBytes = kParserStackBytes);

}  // namespace strun::ast
