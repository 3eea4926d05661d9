#include "interpreter/project/retain_validate.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <vector>

namespace strun::project {

namespace {

using sema::TK;
using sema::Type;

// Whether a type has anything to check (a huge ARRAY OF INT is skipped whole).
bool hasRules(const Type* t, int depth = 0) {
    if (!t || depth > 1100) return false;
    switch (t->kind) {
        case TK::Bool: case TK::String: case TK::WString: case TK::Enum: return true;
        case TK::Array: return !t->flexible && hasRules(t->elem, depth + 1);
        case TK::Struct:
            for (const Type* p = t; p; p = p->parent)
                for (const auto& f : p->fields)
                    if (hasRules(f.type, depth + 1)) return true;
            return false;
        default: return t->isSubrange;
    }
}

int64_t signedAt(const uint8_t* p, uint32_t size) {
    switch (size) {
        case 1: { int8_t v; std::memcpy(&v, p, 1); return v; }
        case 2: { int16_t v; std::memcpy(&v, p, 2); return v; }
        case 4: { int32_t v; std::memcpy(&v, p, 4); return v; }
        default: { int64_t v; std::memcpy(&v, p, 8); return v; }
    }
}

uint64_t unsignedAt(const uint8_t* p, uint32_t size) {
    uint64_t v = 0;
    std::memcpy(&v, p, std::min<uint32_t>(size, 8));  // little-endian host, as the file's bytes are
    return v;
}

class Validator {
public:
    bool check(const Type* t, const uint8_t* p, int depth) {
        if (!t || depth > 1100) return true;
        switch (t->kind) {
            case TK::Bool:
                if (p[0] <= 1) return true;
                why_ = "a BOOL byte of " + std::to_string(p[0]);
                return false;
            case TK::String:
                if (std::memchr(p, 0, t->maxLen + 1)) return true;
                why_ = "a STRING(" + std::to_string(t->maxLen) + ") without its terminator";
                return false;
            case TK::WString:
                for (uint32_t k = 0; k <= t->maxLen; ++k)
                    if (p[2 * k] == 0 && p[2 * k + 1] == 0) return true;
                why_ = "a WSTRING(" + std::to_string(t->maxLen) + ") without its terminator";
                return false;
            case TK::Enum: {
                const int64_t v = t->base && sema::isUnsignedInt(t->base->kind) ? int64_t(unsignedAt(p, t->size)) : signedAt(p, t->size);
                const std::vector<int64_t>& values = enumValues(t);
                if (std::binary_search(values.begin(), values.end(), v)) return true;
                why_ = std::to_string(v) + ", which is no value of " + t->name;
                return false;
            }
            case TK::Array: {
                if (t->flexible || !hasRules(t->elem)) return true;
                for (uint64_t k = 0; k < t->elemCount; ++k)
                    if (!check(t->elem, p + k * t->elem->size, depth + 1)) {
                        why_ = "element " + std::to_string(k) + ": " + why_;
                        return false;
                    }
                return true;
            }
            case TK::Struct:
                for (const Type* s = t; s; s = s->parent)
                    for (const auto& f : s->fields)
                        if (!check(f.type, p + f.offset, depth + 1)) {
                            why_ = "member " + f.name + ": " + why_;
                            return false;
                        }
                return true;
            default:
                if (!t->isSubrange) return true;
                if (sema::isUnsignedInt(t->kind)) {
                    const uint64_t v = unsignedAt(p, t->size);
                    if (t->rangeLo >= 0 && v >= uint64_t(t->rangeLo) && v <= uint64_t(t->rangeHi)) return true;
                    why_ = std::to_string(v) + ", outside " + t->name;
                } else {
                    const int64_t v = signedAt(p, t->size);
                    if (v >= t->rangeLo && v <= t->rangeHi) return true;
                    why_ = std::to_string(v) + ", outside " + t->name;
                }
                return false;
        }
    }
    const std::string& why() const { return why_; }

private:
    // Sorted once per enumeration type: an ARRAY OF an enum checks in n log m.
    const std::vector<int64_t>& enumValues(const Type* t) {
        auto [it, fresh] = enums_.try_emplace(t);
        if (fresh) {
            for (const auto& e : t->enumerators) it->second.push_back(e.value);
            std::sort(it->second.begin(), it->second.end());
        }
        return it->second;
    }
    std::map<const Type*, std::vector<int64_t>> enums_;
    std::string why_;
};

}  // namespace

bool validRetainedValue(const sema::Type* t, const uint8_t* bytes, std::string& why) {
    if (!hasRules(t)) return true;
    Validator v;
    if (v.check(t, bytes, 0)) return true;
    why = v.why();
    return false;
}

}  // namespace strun::project
