// CONCAT, and its in-place form `s := CONCAT(s, piece, ...)`. The in-place
// form appends the pieces to s where it is instead of copying s into a
// temporary and back: string building in a loop costs the length of the
// piece, not of the whole text. The checker builds it only where the result
// is exactly what CONCAT followed by the assignment would leave
// (interpreter/sema/fuse_strings.cpp, decision 0155).
#pragma once

#include <algorithm>
#include <cstring>
#include <string_view>
#include <vector>

#include "interpreter/exec/stmt_nodes.h"

namespace strun::exec {

// Every input part is copied in order into the caller-frame temporary at
// `off`, cut at maxLen; yields the temporary's address.
template <class Ch>
struct ConcatNode final : Expr {
    std::vector<Expr*> parts;
    uint32_t off = 0, maxLen = 0;
    uint8_t* addr(Ctx& c) override {
        Ch* dst = reinterpret_cast<Ch*>(c.frame + off);
        size_t n = 0;
        for (Expr* p : parts) {
            std::basic_string_view<Ch> v(reinterpret_cast<const Ch*>(p->addr(c)));
            size_t k = std::min<size_t>(v.size(), maxLen - n);
            std::memmove(dst + n, v.data(), k * sizeof(Ch));
            n += k;
        }
        dst[n] = 0;
        return reinterpret_cast<uint8_t*>(dst);
    }
};

// s := CONCAT(s, p1, p2, ...) with s a string variable of the instance, the
// frame or a fixed address. `limit` is the smaller of s's length and CONCAT's
// result length: the text CONCAT would produce, cut as the assignment cuts
// it. The pieces never share storage with s (constants and other
// variables only), so appending in place reads them unchanged.
template <class Ch, BaseKind B>
struct AppendInPlace final : Stmt {
    uint32_t off = 0;
    uint8_t* abs = nullptr;
    uint32_t limit = 0;
    std::vector<Expr*> pieces;
    Flow exec(Ctx& c) override {
        Ch* s = reinterpret_cast<Ch*>(baseOf<B>(c, abs) + off);
        size_t n = boundedLength<Ch>(s, limit);
        for (Expr* p : pieces) {
            if (n == limit) break;
            const Ch* piece = reinterpret_cast<const Ch*>(p->addr(c));
            size_t k = boundedLength<Ch>(piece, limit - n);
            std::memcpy(s + n, piece, k * sizeof(Ch));
            n += k;
        }
        s[n] = 0;
        return Flow::Next;
    }
};

}  // namespace strun::exec
