#include "interpreter/testing/suite_slices.h"

#include "interpreter/testing/test_registry.h"

namespace strun::testing {

bool inSlice(size_t index, size_t count, size_t k, size_t n) {
    if (n <= 1 || count == 0) return true;
    return index * n / count == k;
}

void keepSlice(TestRegistry& reg, size_t k, size_t n) {
    std::vector<Suite> kept;
    const size_t count = reg.suites.size();
    for (size_t i = 0; i < count; ++i)
        if (inSlice(i, count, k, n)) kept.push_back(std::move(reg.suites[i]));
    reg.suites = std::move(kept);
}

}  // namespace strun::testing
