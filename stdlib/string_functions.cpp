#include "stdlib/string_functions.h"

#include <algorithm>
#include <limits>

namespace strun::stdlib {

namespace {

// One implementation for STRING and WSTRING; View is the string_view type.
template <typename View>
using StringOf = std::basic_string<typename View::value_type>;

template <typename View>
int64_t lengthOf(View s) {
    return static_cast<int64_t>(s.size());
}

template <typename View>
StringOf<View> left(View s, int64_t size) {
    if (size <= 0) return {};
    return StringOf<View>(s.substr(0, static_cast<size_t>(std::min(size, lengthOf(s)))));
}

template <typename View>
StringOf<View> right(View s, int64_t size) {
    if (size <= 0) return {};
    const int64_t count = std::min(size, lengthOf(s));
    return StringOf<View>(s.substr(s.size() - static_cast<size_t>(count)));
}

template <typename View>
StringOf<View> mid(View s, int64_t length, int64_t position) {
    if (length <= 0 || position < 1 || position > lengthOf(s)) return {};
    const int64_t available = lengthOf(s) - position + 1;
    return StringOf<View>(
        s.substr(static_cast<size_t>(position - 1), static_cast<size_t>(std::min(length, available))));
}

template <typename View>
StringOf<View> concat(View first, View second) {
    StringOf<View> out;
    out.reserve(first.size() + second.size());
    out.append(first);
    out.append(second);
    return out;
}

template <typename View>
StringOf<View> insert(View s1, View s2, int64_t position) {
    if (position < 0) return StringOf<View>(s1);
    const auto at = static_cast<size_t>(std::min(position, lengthOf(s1)));
    StringOf<View> out;
    out.reserve(s1.size() + s2.size());
    out.append(s1.substr(0, at));
    out.append(s2);
    out.append(s1.substr(at));
    return out;
}

template <typename View>
StringOf<View> erase(View s, int64_t length, int64_t position) {
    if (position < 0) return StringOf<View>(s);
    if (position == 0) {  // CODESYS: POS 0 addresses the first character but LEN shrinks by one
        position = 1;
        if (length > std::numeric_limits<int64_t>::min()) --length;
    }
    if (length <= 0 || position > lengthOf(s)) return StringOf<View>(s);
    const int64_t available = lengthOf(s) - position + 1;
    StringOf<View> out(s);
    out.erase(static_cast<size_t>(position - 1), static_cast<size_t>(std::min(length, available)));
    return out;
}

template <typename View>
StringOf<View> replace(View s1, View s2, int64_t length, int64_t position) {
    if (position < 0) return StringOf<View>(s1);
    if (position == 0) {  // same CODESYS quirk as DELETE
        position = 1;
        if (length > std::numeric_limits<int64_t>::min()) --length;
    }
    length = std::max<int64_t>(length, 0);
    const int64_t start = std::min(position - 1, lengthOf(s1));  // 0-based; past the end appends
    const int64_t removed = std::min(length, lengthOf(s1) - start);
    StringOf<View> out;
    out.reserve(s1.size() + s2.size());
    out.append(s1.substr(0, static_cast<size_t>(start)));
    out.append(s2);
    out.append(s1.substr(static_cast<size_t>(start + removed)));
    return out;
}

template <typename View>
int64_t find(View s1, View s2) {
    if (s2.empty()) return 0;
    const size_t at = s1.find(s2);
    return at == View::npos ? 0 : static_cast<int64_t>(at) + 1;
}

template <typename View>
StringOf<View> truncate(View s, int64_t maxLength) {
    return left(s, maxLength);
}

}  // namespace

int64_t stringLength(std::string_view s) { return lengthOf(s); }
int64_t stringLength(std::u16string_view s) { return lengthOf(s); }

std::string stringLeft(std::string_view s, int64_t size) { return left(s, size); }
std::u16string stringLeft(std::u16string_view s, int64_t size) { return left(s, size); }

std::string stringRight(std::string_view s, int64_t size) { return right(s, size); }
std::u16string stringRight(std::u16string_view s, int64_t size) { return right(s, size); }

std::string stringMid(std::string_view s, int64_t length, int64_t position) {
    return mid(s, length, position);
}
std::u16string stringMid(std::u16string_view s, int64_t length, int64_t position) {
    return mid(s, length, position);
}

std::string stringConcat(std::string_view first, std::string_view second) {
    return concat(first, second);
}
std::u16string stringConcat(std::u16string_view first, std::u16string_view second) {
    return concat(first, second);
}

std::string stringInsert(std::string_view s1, std::string_view s2, int64_t position) {
    return insert(s1, s2, position);
}
std::u16string stringInsert(std::u16string_view s1, std::u16string_view s2, int64_t position) {
    return insert(s1, s2, position);
}

std::string stringDelete(std::string_view s, int64_t length, int64_t position) {
    return erase(s, length, position);
}
std::u16string stringDelete(std::u16string_view s, int64_t length, int64_t position) {
    return erase(s, length, position);
}

std::string stringReplace(std::string_view s1, std::string_view s2, int64_t length,
                          int64_t position) {
    return replace(s1, s2, length, position);
}
std::u16string stringReplace(std::u16string_view s1, std::u16string_view s2, int64_t length,
                             int64_t position) {
    return replace(s1, s2, length, position);
}

int64_t stringFind(std::string_view s1, std::string_view s2) { return find(s1, s2); }
int64_t stringFind(std::u16string_view s1, std::u16string_view s2) { return find(s1, s2); }

std::string truncateToLength(std::string_view s, int64_t maxLength) {
    return truncate(s, maxLength);
}
std::u16string truncateToLength(std::u16string_view s, int64_t maxLength) {
    return truncate(s, maxLength);
}

}  // namespace strun::stdlib
