#include "interpreter/testing/axunit_nodes.h"

#include <cmath>

#include "interpreter/testing/assert_text.h"

namespace strun::testing {

using sema::TK;

void CallerPlace::fill(Ctx& c, Failure& f) const {
    std::string scratch;
    if (file) f.filePath = std::string(stringArg(file, fileType, c, scratch));
    if (line) f.line = static_cast<int>(line->i(c));
}

namespace {

// -1, 0, 1: a against b, both of the same elementary type `t` (the overload
// the call chose), REAL/LREAL by value (NaN compares unequal and unordered: 2).
int compare(const sema::Type* t, const uint8_t* a, const uint8_t* b) {
    if (sema::isReal(t->kind)) {
        const double x = t->kind == TK::Real ? static_cast<double>(exec::loadAs<float>(a)) : exec::loadAs<double>(a);
        const double y = t->kind == TK::Real ? static_cast<double>(exec::loadAs<float>(b)) : exec::loadAs<double>(b);
        if (std::isnan(x) || std::isnan(y)) return 2;
        return x < y ? -1 : x > y ? 1 : 0;
    }
    if (sema::isStringType(t->kind)) {
        const std::string x = stringText(t, a), y = stringText(t, b);
        return x < y ? -1 : x > y ? 1 : 0;
    }
    uint64_t ux = 0, uy = 0;
    std::memcpy(&ux, a, std::min<size_t>(t->size, 8));
    std::memcpy(&uy, b, std::min<size_t>(t->size, 8));
    if (sema::isSignedInt(t->kind) || t->kind == TK::Time || t->kind == TK::LTime) {
        const unsigned shift = 64 - 8 * static_cast<unsigned>(std::min<size_t>(t->size, 8));
        const int64_t x = static_cast<int64_t>(ux << shift) >> shift, y = static_cast<int64_t>(uy << shift) >> shift;
        return x < y ? -1 : x > y ? 1 : 0;
    }
    return ux < uy ? -1 : ux > uy ? 1 : 0;
}

}  // namespace

int64_t AxCompareNode::i(Ctx& c) {
    if (!reg->assertionsActive()) return 0;
    alignas(8) uint8_t ba[8], bb[8];
    const uint8_t* pa = a.load(c, ba);
    const uint8_t* pb = b.load(c, bb);
    const int r = compare(a.t, pa, pb);
    bool ok = false;
    Failure f;
    switch (kind) {
        case Kind::Equal:
            ok = r == 0;
            f.expected = assertText(a.t, pa);
            f.actual = assertText(b.t, pb);
            break;
        case Kind::NotEqual:
            ok = r != 0;
            f.expected = "not " + assertText(a.t, pa);
            f.actual = assertText(b.t, pb);
            break;
        case Kind::Less:
            ok = r == -1;
            f.expected = "less than " + assertText(b.t, pb);
            f.actual = assertText(a.t, pa);
            break;
        case Kind::Greater:
            ok = r == 1;
            f.expected = "greater than " + assertText(b.t, pb);
            f.actual = assertText(a.t, pa);
            break;
    }
    if (ok) return 0;
    place.fill(c, f);
    reg->recordFailure(std::move(f));
    return 0;
}

int64_t AxFailNode::i(Ctx& c) {
    if (!reg->assertionsActive()) return 0;
    Failure f;
    std::string scratch;
    f.message = std::string(stringArg(message, messageType, c, scratch));
    place.fill(c, f);
    reg->recordFailure(std::move(f));
    return 0;
}

}  // namespace strun::testing
