// The dynamic memory of a running project: the blocks CODESYS/TwinCAT
// `__NEW` allocates and `__DELETE` releases (docs/decisions/0300). The
// project's MemoryMap asks the heap about an address no fixed region holds,
// so a pointer into a live block is checked like any other dereference
// (an ordered map: allocation, release and lookup are logarithmic); a released block leaves the map at
// once, so a dangling pointer faults instead of reaching host memory.
// Released blocks keep their host memory until the scheduler calls trim()
// with no activation in progress (code may still run on an instance it has
// just released: `__DELETE(pSelf); count := count + 1;` must not touch freed
// host memory), and then the newest 8 MiB of them stay reserved (a
// quarantine), so a second __DELETE, or a dereference, of a recently
// released block is recognised as such. The heap is bounded
// (docs/limits.md); past a bound __NEW yields 0, as on the PLC when its heap
// is exhausted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <map>

#include "runtime/memory_map.h"

namespace strun::rt {

class Heap {
public:
    static constexpr size_t kMaxBytes = size_t{64} << 20;        // live bytes, all blocks together
    static constexpr size_t kMaxBlocks = 100000;                 // live blocks
    static constexpr size_t kQuarantineBytes = size_t{8} << 20;  // released bytes kept reserved after trim()
    static constexpr size_t kQuarantineBlocks = 10000;           // ... and released blocks
    // Released but not yet trimmed (within one activation) at most: past
    // either, __NEW gives 0 until the activation ends.
    static constexpr size_t kMaxWaitingBytes = size_t{64} << 20;
    static constexpr size_t kMaxWaitingBlocks = 100000;

    explicit Heap(MemoryMap& map) : map_(map) { map.setDynamic(&Heap::holds, this); }
    Heap(const Heap&) = delete;
    Heap& operator=(const Heap&) = delete;

    // A zeroed block of `size` bytes (at least 1) registered in the memory
    // map, or nullptr when the bound would be passed.
    uint8_t* allocate(size_t size);

    enum class Release { Freed, AlreadyFreed, Interior, NotHeap };
    // Releases the block starting at p; anything else is refused untouched.
    Release release(const void* p);

    // The size of the live block that starts at p; 0 when none does.
    size_t blockAt(const void* p) const;

    // What p is, for a fault message: the start or inside of a live block
    // (size of the block in *blockSize), of a released one, or neither.
    // Ordered maps: a lookup is logarithmic, also in a loop of faults.
    enum class Where { Live, Released, None };
    Where locate(const void* p, size_t* blockSize = nullptr) const;

    // With no activation in progress (the scheduler, once per activation):
    // gives back the host memory of released blocks beyond the quarantine.
    // One load and branch per activation: release() sets trimDue_.
    void trim() {
        if (__builtin_expect(trimDue_, 0)) trimSlow();
    }

    size_t liveBytes() const { return liveBytes_; }
    size_t liveBlocks() const { return live_.size(); }

private:
    void trimSlow();
    // MemoryMap::DynamicLookup: the live block holding [a, a + size).
    static bool holds(const void* heap, uintptr_t a, size_t size, uintptr_t& begin, uintptr_t& end);
    struct Block {
        std::unique_ptr<uint8_t[]> data;
        size_t size;
    };
    MemoryMap& map_;
    std::map<uintptr_t, Block> live_;
    std::deque<std::pair<uintptr_t, Block>> released_;  // oldest first
    std::map<uintptr_t, size_t> releasedAt_;            // the same blocks by address: their sizes
    size_t liveBytes_ = 0;
    size_t releasedBytes_ = 0;
    bool trimDue_ = false;  // the quarantine is over its bounds
};

}  // namespace strun::rt
