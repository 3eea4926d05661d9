// The string edits of LEFT RIGHT MID INSERT DELETE REPLACE as at most three
// slices of their inputs, in order. The evaluator copies the slices straight
// into the result's storage (no allocation on the statement path);
// string_functions.cpp joins them for callers that want a std::string.
// Edge cases: see string_functions.h and decision 0033.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace strun::stdlib {

template <class Ch>
struct StringPieces {
    std::basic_string_view<Ch> part[3];
    std::basic_string<Ch> join() const {
        std::basic_string<Ch> out;
        out.reserve(part[0].size() + part[1].size() + part[2].size());
        for (const auto& p : part) out.append(p);
        return out;
    }
};

namespace pieces {

template <class Ch>
using View = std::basic_string_view<Ch>;

template <class Ch>
int64_t lengthOf(View<Ch> s) { return static_cast<int64_t>(s.size()); }

template <class Ch>
StringPieces<Ch> left(View<Ch> s, int64_t size) {
    if (size <= 0) return {};
    return {{s.substr(0, static_cast<size_t>(std::min(size, lengthOf(s))))}};
}

template <class Ch>
StringPieces<Ch> right(View<Ch> s, int64_t size) {
    if (size <= 0) return {};
    const int64_t count = std::min(size, lengthOf(s));
    return {{s.substr(s.size() - static_cast<size_t>(count))}};
}

template <class Ch>
StringPieces<Ch> mid(View<Ch> s, int64_t length, int64_t position) {
    if (length <= 0 || position < 1 || position > lengthOf(s)) return {};
    const int64_t available = lengthOf(s) - position + 1;
    return {{s.substr(static_cast<size_t>(position - 1), static_cast<size_t>(std::min(length, available)))}};
}

template <class Ch>
StringPieces<Ch> insert(View<Ch> s1, View<Ch> s2, int64_t position) {
    if (position < 0) return {{s1}};
    const auto at = static_cast<size_t>(std::min(position, lengthOf(s1)));
    return {{s1.substr(0, at), s2, s1.substr(at)}};
}

template <class Ch>
StringPieces<Ch> erase(View<Ch> s, int64_t length, int64_t position) {
    if (position < 0) return {{s}};
    if (position == 0) {  // CODESYS: POS 0 addresses the first character but LEN shrinks by one
        position = 1;
        if (length > std::numeric_limits<int64_t>::min()) --length;
    }
    if (length <= 0 || position > lengthOf(s)) return {{s}};
    const int64_t available = lengthOf(s) - position + 1;
    const auto start = static_cast<size_t>(position - 1);
    const auto removed = static_cast<size_t>(std::min(length, available));
    return {{s.substr(0, start), s.substr(start + removed)}};
}

template <class Ch>
StringPieces<Ch> replace(View<Ch> s1, View<Ch> s2, int64_t length, int64_t position) {
    if (position < 0) return {{s1}};
    if (position == 0) {  // same CODESYS quirk as DELETE
        position = 1;
        if (length > std::numeric_limits<int64_t>::min()) --length;
    }
    length = std::max<int64_t>(length, 0);
    const int64_t start = std::min(position - 1, lengthOf(s1));  // 0-based; past the end appends
    const int64_t removed = std::min(length, lengthOf(s1) - start);
    return {{s1.substr(0, static_cast<size_t>(start)), s2, s1.substr(static_cast<size_t>(start + removed))}};
}

}  // namespace pieces
}  // namespace strun::stdlib
