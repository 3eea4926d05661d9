// The node arena of node.h (decision 0261).
#include "interpreter/exec/node.h"

namespace strun::exec {

void* NodePool::allocate(size_t size, size_t align) {
    auto at = reinterpret_cast<uintptr_t>(next_);
    uintptr_t aligned = (at + (align - 1)) & ~static_cast<uintptr_t>(align - 1);
    if (next_ && aligned + size <= reinterpret_cast<uintptr_t>(end_)) {
        next_ = reinterpret_cast<std::byte*>(aligned + size);
        return reinterpret_cast<void*>(aligned);
    }
    // A new block (operator new[] aligns to max_align_t, which every node fits);
    // a node larger than a block gets a block of its own.
    size_t bytes = size > kBlock / 4 ? size : kBlock;
    blocks_.push_back(std::unique_ptr<std::byte[]>(new std::byte[bytes]));  // not zeroed: every node is constructed
    std::byte* block = blocks_.back().get();
    if (bytes == kBlock) {
        next_ = block + size;
        end_ = block + bytes;
    }
    return block;
}

NodePool::~NodePool() {
    for (auto it = others_.rbegin(); it != others_.rend(); ++it) it->second(it->first);
    for (auto it = stmts_.rbegin(); it != stmts_.rend(); ++it) (*it)->~Stmt();
    for (auto it = exprs_.rbegin(); it != exprs_.rend(); ++it) (*it)->~Expr();
}

}  // namespace strun::exec
