#include "runtime/diag_buffer.h"

namespace strun::rt {

void DiagBuffer::add(DiagEntry entry) {
    if (capacity_ == 0) {
        ++dropped_;
        return;
    }
    if (ring_.size() < capacity_) {
        ring_.push_back(std::move(entry));
        return;
    }
    ring_[oldest_] = std::move(entry);
    oldest_ = (oldest_ + 1) % capacity_;
    ++dropped_;
}

const std::vector<DiagEntry>& DiagBuffer::entries() const {
    if (oldest_ == 0) return ring_;
    ordered_.clear();
    ordered_.reserve(ring_.size());
    for (size_t i = 0; i < ring_.size(); ++i) ordered_.push_back(ring_[(oldest_ + i) % ring_.size()]);
    return ordered_;
}

}  // namespace strun::rt
