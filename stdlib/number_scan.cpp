#include "stdlib/number_scan.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace strun::stdlib {

std::string quoted(std::string_view text) {
    constexpr size_t kMaxShown = 40;
    if (text.size() <= kMaxShown) return fmt::format("'{}'", text);
    return fmt::format("'{}...'", text.substr(0, kMaxShown));
}

int digitValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'z') return c - 'a' + 10;
    if (c >= 'A' && c <= 'Z') return c - 'A' + 10;
    return -1;
}

namespace {

bool isDigitOf(std::string_view text, size_t pos, unsigned base) {
    if (pos >= text.size()) return false;
    const int value = digitValue(text[pos]);
    return value >= 0 && static_cast<unsigned>(value) < base;
}

}  // namespace

DigitScan scanDigits(std::string_view text, size_t pos, unsigned base) {
    DigitScan scan;
    scan.end = pos;
    size_t i = pos;
    while (true) {
        if (isDigitOf(text, i, base)) {
            // consume the digit below
        } else if (scan.digits > 0 && i < text.size() && text[i] == '_') {
            // Underscores between two digits: one (IEC) or several (TwinCAT).
            size_t j = i;
            while (j < text.size() && text[j] == '_') ++j;
            if (!isDigitOf(text, j, base)) break;
            i = j;
        } else {
            break;
        }
        const auto digit = static_cast<uint64_t>(digitValue(text[i]));
        scan.wrapped = scan.wrapped * base + digit;  // unsigned: wraps modulo 2^64
        if (!scan.overflow) {
            uint64_t next = 0;
            if (__builtin_mul_overflow(scan.value, static_cast<uint64_t>(base), &next) ||
                __builtin_add_overflow(next, digit, &next)) {
                scan.overflow = true;
            } else {
                scan.value = next;
            }
        }
        ++scan.digits;
        ++i;
        scan.end = i;
    }
    return scan;
}

RealScan scanReal(std::string_view text, size_t pos) {
    RealScan scan;
    scan.end = pos;
    size_t i = pos;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
        if (text[i] == '-') scan.normalized.push_back('-');
        ++i;
    }
    // Position of the first non-zero mantissa digit relative to the point gives
    // the order of magnitude without converting.
    int64_t integerDigitsAfterLeadingZeros = 0;
    int64_t leadingFractionZeros = 0;
    bool seenNonZero = false;

    auto appendGroup = [&](size_t from, size_t to, bool fraction) {
        for (size_t k = from; k < to; ++k) {
            const char c = text[k];
            if (c == '_') continue;
            scan.normalized.push_back(c);
            if (c != '0') seenNonZero = true;
            if (!fraction && seenNonZero) ++integerDigitsAfterLeadingZeros;
            if (fraction && !seenNonZero) ++leadingFractionZeros;
        }
    };

    const DigitScan integerPart = scanDigits(text, i, 10);
    if (integerPart.digits == 0) return scan;  // no mantissa: nothing matched
    appendGroup(i, integerPart.end, false);
    i = integerPart.end;
    scan.matched = true;

    if (i < text.size() && text[i] == '.') {
        const DigitScan fractionPart = scanDigits(text, i + 1, 10);
        if (fractionPart.digits > 0) {
            scan.normalized.push_back('.');
            appendGroup(i + 1, fractionPart.end, true);
            i = fractionPart.end;
            scan.hasFraction = true;
        }
    }
    int64_t exponent = 0;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        size_t j = i + 1;
        bool negative = false;
        if (j < text.size() && (text[j] == '+' || text[j] == '-')) {
            negative = text[j] == '-';
            ++j;
        }
        const DigitScan exponentPart = scanDigits(text, j, 10);
        if (exponentPart.digits > 0) {
            scan.normalized.push_back('e');
            if (negative) scan.normalized.push_back('-');
            for (size_t k = j; k < exponentPart.end; ++k) {
                if (text[k] != '_') scan.normalized.push_back(text[k]);
            }
            // Exponents beyond any double range are clamped; the sign is what matters.
            constexpr uint64_t kClamp = 1'000'000;
            const uint64_t magnitude =
                exponentPart.overflow ? kClamp : std::min<uint64_t>(exponentPart.value, kClamp);
            exponent = negative ? -static_cast<int64_t>(magnitude) : static_cast<int64_t>(magnitude);
            i = exponentPart.end;
            scan.hasExponent = true;
        }
    }
    scan.isZero = !seenNonZero;
    scan.decimalExponent = exponent + (integerDigitsAfterLeadingZeros > 0
                                           ? integerDigitsAfterLeadingZeros - 1
                                           : -leadingFractionZeros - 1);
    scan.end = i;
    return scan;
}

namespace {

template <typename T>
T realScanTo(const RealScan& scan, bool* overflowed) {
    if (overflowed) *overflowed = false;
    const bool negative = !scan.normalized.empty() && scan.normalized[0] == '-';
    if (!scan.matched) return T{0};
    T value{};
    const char* first = scan.normalized.data();
    const char* last = first + scan.normalized.size();
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (ec == std::errc::result_out_of_range) {
        if (scan.isZero || scan.decimalExponent < 0) {
            return negative ? -T{0} : T{0};  // underflow
        }
        if (overflowed) *overflowed = true;
        const T infinity = std::numeric_limits<T>::infinity();
        return negative ? -infinity : infinity;
    }
    if (ec != std::errc{}) return T{0};  // cannot happen for a matched scan
    return value;
}

}  // namespace

double realScanToDouble(const RealScan& scan, bool* overflowed) {
    return realScanTo<double>(scan, overflowed);
}

float realScanToFloat(const RealScan& scan, bool* overflowed) {
    return realScanTo<float>(scan, overflowed);
}

std::string_view trimBlanks(std::string_view text) {
    auto isBlank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
    while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
    return text;
}

}  // namespace strun::stdlib
