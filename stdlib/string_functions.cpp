#include "stdlib/string_functions.h"
#include "stdlib/string_pieces.h"

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
    return pieces::left<typename View::value_type>(s, size).join();
}

template <typename View>
StringOf<View> right(View s, int64_t size) {
    return pieces::right<typename View::value_type>(s, size).join();
}

template <typename View>
StringOf<View> mid(View s, int64_t length, int64_t position) {
    return pieces::mid<typename View::value_type>(s, length, position).join();
}

template <typename View>
StringOf<View> concat(View first, View second) {
    return StringPieces<typename View::value_type>{{first, second}}.join();
}

template <typename View>
StringOf<View> insert(View s1, View s2, int64_t position) {
    return pieces::insert<typename View::value_type>(s1, s2, position).join();
}

template <typename View>
StringOf<View> erase(View s, int64_t length, int64_t position) {
    return pieces::erase<typename View::value_type>(s, length, position).join();
}

template <typename View>
StringOf<View> replace(View s1, View s2, int64_t length, int64_t position) {
    return pieces::replace<typename View::value_type>(s1, s2, length, position).join();
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
