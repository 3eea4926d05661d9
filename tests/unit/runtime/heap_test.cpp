// The __NEW/__DELETE heap (runtime/heap.h) and the memory map's regions
// added and removed while running (decision 0300).
#include <catch2/catch.hpp>

#include "runtime/heap.h"

using namespace strun::rt;

TEST_CASE("a live block is a region of the memory map until it is released", "[heap]") {
    MemoryMap map;
    uint8_t fixed[16] = {};
    map.add(fixed, sizeof fixed);
    Heap heap(map);
    uint8_t* a = heap.allocate(40);
    uint8_t* b = heap.allocate(8);
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a[0] == 0);
    CHECK(a[39] == 0);
    CHECK(map.contains(a, 40));
    CHECK(map.contains(a + 32, 8));
    CHECK_FALSE(map.contains(a + 33, 8));  // past the block's end
    CHECK(map.contains(fixed, 16));
    CHECK(heap.liveBytes() == 48);
    CHECK(heap.release(a) == Heap::Release::Freed);
    CHECK_FALSE(map.contains(a, 1));
    CHECK(map.contains(b, 8));
    CHECK(map.contains(fixed, 16));
    CHECK(heap.liveBytes() == 8);
}

TEST_CASE("a wrong release is recognised and changes nothing", "[heap]") {
    MemoryMap map;
    Heap heap(map);
    uint8_t* a = heap.allocate(16);
    uint8_t other = 0;
    CHECK(heap.release(a + 4) == Heap::Release::Interior);
    CHECK(heap.release(&other) == Heap::Release::NotHeap);
    CHECK(map.contains(a, 16));
    CHECK(heap.release(a) == Heap::Release::Freed);
    CHECK(heap.release(a) == Heap::Release::AlreadyFreed);
    size_t size = 0;
    CHECK(heap.locate(a + 3, &size) == Heap::Where::Released);
    CHECK(size == 16);
}

TEST_CASE("released memory stays until trim, then the newest 8 MiB stay", "[heap]") {
    MemoryMap map;
    Heap heap(map);
    uint8_t* big = heap.allocate(size_t{9} << 20);
    uint8_t* small = heap.allocate(64);
    REQUIRE(big);
    REQUIRE(small);
    CHECK(heap.release(big) == Heap::Release::Freed);
    CHECK(heap.release(small) == Heap::Release::Freed);
    // Not trimmed: both are still known as released.
    CHECK(heap.locate(big) == Heap::Where::Released);
    heap.trim();
    // 9 MiB + 64 B is over the quarantine: the oldest (big) goes, small stays.
    CHECK(heap.locate(big) == Heap::Where::None);
    CHECK(heap.locate(small) == Heap::Where::Released);
}

TEST_CASE("the heap is bounded", "[heap]") {
    MemoryMap map;
    Heap heap(map);
    CHECK(heap.allocate(Heap::kMaxBytes + 1) == nullptr);
    uint8_t* all = heap.allocate(Heap::kMaxBytes);
    REQUIRE(all);
    CHECK(heap.allocate(1) == nullptr);
    CHECK(heap.release(all) == Heap::Release::Freed);
    CHECK(heap.allocate(1) != nullptr);
}
