// See atn_heap.h. The replacement operator new and delete are the whole
// program's; they differ from the library's only while a Scope is open on
// the calling thread, and by one range test in operator delete.
#include "grammar/atn_heap.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

#include <sys/mman.h>

namespace strun_grammar {

namespace {

// One region of address space, reserved at the first Scope; its first part
// is faulted in by one call instead of a page fault per page. The parser's
// ATN takes about 200 KB of it; if it ever took more than the region holds,
// the rest would come from malloc.
constexpr std::size_t kRegion = 4u << 20;
constexpr std::size_t kPrefault = 256u << 10;
constexpr std::size_t kAlign = alignof(std::max_align_t);

std::byte* regionStart = nullptr;
std::byte* next = nullptr;
thread_local bool open = false;

#ifndef STRUN_SANITIZED  // the sanitizers' own operator new keeps its checks: no region there
std::byte* regionEnd = nullptr;
// regionStart as a number for operator delete's one unsigned comparison:
// until the region exists, the last kRegion bytes of the address space
// (kernel addresses, never a pointer new returned; a null pointer falls in
// too, and deleting it does nothing either way).
std::uintptr_t regionBase = ~std::uintptr_t(0) - kRegion + 1;

void reserveRegion() {
    void* p = mmap(nullptr, kRegion, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) return;
#ifdef MADV_POPULATE_WRITE
    madvise(p, kPrefault, MADV_POPULATE_WRITE);  // Linux 5.14 and later; elsewhere the pages fault in one by one
#endif
    regionStart = next = static_cast<std::byte*>(p);
    regionEnd = regionStart + kRegion;
    regionBase = reinterpret_cast<std::uintptr_t>(p);
}

void* fromRegion(std::size_t bytes) {
    bytes = (bytes + kAlign - 1) & ~(kAlign - 1);
    if (bytes > static_cast<std::size_t>(regionEnd - next)) return nullptr;
    void* out = next;
    next += bytes;
    return out;
}

bool inRegion(void* p) { return reinterpret_cast<std::uintptr_t>(p) - regionBase < kRegion; }

void* allocate(std::size_t bytes) {
    if (open) [[unlikely]] {
        if (void* p = fromRegion(bytes)) return p;
    }
    if (bytes == 0) bytes = 1;
    for (;;) {
        if (void* p = std::malloc(bytes)) return p;
        std::new_handler handler = std::get_new_handler();
        if (handler == nullptr) throw std::bad_alloc();
        handler();
    }
}

void release(void* p) noexcept {
    if (inRegion(p)) [[unlikely]]
        return;
    std::free(p);
}
#endif

}  // namespace

AtnHeap::Scope::Scope() {
#ifndef STRUN_SANITIZED
    if (regionStart == nullptr) reserveRegion();
    open = regionStart != nullptr;
#endif
}

AtnHeap::Scope::~Scope() { open = false; }

unsigned long AtnHeap::bytesUsed() { return static_cast<unsigned long>(next - regionStart); }

}  // namespace strun_grammar

#ifndef STRUN_SANITIZED
void* operator new(std::size_t bytes) { return strun_grammar::allocate(bytes); }
void* operator new[](std::size_t bytes) { return strun_grammar::allocate(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
    try {
        return strun_grammar::allocate(bytes);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept { return operator new(bytes, std::nothrow); }
void operator delete(void* p) noexcept { strun_grammar::release(p); }
void operator delete[](void* p) noexcept { strun_grammar::release(p); }
void operator delete(void* p, std::size_t) noexcept { strun_grammar::release(p); }
void operator delete[](void* p, std::size_t) noexcept { strun_grammar::release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { strun_grammar::release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { strun_grammar::release(p); }
#endif
