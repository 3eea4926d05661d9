// The memory that belongs to a running project: storage blocks (globals,
// instances), the tasks' frame stacks and fault sinks, the process image.
// A pointer moved by arithmetic, or forged through a UNION, may point
// anywhere; dereferences and method calls through pointers check it here
// first and raise NULL_POINTER instead of touching host memory
// (docs/diagnostics.md). Regions are registered before the run; lookups are
// a binary search, done only for pointer dereferences, not for ordinary
// variable access.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace strun::rt {

class MemoryMap {
public:
    void add(const void* begin, size_t size);
    // Memory that comes and goes while running (runtime/heap.h): asked when no
    // fixed region holds the range. It answers with the block [begin, end)
    // that holds [a, a + size), or false.
    using DynamicLookup = bool (*)(const void* owner, uintptr_t a, size_t size, uintptr_t& begin, uintptr_t& end);
    void setDynamic(DynamicLookup lookup, const void* owner) {
        dynamic_ = lookup;
        dynamicOwner_ = owner;
    }
    // A dynamic block went away: the last hit may have been it.
    void forgetHot() { hot_ = {0, 0}; }
    // True when [p, p + size) lies inside one registered region. The region
    // of the last hit is tried first: accesses through one reference or
    // pointer tend to stay in one block, so most checks are two compares.
    bool contains(const void* p, size_t size) const {
        auto a = reinterpret_cast<uintptr_t>(p);
        if (a >= hot_.begin && a < hot_.end && size <= hot_.end - a) return true;
        return containsSlow(a, size);
    }
    // True when [p, p + size) lies inside one block of the dynamic memory (the
    // heap of __NEW), for Tc2_System's F_CheckMemoryArea. Not on a hot path.
    bool isDynamic(const void* p, size_t size) const {
        uintptr_t begin = 0, end = 0;
        return dynamic_ && dynamic_(dynamicOwner_, reinterpret_cast<uintptr_t>(p), size, begin, end);
    }
    // Objects that may be the target of a hidden pointer (class descriptors of FB instances).
    void addObject(const void* object);
    bool isObject(const void* p) const;

private:
    void sort() const;
    bool containsSlow(uintptr_t a, size_t size) const;
    struct Region {
        uintptr_t begin, end;
    };
    mutable Region hot_{0, 0};
    mutable std::vector<Region> regions_;
    mutable std::vector<uintptr_t> objects_;
    mutable bool sorted_ = true;
    DynamicLookup dynamic_ = nullptr;
    const void* dynamicOwner_ = nullptr;
};

}  // namespace strun::rt
