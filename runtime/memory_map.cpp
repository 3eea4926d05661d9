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

void MemoryMap::insert(const void* begin, size_t size) {
    if (!begin || size == 0) return;
    if (!sorted_) sort();
    auto b = reinterpret_cast<uintptr_t>(begin);
    auto it = std::upper_bound(regions_.begin(), regions_.end(), b, [](uintptr_t v, const Region& r) { return v < r.begin; });
    regions_.insert(it, {b, b + size});
}

void MemoryMap::remove(const void* begin) {
    if (!sorted_) sort();
    auto b = reinterpret_cast<uintptr_t>(begin);
    auto it = std::lower_bound(regions_.begin(), regions_.end(), b, [](const Region& r, uintptr_t v) { return r.begin < v; });
    if (it != regions_.end() && it->begin == b) regions_.erase(it);
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
    if (it == regions_.begin()) return false;
    --it;
    if (!(a < it->end && size <= it->end - a)) return false;
    hot_ = *it;
    return true;
}

bool MemoryMap::isObject(const void* p) const {
    if (!sorted_) sort();
    return std::binary_search(objects_.begin(), objects_.end(), reinterpret_cast<uintptr_t>(p));
}

}  // namespace strun::rt
