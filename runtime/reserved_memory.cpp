#include "runtime/reserved_memory.h"

#include <new>

#include <sys/mman.h>

namespace strun::rt {

ReservedMemory::ReservedMemory(std::size_t size) : size_(size ? size : 1) {
    void* p = ::mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<uint8_t*>(p);
}

ReservedMemory::~ReservedMemory() { ::munmap(data_, size_); }

}  // namespace strun::rt
