// Evaluator nodes of the character-string functions. A string value is the
// address of NUL-terminated code units (char for STRING, char16_t for
// WSTRING); a string result is written into a temporary of the caller's
// frame (offset `off`, room for maxLen units + NUL) and yields its address.
// The position/length rules are those of stdlib/string_functions.h.
#pragma once

#include <algorithm>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/exec/string_append_nodes.h"
#include "stdlib/string_functions.h"
#include "stdlib/string_pieces.h"

namespace strun::stdlib::bind {

using exec::Ctx;
using exec::Expr;

template <class Ch>
inline std::basic_string_view<Ch> viewOf(Expr* e, Ctx& c) {
    return std::basic_string_view<Ch>(reinterpret_cast<const Ch*>(e->addr(c)));
}

// Copies `s` into the result temporary, cut to maxLen; returns its address.
template <class Ch>
inline uint8_t* writeString(Ctx& c, uint32_t off, uint32_t maxLen, std::basic_string_view<Ch> s) {
    Ch* dst = reinterpret_cast<Ch*>(c.frame + off);
    size_t n = std::min<size_t>(s.size(), maxLen);
    std::memmove(dst, s.data(), n * sizeof(Ch));
    dst[n] = 0;
    return reinterpret_cast<uint8_t*>(dst);
}

// Copies the slices of an edit into the result temporary, cut to maxLen. The
// slices may point into that same temporary (s := LEFT(s, 3) on a result), so
// they are first gathered in a scratch copy when they overlap it.
template <class Ch>
inline uint8_t* writePieces(Ctx& c, uint32_t off, uint32_t maxLen, const stdlib::StringPieces<Ch>& r) {
    Ch* dst = reinterpret_cast<Ch*>(c.frame + off);
    const Ch* end = dst + maxLen + 1;
    bool overlaps = false;
    for (const auto& part : r.part)
        overlaps = overlaps || (!part.empty() && part.data() < end && part.data() + part.size() > dst);
    if (overlaps) return writeString<Ch>(c, off, maxLen, std::basic_string_view<Ch>(r.join()));
    size_t n = 0;
    for (const auto& part : r.part) {
        size_t k = std::min<size_t>(part.size(), maxLen - n);
        if (k == 0) continue;  // an empty slice may have no data pointer at all
        std::memcpy(dst + n, part.data(), k * sizeof(Ch));
        n += k;
    }
    dst[n] = 0;
    return reinterpret_cast<uint8_t*>(dst);
}

template <class Ch>
struct LenNode final : Expr {
    Expr* s;
    explicit LenNode(Expr* x) : s(x) {}
    int64_t i(Ctx& c) override { return static_cast<int16_t>(viewOf<Ch>(s, c).size()); }
};

template <class Ch>
struct FindNode final : Expr {
    Expr *s1, *s2;
    FindNode(Expr* a, Expr* b) : s1(a), s2(b) {}
    int64_t i(Ctx& c) override {
        auto a = viewOf<Ch>(s1, c);
        auto b = viewOf<Ch>(s2, c);
        return static_cast<int16_t>(stdlib::stringFind(a, b));
    }
};

// CONCAT: exec::ConcatNode (it has an in-place form there).
using exec::ConcatNode;

enum class StrFn : uint8_t { Left, Right, Mid, Insert, Delete, Replace };

// LEFT(IN, L) RIGHT(IN, L) MID(IN, L, P) INSERT(IN1, IN2, P) DELETE(IN, L, P)
// REPLACE(IN1, IN2, L, P): s2 / l / p are null where the function has none.
template <class Ch, StrFn F>
struct StrEditNode final : Expr {
    Expr *s1 = nullptr, *s2 = nullptr, *l = nullptr, *p = nullptr;
    uint32_t off = 0, maxLen = 0;
    uint8_t* addr(Ctx& c) override {
        auto a = viewOf<Ch>(s1, c);
        stdlib::StringPieces<Ch> r;
        if constexpr (F == StrFn::Left) r = stdlib::pieces::left<Ch>(a, l->i(c));
        else if constexpr (F == StrFn::Right) r = stdlib::pieces::right<Ch>(a, l->i(c));
        else if constexpr (F == StrFn::Mid) {
            int64_t len = l->i(c);
            r = stdlib::pieces::mid<Ch>(a, len, p->i(c));
        } else if constexpr (F == StrFn::Insert) {
            auto b = viewOf<Ch>(s2, c);
            r = stdlib::pieces::insert<Ch>(a, b, p->i(c));
        } else if constexpr (F == StrFn::Delete) {
            int64_t len = l->i(c);
            r = stdlib::pieces::erase<Ch>(a, len, p->i(c));
        } else {
            auto b = viewOf<Ch>(s2, c);
            int64_t len = l->i(c);
            r = stdlib::pieces::replace<Ch>(a, b, len, p->i(c));
        }
        return writePieces<Ch>(c, off, maxLen, r);
    }
};

}  // namespace strun::stdlib::bind
