#include "interpreter/exec/heap_nodes.h"

#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "interpreter/exec/stmt_nodes.h"
#include "interpreter/sema/types.h"

namespace strun::exec {

int64_t HeapNew::i(Ctx& c) {
    int64_t n = count ? count->i(c) : 1;
    if (n < 1 || static_cast<uint64_t>(n) > rt::Heap::kMaxBytes / std::max<uint32_t>(elemSize, 1)) return 0;
    uint8_t* p = c.m->heap.allocate(static_cast<size_t>(n) * elemSize);
    if (!p) return 0;
    const std::vector<uint8_t>& image = elem->defaultImage;
    if (!image.empty())
        for (int64_t k = 0; k < n; ++k) std::memcpy(p + k * elemSize, image.data(), std::min<size_t>(image.size(), elemSize));
    if (init) {
        uint8_t* saved = current;
        current = p;
        (void)init->exec(c);
        current = saved;
    }
    return static_cast<int64_t>(reinterpret_cast<intptr_t>(p));
}

int64_t HeapDelete::i(Ctx& c) {
    auto* p = reinterpret_cast<uint8_t*>(static_cast<intptr_t>(clears ? loadAs<int64_t>(pointer->addr(c)) : pointer->i(c)));
    if (!p) return 0;
    rt::Heap& heap = c.m->heap;
    if (heap.blockAt(p) == 0) {  // not the start of a live block: say what it is, release nothing
        size_t blockSize = 0;
        switch (heap.locate(p, &blockSize)) {
            case rt::Heap::Where::Released:
                reportMemoryFault(c, site, "__DELETE of memory already released by __DELETE (a double free); nothing is released");
                break;
            case rt::Heap::Where::Live:
                reportMemoryFault(c, site, fmt::format("__DELETE of a pointer into the middle of a __NEW block of {} bytes; nothing is released", blockSize));
                break;
            case rt::Heap::Where::None:
                reportMemoryFault(c, site, "__DELETE of a pointer that __NEW did not return; nothing is released");
                break;
        }
        return 0;
    }
    if (exit) {
        uint8_t* saved = current;
        current = p;
        (void)exit->exec(c);
        current = saved;
    }
    // The pointer is cleared before the block goes: it may lie inside it.
    // Its place is evaluated again, as FB_exit may have moved things.
    if (clears) storeAs<int64_t>(pointer->addr(c), 0);
    if (heap.release(p) != rt::Heap::Release::Freed)
        reportMemoryFault(c, site, "__DELETE: FB_exit released the instance itself (a double free)");
    return 0;
}

std::string heapDescription(const rt::Heap& heap, const void* p) {
    size_t size = 0;
    auto where = heap.locate(p, &size);
    // A pointer just past a block (p[n] on __NEW(T, n)) lies in no block: ask about the byte before it.
    if (where == rt::Heap::Where::None && p) where = heap.locate(static_cast<const uint8_t*>(p) - 1, &size);
    switch (where) {
        case rt::Heap::Where::Released: return "memory released by __DELETE";
        case rt::Heap::Where::Live: return fmt::format("memory past the end of a __NEW block of {} bytes", size);
        case rt::Heap::Where::None: break;
    }
    return "";
}

}  // namespace strun::exec
