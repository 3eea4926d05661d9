#include "runtime/memory_map.h"

#include <algorithm>

namespace strun::rt {

void MemoryMap::add(const void* begin, size_t size) {
    if (!begin || size == 0) return;
    auto b = reinterpret_cast<uintptr_t>(begin);
    regions_.push_back({b, b + size});
    sorted_ = false;
    hot_ = {0, 0};
}

void MemoryMap::addObject(const void* object) {
    objects_.push_back(reinterpret_cast<uintptr_t>(object));
    sorted_ = false;
}

// Registration happens before the run, lookups during it: sort once, on the first lookup.
void MemoryMap::sort() const {
    std::sort(regions_.begin(), regions_.end(), [](const Region& a, const Region& b) { return a.begin < b.begin; });
    std::sort(objects_.begin(), objects_.end());
    sorted_ = true;
}

bool MemoryMap::containsSlow(uintptr_t a, size_t size) const {
    if (!sorted_) sort();
    // The last region starting at or before `a`; regions do not overlap.
    auto it = std::upper_bound(regions_.begin(), regions_.end(), a, [](uintptr_t v, const Region& r) { return v < r.begin; });
    if (it != regions_.begin()) {
        --it;
        if (a < it->end && size <= it->end - a) {
            hot_ = *it;
            return true;
        }
    }
    Region block{0, 0};
    if (dynamic_ && dynamic_(dynamicOwner_, a, size, block.begin, block.end)) {
        hot_ = block;
        return true;
    }
    return false;
}

bool MemoryMap::isDynamic(const void* p, size_t size) const {
    uintptr_t begin = 0, end = 0;
    return dynamic_ && dynamic_(dynamicOwner_, reinterpret_cast<uintptr_t>(p), size, begin, end);
}

bool MemoryMap::isObject(const void* p) const {
    if (!sorted_) sort();
    return std::binary_search(objects_.begin(), objects_.end(), reinterpret_cast<uintptr_t>(p));
}

}  // namespace strun::rt
