#pragma once
// REF_TO ARRAY[*] OF T (SIMATIC AX, decision 0402): the reference variable
// holds the same descriptor an ARRAY[*] parameter's slot holds,
// { address, lo0, hi0, lo1, hi1, ... }; address 0 is NULL.
#include <cstdint>
#include <vector>

#include "interpreter/exec/call_nodes.h"

namespace strun::exec {

// ref^ where a descriptor is read whole (LOWER_BOUND / UPPER_BOUND, binding
// an ARRAY[*] parameter): the reference's own place, or, when it is NULL, a
// NULL_POINTER fault and the descriptor of an empty array in the fault sink.
struct FlexRefDesc final : Expr {
    Expr* slot;  // place of the reference variable
    Site site;
    size_t dims;
    FlexRefDesc(Expr* s, Site st, size_t n) : slot(s), site(st), dims(n) {}
    uint8_t* addr(Ctx& c) override {
        uint8_t* d = slot->addr(c);
        if (__builtin_expect(loadAs<uint8_t*>(d) == nullptr, 0)) return unbound(c);
        return d;
    }
    uint8_t* unbound(Ctx& c);
};

// ref^[i, j]: as FlexIndexPlace, after the NULL test (one fault, not a
// NULL_POINTER followed by an ARRAY_BOUNDS).
struct FlexRefIndexPlace final : Expr {
    Expr* slot;  // place of the reference variable
    std::vector<Expr*> index;
    uint64_t elemSize = 0;
    Site site;
    uint8_t* addr(Ctx& c) override {
        uint8_t* d = slot->addr(c);
        uint8_t* base = loadAs<uint8_t*>(d);
        if (__builtin_expect(base == nullptr, 0)) return unbound(c);
        uint64_t element;
        int64_t v, lo, hi;
        if (!flexElement(c, d, index, element, v, lo, hi)) return outOfRange(c, v, lo, hi);
        return base + element * elemSize;
    }
    uint8_t* unbound(Ctx& c);
    uint8_t* outOfRange(Ctx& c, int64_t v, int64_t lo, int64_t hi);
};

}  // namespace strun::exec
