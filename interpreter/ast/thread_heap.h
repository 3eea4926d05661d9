// The malloc arena of a thread about to build a large tree, grown at once
// (decision 0494).
#pragma once

#include <cstddef>

namespace strun::ast {

// glibc grows a thread's own arena (any thread but the first) only by what
// each allocation lacks, a page at a time: the AST of half a 30 000-line
// file cost 2 300 mprotect calls and as many page faults. This grows the
// arena this thread allocates from by about `bytes` (in pieces under the
// 8 MiB mmap threshold cli/main.cpp sets, so that they come from the arena),
// marks the pieces for transparent huge pages and frees them: the arena
// keeps the room (cli/main.cpp's 64 MiB trim threshold), and the tree is
// built in it. Without those two settings (a unit test, a fuzzer) the
// pieces are mapped or trimmed again, which costs a few system calls and
// changes nothing else.
// Nothing under kWorthGrowing: there the huge pages marked and not filled
// cost more than the page faults they save (8 000 lines parsed in halves:
// +4.5 % wall time with it).
void growThisThreadsHeap(std::size_t bytes);

inline constexpr std::size_t kWorthGrowing = 7u << 20;
// What the parser and the AST builder allocate (measured on
// benchmarks/generated_project.sh): about 280 bytes per token, 60 per byte of source.
inline constexpr std::size_t kTreeBytesPerToken = 280;
inline constexpr std::size_t kTreeBytesPerSourceByte = 60;

}  // namespace strun::ast
