#include "runtime/heap.h"

#include <iterator>
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
    map_.forgetHot();
    liveBytes_ -= it->second.size;
    releasedBytes_ += it->second.size;
    releasedAt_[a] = it->second.size;
    released_.emplace_back(a, std::move(it->second));
    live_.erase(it);
    trimDue_ = releasedBytes_ > kQuarantineBytes || released_.size() > kQuarantineBlocks;
    return Release::Freed;
}

void Heap::trimSlow() {
    while ((releasedBytes_ > kQuarantineBytes || released_.size() > kQuarantineBlocks) && !released_.empty()) {
        releasedBytes_ -= released_.front().second.size;
        releasedAt_.erase(released_.front().first);
        released_.pop_front();
    }
    trimDue_ = false;
}

bool Heap::holds(const void* heap, uintptr_t a, size_t size, uintptr_t& begin, uintptr_t& end) {
    const auto& live = static_cast<const Heap*>(heap)->live_;
    auto it = live.upper_bound(a);
    if (it == live.begin()) return false;
    --it;
    if (!(a - it->first < it->second.size && size <= it->second.size - (a - it->first))) return false;
    begin = it->first;
    end = it->first + it->second.size;
    return true;
}

size_t Heap::blockAt(const void* p) const {
    auto it = live_.find(reinterpret_cast<uintptr_t>(p));
    return it == live_.end() ? 0 : it->second.size;
}

Heap::Where Heap::locate(const void* p, size_t* blockSize) const {
    auto a = reinterpret_cast<uintptr_t>(p);
    // The last block starting at or before a, in each map.
    auto live = live_.upper_bound(a);
    if (live != live_.begin() && a - std::prev(live)->first < std::prev(live)->second.size) {
        if (blockSize) *blockSize = std::prev(live)->second.size;
        return Where::Live;
    }
    auto released = releasedAt_.upper_bound(a);
    if (released != releasedAt_.begin() && a - std::prev(released)->first < std::prev(released)->second) {
        if (blockSize) *blockSize = std::prev(released)->second;
        return Where::Released;
    }
    return Where::None;
}

}  // namespace strun::rt
