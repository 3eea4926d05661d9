// The parser's rule-context arena (grammar/arena_rule_context.h): bump
// allocation in blocks, the blocks past the first MiB 2 MiB of their own,
// aligned for transparent huge pages (decision 0494).
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

#include "grammar/arena_rule_context.h"

using strun_grammar::RuleContextArena;

TEST_CASE("rule-context arena: 8 MiB of allocations, every one intact, later blocks 2 MiB-aligned", "[arena]") {
    RuleContextArena arena;
    constexpr std::size_t kPiece = 1000;  // rounded up to the arena's alignment
    constexpr std::size_t kPieces = 8 * 1024;
    std::vector<unsigned char*> pieces;
    std::vector<std::uintptr_t> blockStarts;  // where a piece does not follow the one before
    std::uintptr_t expected = 0;
    for (std::size_t i = 0; i < kPieces; ++i) {
        auto* p = static_cast<unsigned char*>(arena.allocate(kPiece));
        const auto at = reinterpret_cast<std::uintptr_t>(p);
        CHECK(at % RuleContextArena::kAlign == 0);
        if (at != expected) blockStarts.push_back(at);
        expected = at + ((kPiece + RuleContextArena::kAlign - 1) & ~(RuleContextArena::kAlign - 1));
        std::memset(p, static_cast<int>(i & 0xff), kPiece);
        pieces.push_back(p);
    }
    for (std::size_t i = 0; i < kPieces; ++i) {
        const unsigned char want = static_cast<unsigned char>(i & 0xff);
        if (pieces[i][0] != want || pieces[i][kPiece - 1] != want) FAIL("piece " << i << " was overwritten");
    }
    // Four 256 KiB blocks from the heap, then 2 MiB blocks at 2 MiB boundaries.
    REQUIRE(blockStarts.size() >= 6);
    for (std::size_t b = 4; b < blockStarts.size(); ++b) CHECK(blockStarts[b] % (2 * 1024 * 1024) == 0);
}

TEST_CASE("rule-context arena: a piece larger than a block gets a block of its own", "[arena]") {
    RuleContextArena arena;
    auto* small = static_cast<unsigned char*>(arena.allocate(64));
    auto* large = static_cast<unsigned char*>(arena.allocate(3 * 1024 * 1024));
    std::memset(large, 0xab, 3 * 1024 * 1024);
    std::memset(small, 0x11, 64);
    CHECK(large[0] == 0xab);
    CHECK(large[3 * 1024 * 1024 - 1] == 0xab);
    CHECK(small[63] == 0x11);
}
