// A zeroed block of address space whose pages are committed only when first
// touched. Task frame stacks are sized for the deepest call of the largest
// frame in the project; a never-called FUNCTION with a huge local must not
// cost that much real memory per task (docs/limits.md).
#pragma once

#include <cstddef>
#include <cstdint>

namespace strun::rt {

class ReservedMemory {
public:
    explicit ReservedMemory(std::size_t size);  // throws std::bad_alloc when the address space is exhausted
    ~ReservedMemory();
    ReservedMemory(const ReservedMemory&) = delete;
    ReservedMemory& operator=(const ReservedMemory&) = delete;
    uint8_t* data() const { return data_; }
    std::size_t size() const { return size_; }

private:
    uint8_t* data_ = nullptr;
    std::size_t size_ = 0;
};

}  // namespace strun::rt
