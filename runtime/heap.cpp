#include "runtime/heap.h"

#include <new>

namespace strun::rt {

uint8_t* Heap::allocate(size_t size) {
    if (size == 0) size = 1;
    if (size > kMaxBytes - liveBytes_ || live_.size() >= kMaxBlocks) return nullptr;
    if (releasedBytes_ > kMaxWaitingBytes || released_.size() >= kMaxWaitingBlocks) return nullptr;
    std::unique_ptr<uint8_t[]> data(new (std::nothrow) uint8_t[size]());
    if (!data) return nullptr;
    uint8_t* p = data.get();
    live_.emplace(reinterpret_cast<uintptr_t>(p), Block{std::move(data), size});
    liveBytes_ += size;
    map_.insert(p, size);
    return p;
}

Heap::Release Heap::release(const void* p) {
    auto a = reinterpret_cast<uintptr_t>(p);
    auto it = live_.find(a);
    if (it == live_.end()) {
        switch (locate(p)) {
        case Where::Live: return Release::Interior;
        case Where::Released: return Release::AlreadyFreed;
        case Where::None: return Release::NotHeap;
        }
    }
    map_.remove(p);
    liveBytes_ -= it->second.size;
    releasedBytes_ += it->second.size;
    released_.emplace_back(a, std::move(it->second));
    live_.erase(it);
    trimDue_ = releasedBytes_ > kQuarantineBytes || released_.size() > kQuarantineBlocks;
    return Release::Freed;
}

void Heap::trimSlow() {
    while ((releasedBytes_ > kQuarantineBytes || released_.size() > kQuarantineBlocks) && !released_.empty()) {
        releasedBytes_ -= released_.front().second.size;
        released_.pop_front();
    }
    trimDue_ = false;
}

Heap::Where Heap::locate(const void* p, size_t* blockSize) const {
    auto a = reinterpret_cast<uintptr_t>(p);
    // Only on fault paths and __DELETE of a non-block: a linear search is enough.
    for (const auto& [begin, block] : live_)
        if (a >= begin && a - begin < block.size) {
            if (blockSize) *blockSize = block.size;
            return Where::Live;
        }
    for (const auto& [begin, block] : released_)
        if (a >= begin && a - begin < block.size) {
            if (blockSize) *blockSize = block.size;
            return Where::Released;
        }
    return Where::None;
}

}  // namespace strun::rt
