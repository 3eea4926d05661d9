#include "grammar/arena_rule_context.h"

#include <cstdint>

#include <sys/mman.h>

namespace strun_grammar {

namespace {

// kHugeBlock bytes aligned to their size, marked MADV_HUGEPAGE (when the
// kernel's transparent huge pages are off the mark does nothing, and the
// block is ordinary pages); nullptr when mmap fails.
std::byte* mapAlignedBlock(std::size_t size) {
    void* p = mmap(nullptr, 2 * size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) return nullptr;
    const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t aligned = (start + size - 1) & ~(size - 1);
    if (aligned > start) munmap(p, aligned - start);
    const std::uintptr_t end = start + 2 * size;
    if (end > aligned + size) munmap(reinterpret_cast<void*>(aligned + size), end - (aligned + size));
    madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);
    return reinterpret_cast<std::byte*>(aligned);
}

}  // namespace

RuleContextArena::~RuleContextArena() {
    for (const Block& b : blocks_) {
        if (b.mapped) munmap(b.data, kHugeBlock);
        else delete[] b.data;
    }
}

void RuleContextArena::grow(std::size_t bytes) {
    blocks_.reserve(blocks_.size() + 1);  // push_back below cannot throw and leak the block
    std::byte* block = nullptr;
    std::size_t size = 0;
    if (held_ >= kHugeAfter && bytes <= kHugeBlock) {
        block = mapAlignedBlock(kHugeBlock);
        size = kHugeBlock;
    }
    const bool mapped = block != nullptr;
    if (!mapped) {
        size = bytes > kBlock / 4 ? bytes : kBlock;
        block = new std::byte[size];  // not zeroed: the contexts initialise themselves
    }
    blocks_.push_back({block, mapped});
    held_ += size;
    next_ = block;
    end_ = block + size;
}

}  // namespace strun_grammar
