#include "interpreter/testing/tcunit_nodes.h"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "interpreter/testing/assert_text.h"
#include "runtime/fnv1a.h"

namespace strun::testing {

using exec::loadAs;
using sema::TK;

std::string_view stringArg(Expr* e, const sema::Type* t, Ctx& c, std::string& scratch) {
    if (!e) return {};
    const uint8_t* p = e->addr(c);
    if (t->kind == TK::String) return std::string_view(reinterpret_cast<const char*>(p), stringLength(t, p));
    scratch = stringText(t, p);
    return scratch;
}

int64_t AdsLogNode::i(Ctx& c) {
    // TcUnit queues only ADSLOG_MSGTYPE_ERROR (16#4) when LogExtendedResults is FALSE.
    constexpr int64_t kAdsLogError = 4;
    if (reg && !reg->logExtendedResults && (mask ? mask->i(c) : 0) != kAdsLogError) return 0;
    std::string s1, s2;
    std::string text(stringArg(format, formatType, c, s1));
    std::string_view value = stringArg(arg, argType, c, s2);
    size_t at = text.find("%s");
    if (at != std::string::npos) text.replace(at, 2, value);
    std::cerr << text << '\n';
    return 0;
}

int64_t SuiteQueryNode::i(Ctx& c) {
    const Suite* s = reg->suiteAt(reinterpret_cast<const uint8_t*>(self->i(c)));
    if (!s) return 0;
    int64_t failed = 0, skipped = 0;
    for (const auto& t : s->tests) {
        if (t.skipped) ++skipped;
        else if (!t.failures.empty()) ++failed;
    }
    const int64_t total = static_cast<int64_t>(s->tests.size());
    switch (what) {
        case What::Tests: return total;
        case What::Failed: return failed;
        case What::Skipped: return skipped;
        case What::Successful: return total - failed - skipped;  // TcUnit counts unfinished tests here too
        case What::AllFinished: return s->finished();
        case What::TestFinished: {
            std::string_view n = stringArg(name, nameType, c, scratch);
            while (!n.empty() && n.front() == ' ') n.remove_prefix(1);
            while (!n.empty() && n.back() == ' ') n.remove_suffix(1);
            for (const auto& t : s->tests)
                if (t.name == n) return t.finished;
            return 0;
        }
    }
    return 0;
}

uint64_t hashBytes(uint64_t h, const void* p, size_t n) { return rt::fnv1a(h, p, n); }

void AssertBase::note(Ctx& c, uint64_t values) {
    std::string scratch;
    std::string_view text = stringArg(message, messageType, c, scratch);
    uint64_t h = hashBytes(values, &file, sizeof file);
    h = hashBytes(h, &line, sizeof line);
    reg->noteAssertion(hashBytes(h, text.data(), text.size()));
}

void AssertBase::fail(Ctx& c, std::string expected, std::string actual, const char* messageSuffix) {
    Failure f;
    f.file = file;
    f.line = line;
    f.expected = std::move(expected);
    f.actual = std::move(actual);
    std::string scratch;
    f.message = std::string(stringArg(message, messageType, c, scratch)) + messageSuffix;
    reg->recordFailure(std::move(f));
}

int64_t AssertConditionNode::i(Ctx& c) {
    if (!reg->assertionsActive()) return 0;
    bool value = condition->i(c) != 0;
    note(c, hashBytes(rt::kFnv1aBasis, &value, sizeof value));
    if (value != expected) fail(c, expected ? "TRUE" : "FALSE", value ? "TRUE" : "FALSE");
    return 0;
}

const uint8_t* Operand::load(Ctx& c, uint8_t* buf) const {
    if (sema::isAggregate(t)) return e->addr(c);
    if (t->kind == TK::Real) {
        float v = static_cast<float>(e->f(c));
        std::memcpy(buf, &v, sizeof v);
    } else if (t->kind == TK::LReal) {
        double v = e->f(c);
        std::memcpy(buf, &v, sizeof v);
    } else {
        int64_t v = e->i(c);  // little-endian: the low `size` bytes are the stored value
        std::memcpy(buf, &v, sizeof v);
    }
    return buf;
}

namespace {

double realAt(const sema::Type* t, const uint8_t* p) {
    return t->kind == TK::Real ? static_cast<double>(loadAs<float>(p)) : loadAs<double>(p);
}

// Equal as an assertion of type t sees it (REAL/LREAL within `delta` when one is given).
bool sameValue(const sema::Type* t, const uint8_t* a, const sema::Type* tb, const uint8_t* b, const double* delta) {
    if (sema::isReal(t->kind)) {
        double x = realAt(t, a), y = realAt(tb, b);
        return delta ? !(std::fabs(x - y) > *delta) : x == y;
    }
    if (sema::isStringType(t->kind)) {
        size_t n = stringLength(t, a);
        if (n != stringLength(tb, b)) return false;
        return std::memcmp(a, b, n * (t->kind == TK::String ? 1 : 2)) == 0;
    }
    return std::memcmp(a, b, t->size) == 0;
}

bool sameClass(const sema::Type* a, const sema::Type* b) {
    auto cls = [](TK k) { return k == TK::FunctionBlock ? TK::Struct : k; };
    return cls(a->kind) == cls(b->kind);
}

}  // namespace

int64_t AssertEqualsNode::i(Ctx& c) {
    if (!reg->assertionsActive()) return 0;
    alignas(8) uint8_t be[8], ba[8];
    const uint8_t* pe = expected.load(c, be);
    const uint8_t* pa = actual.load(c, ba);
    const sema::Type* te = expected.t;
    const sema::Type* ta = actual.t;
    auto bytes = [](const sema::Type* t, const uint8_t* p) -> size_t {
        if (sema::isStringType(t->kind)) return stringLength(t, p) * (t->kind == TK::String ? 1 : 2);
        return t->size;
    };
    note(c, hashBytes(hashBytes(rt::kFnv1aBasis, pe, bytes(te, pe)), pa, bytes(ta, pa)));
    double d = 0;
    const double* dp = nullptr;
    if (delta) {
        d = delta->f(c);
        dp = &d;
    }
    if (te->kind == TK::WString && ta->kind == TK::WString && (!generic || stringLength(te, pe) == stringLength(ta, pa))) {
        // TcUnit does not print WSTRING values (its log is ASCII): these are its texts.
        if (!sameValue(te, pe, ta, pa, nullptr))
            fail(c, "Not possible to print EXP unicode WSTRING value", "Not possible to print ACT unicode WSTRING value");
        return 0;
    }
    if (!generic) {
        if (!sameValue(te, pe, ta, pa, dp)) fail(c, assertText(te, pe), assertText(ta, pa));
        return 0;
    }
    // AssertEquals(ANY): type class, then size, then content (TcUnit's order).
    if (!sameClass(te, ta)) {
        fail(c, "(Type class = " + typeClassName(te) + ")", "(Type class = " + typeClassName(ta) + ")");
        return 0;
    }
    if (sema::isStringType(te->kind)) {
        size_t ne = stringLength(te, pe), na = stringLength(ta, pa);
        if (ne != na) {
            const char* what = te->kind == TK::String ? "(Data size (LEN) = " : "(Data size (WLEN) = ";
            fail(c, what + std::to_string(ne) + ")", what + std::to_string(na) + ")");
        } else if (!sameValue(te, pe, ta, pa, nullptr)) {
            fail(c, assertText(te, pe), assertText(ta, pa));
        }
        return 0;
    }
    if (te->size != ta->size) {
        fail(c, "(Data size = " + std::to_string(te->size) + ")", "(Data size = " + std::to_string(ta->size) + ")");
        return 0;
    }
    const double zero = 0;
    if (sema::isElementary(te->kind) && te->kind != TK::Enum) {
        if (!sameValue(te, pe, ta, pa, sema::isReal(te->kind) ? &zero : nullptr)) fail(c, assertText(te, pe), assertText(ta, pa));
        return 0;
    }
    if (std::memcmp(pe, pa, te->size) != 0) fail(c, hexBytes(pe, te->size), hexBytes(pa, ta->size));
    return 0;
}

uint8_t* ArrayOperand::resolve(Ctx& c, size_t dims, int64_t* los, int64_t* his) const {
    if (desc) {
        const uint8_t* d = desc->addr(c);
        for (size_t k = 0; k < dims; ++k) {
            los[k] = loadAs<int64_t>(d + 8 + 16 * k);
            his[k] = loadAs<int64_t>(d + 16 + 16 * k);
        }
        return loadAs<uint8_t*>(d);
    }
    for (size_t k = 0; k < dims; ++k) {
        los[k] = lo[k];
        his[k] = hi[k];
    }
    return place->addr(c);
}

namespace {

std::string sizeText(size_t dims, const int64_t* lo, const int64_t* hi) {
    if (dims == 1) return "SIZE = " + std::to_string(hi[0] - lo[0] + 1);
    std::string bounds, counts;
    for (size_t k = 0; k < dims; ++k) {
        bounds += (k ? "," : "") + std::to_string(lo[k]) + ".." + std::to_string(hi[k]);
        counts += (k ? "x" : "") + std::to_string(hi[k] - lo[k] + 1);
    }
    return "SIZE = [" + bounds + "] (" + counts + ")";
}

std::string elementText(const sema::Type* elem, size_t dims, const int64_t* lo, const uint64_t* offset, const uint8_t* p) {
    std::string s = "ARRAY[";
    for (size_t k = 0; k < dims; ++k) s += (k ? "," : "") + std::to_string(lo[k] + static_cast<int64_t>(offset[k]));
    return s + "] = " + assertText(elem, p);
}

}  // namespace

int64_t AssertArrayNode::i(Ctx& c) {
    if (!reg->assertionsActive()) return 0;
    int64_t le[3], he[3], la[3], ha[3];
    const uint8_t* be = expected.resolve(c, dims, le, he);
    const uint8_t* ba = actual.resolve(c, dims, la, ha);
    {
        uint64_t ne = 1, na = 1;
        for (size_t k = 0; k < dims; ++k) {
            ne *= static_cast<uint64_t>(std::max<int64_t>(he[k] - le[k] + 1, 0));
            na *= static_cast<uint64_t>(std::max<int64_t>(ha[k] - la[k] + 1, 0));
        }
        note(c, hashBytes(hashBytes(rt::kFnv1aBasis, be, ne * elem->size), ba, na * elem->size));
    }
    for (size_t k = 0; k < dims; ++k) {
        if (he[k] - le[k] != ha[k] - la[k]) {
            fail(c, sizeText(dims, le, he), sizeText(dims, la, ha), ", size of arrays not matching.");
            return 0;
        }
    }
    double d = 0;
    const double* dp = nullptr;
    if (delta) {
        d = delta->f(c);
        dp = &d;
    }
    uint64_t total = 1;
    for (size_t k = 0; k < dims; ++k) total *= static_cast<uint64_t>(he[k] - le[k] + 1);
    for (uint64_t n = 0; n < total; ++n) {
        const uint8_t* pe = be + n * elem->size;
        const uint8_t* pa = ba + n * elem->size;
        if (sameValue(elem, pe, elem, pa, dp)) continue;
        uint64_t offset[3] = {0, 0, 0};
        uint64_t rest = n;
        for (size_t k = dims; k-- > 0;) {
            uint64_t count = static_cast<uint64_t>(he[k] - le[k] + 1);
            offset[k] = rest % count;
            rest /= count;
        }
        fail(c, elementText(elem, dims, le, offset, pe), elementText(elem, dims, la, offset, pa));
        return 0;
    }
    return 0;
}

}  // namespace strun::testing
