// Anonymous mappings for the process image (runtime/machine.h): the kernel
// hands out zero pages on first touch, so an area nobody addresses costs
// one system call and no memory. Also ProcessImage's constructors and
// destructor (declared out of line in machine.h).
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

ProcessImage::ProcessImage() = default;
ProcessImage::ProcessImage(const ProcessImage&) = default;
ProcessImage::ProcessImage(ProcessImage&&) noexcept = default;
ProcessImage& ProcessImage::operator=(const ProcessImage&) = default;
ProcessImage& ProcessImage::operator=(ProcessImage&&) noexcept = default;
ProcessImage::~ProcessImage() = default;

}  // namespace strun::rt
