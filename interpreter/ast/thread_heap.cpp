#include "interpreter/ast/thread_heap.h"

#include <array>
#include <cstdint>
#include <cstdlib>

#include <sys/mman.h>

namespace strun::ast {

void growThisThreadsHeap(std::size_t bytes) {
    constexpr std::size_t kPiece = 7u << 20;
    constexpr std::size_t kHugePage = 2u << 20;
    if (bytes < kWorthGrowing) return;
    std::array<void*, 8> pieces{};  // at most 56 MiB: a thread arena holds 64 MiB
    std::size_t count = 0;
    for (std::size_t got = 0; got < bytes && count < pieces.size(); got += kPiece) {
        void* p = std::malloc(kPiece);
        if (p == nullptr) break;
        const auto start = reinterpret_cast<std::uintptr_t>(p);
        const std::uintptr_t first = (start + kHugePage - 1) & ~(kHugePage - 1);
        const std::uintptr_t last = (start + kPiece) & ~(kHugePage - 1);
        if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
        pieces[count++] = p;
    }
    // Last first: each piece joins the free top of the arena before the one below it.
    while (count > 0) std::free(pieces[--count]);
}

}  // namespace strun::ast
