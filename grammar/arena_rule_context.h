// The base class of the generated parser's rule contexts (the grammar's
// contextSuperClass option): contexts come from the arena of the parse in
// progress, and freeing one is free.
//
// A parse makes one context per rule it enters, about five per line of ST,
// and ANTLR's tracker deletes each when the parser goes: with malloc, a
// tenth of `strun check` was allocating and freeing them (decision 0159).
// Their destructors still run (they free the contexts' label vectors).
#pragma once

#include <cstddef>
#include <new>
#include <vector>

#include <antlr4-runtime.h>

namespace strun_grammar {

// Bump allocation in blocks; everything goes when the arena does. Install
// one with Scope on the thread that parses, and keep it alive until the
// parser (whose tracker deletes the contexts) is gone.
class RuleContextArena {
public:
    RuleContextArena() = default;
    ~RuleContextArena();
    RuleContextArena(const RuleContextArena&) = delete;
    RuleContextArena& operator=(const RuleContextArena&) = delete;

    void* allocate(std::size_t bytes) {
        bytes = (bytes + kAlign - 1) & ~(kAlign - 1);
        if (bytes > static_cast<std::size_t>(end_ - next_)) grow(bytes);
        void* out = next_;
        next_ += bytes;
        return out;
    }

    // The arena of the parse running on this thread, if any.
    static RuleContextArena* current() { return current_; }

    class Scope {
    public:
        explicit Scope(RuleContextArena& arena) : previous_(current_) { current_ = &arena; }
        ~Scope() { current_ = previous_; }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        RuleContextArena* previous_;
    };

    static constexpr std::size_t kAlign = alignof(std::max_align_t);

private:
    // A new block of at least `bytes` (arena_rule_context.cpp).
    void grow(std::size_t bytes);

    // The first blocks come from the heap: most parses are small (a library
    // file, an editor's document). Once the arena holds kHugeAfter, its
    // blocks are 2 MiB of their own, aligned and marked for transparent huge
    // pages (decision 0494): a 30 000-line file makes about 12 MB of
    // contexts, a third of the pages `check` touched.
    static constexpr std::size_t kBlock = 256 * 1024;
    static constexpr std::size_t kHugeAfter = 1024 * 1024;
    static constexpr std::size_t kHugeBlock = 2 * 1024 * 1024;
    struct Block {
        std::byte* data;
        bool mapped;  // from mmap (a huge block), else from new[]
    };
    static inline thread_local constinit RuleContextArena* current_ = nullptr;
    std::vector<Block> blocks_;
    std::size_t held_ = 0;  // bytes of all blocks
    std::byte* next_ = nullptr;
    std::byte* end_ = nullptr;
};

class ArenaRuleContext : public antlr4::ParserRuleContext {
public:
    using antlr4::ParserRuleContext::ParserRuleContext;
    ArenaRuleContext() = default;

    // Each allocation starts with a header saying where it came from: a
    // context made with no arena installed comes from the heap and goes
    // back to it.
    static void* operator new(std::size_t bytes) {
        RuleContextArena* arena = RuleContextArena::current();
        std::byte* block = static_cast<std::byte*>(arena != nullptr ? arena->allocate(bytes + kHeader)
                                                                     : ::operator new(bytes + kHeader));
        *reinterpret_cast<bool*>(block) = arena != nullptr;
        return block + kHeader;
    }
    static void operator delete(void* p) noexcept {
        if (p == nullptr) return;
        std::byte* block = static_cast<std::byte*>(p) - kHeader;
        if (!*reinterpret_cast<bool*>(block)) ::operator delete(block);
    }

private:
    static constexpr std::size_t kHeader = RuleContextArena::kAlign;
};

}  // namespace strun_grammar
