// Anonymous mappings for the process image (runtime/machine.h): the kernel
// hands out zero pages on first touch, so an area nobody addresses costs
// one system call and no memory.
#include <sys/mman.h>

#include <new>

#include "runtime/machine.h"

namespace strun::rt {

void* allocateZeroedPages(size_t bytes) {
    if (bytes == 0) return nullptr;
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    return p;
}

void freeZeroedPages(void* p, size_t bytes) {
    if (p != nullptr) munmap(p, bytes);
}

}  // namespace strun::rt
