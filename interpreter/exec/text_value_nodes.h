// CASE on a STRING / WSTRING selector and a CHAR as a STRING (SIMATIC AX;
// decision 0394). For the CASE, the checker numbers the distinct label
// strings 1..n and builds an ordinary CASE on StringCaseKey, the number of
// the label the selector equals (0: none, the ELSE branch). Only CASEs on
// strings pay for it.
#pragma once

#include <string>
#include <vector>

#include "interpreter/exec/value_nodes.h"

namespace strun::exec {

template <class Ch>
struct StringCaseKey final : Expr {
    Expr* selector;
    uint32_t maxLen;  // the selector's declared length: its text ends there at the latest
    std::vector<std::basic_string<Ch>> labels;
    StringCaseKey(Expr* s, uint32_t n) : selector(s), maxLen(n) {}
    int64_t i(Ctx& c) override {
        const Ch* text = reinterpret_cast<const Ch*>(selector->addr(c));
        size_t len = 0;
        while (len < maxLen && text[len] != 0) ++len;
        for (size_t k = 0; k < labels.size(); ++k)
            if (labels[k].size() == len && std::char_traits<Ch>::compare(labels[k].data(), text, len) == 0) return static_cast<int64_t>(k + 1);
        return 0;
    }
};


// A CHAR (WCHAR) where a STRING (WSTRING) is expected (IEC Ed.3, SIMATIC AX:
// `_c : STRING; _c := str[i];`): the one-character string, in a temporary of
// the caller's frame (a NUL character gives the empty string).
template <class Ch>
struct CharAsString final : Expr {
    Expr* ch;
    uint32_t off;
    CharAsString(Expr* c, uint32_t o) : ch(c), off(o) {}
    uint8_t* addr(Ctx& c) override {
        Ch* dst = reinterpret_cast<Ch*>(c.frame + off);
        dst[0] = static_cast<Ch>(ch->i(c));
        dst[1] = 0;
        return reinterpret_cast<uint8_t*>(dst);
    }
};


// s[i] on a STRING (WSTRING) in a SIMATIC AX project: the i-th character,
// i from 1 to the declared length. A position outside reads the NUL
// character and a write there is lost (AX's own tests read `str[0]` of a
// text without brackets and expect no fault; decision 0394): the place is
// then a scratch character, cleared at each use.
struct AxCharPlace final : Expr {
    Expr* base;
    Expr* index;
    uint64_t count;
    uint32_t stride;
    uint16_t scratch = 0;
    AxCharPlace(Expr* b, Expr* i, uint64_t n, uint32_t s) : base(b), index(i), count(n), stride(s) {}
    uint8_t* addr(Ctx& c) override {
        const uint64_t k = static_cast<uint64_t>(index->i(c)) - 1;
        if (__builtin_expect(k >= count, 0)) {
            scratch = 0;
            return reinterpret_cast<uint8_t*>(&scratch);
        }
        return base->addr(c) + k * stride;
    }
};

}  // namespace strun::exec
