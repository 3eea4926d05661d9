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
// calling thread if such a thread cannot be created, and runs there
// directly when that is a thread this file started. `work` must not throw.
void runWithLargeStack(const std::function<void()>& work, std::size_t stackBytes = kParserStackBytes);

// Runs `a` and `b` at the same time, each on a thread with a large stack,
// and returns when both are done (one after the other on the calling
// thread's helpers if a thread cannot be created). Neither may throw.
void runInParallelWithLargeStacks(const std::function<void()>& a, const std::function<void()>& b,
                                  std::size_t stackBytes = kParserStackBytes);

}  // namespace strun::ast
