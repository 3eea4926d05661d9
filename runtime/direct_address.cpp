#include "runtime/direct_address.h"

#include <cctype>
#include <cstdint>

namespace strun::rt {

namespace {

// Decimal digits only, below `limit`; nullopt otherwise.
std::optional<uint64_t> number(std::string_view digits, uint64_t limit) {
    if (digits.empty() || digits.size() > 12) return std::nullopt;
    uint64_t v = 0;
    for (char c : digits) {
        if (c < '0' || c > '9') return std::nullopt;
        v = v * 10 + uint64_t(c - '0');
    }
    if (v >= limit) return std::nullopt;
    return v;
}

}  // namespace

std::optional<DirectAddress> parseDirectAddress(std::string_view text, size_t areaBytes, std::string& error) {
    std::string t;
    for (char c : text) t += char(std::toupper(static_cast<unsigned char>(c)));
    auto fail = [&](const std::string& why) -> std::optional<DirectAddress> {
        error = "'" + std::string(text) + "' " + why;
        return std::nullopt;
    };
    const char* form = "is not a direct address (%IX0.3, %IW2, %QX0.0, %QW4, %MW5)";
    if (t.size() < 3 || t[0] != '%') return fail(form);
    DirectAddress a;
    switch (t[1]) {
        case 'I': a.area = DirectAddress::Area::Input; break;
        case 'Q': a.area = DirectAddress::Area::Output; break;
        case 'M': a.area = DirectAddress::Area::Memory; break;
        default: return fail(form);
    }
    size_t pos = 2;
    if (std::isalpha(static_cast<unsigned char>(t[pos]))) a.size = t[pos++];
    if (a.size != 'X' && a.size != 'B' && a.size != 'W' && a.size != 'D' && a.size != 'L') return fail(form);
    std::string_view rest = std::string_view(t).substr(pos);
    size_t dot = rest.find('.');
    if ((a.size == 'X') != (dot != std::string_view::npos)) return fail(form);
    if (a.size == 'X') {
        auto byte = number(rest.substr(0, dot), areaBytes);
        auto bit = number(rest.substr(dot + 1), 8);
        if (!bit) return fail("has a bit number outside 0..7");
        if (!byte) return fail(number(rest.substr(0, dot), UINT64_MAX) ? "is outside the process image" : form);
        a.byte = size_t(*byte);
        a.bit = int(*bit);
        return a;
    }
    auto index = number(rest, UINT64_MAX);
    if (!index) return fail(form);
    if (*index >= areaBytes / a.bytes()) return fail("is outside the process image");
    a.byte = size_t(*index * a.bytes());
    return a;
}

std::string formatDirectAddress(const DirectAddress& a) {
    std::string s = "%";
    s += char(a.area);
    s += a.size;
    if (a.size == 'X') return s + std::to_string(a.byte) + "." + std::to_string(a.bit);
    return s + std::to_string(a.byte / a.bytes());
}

}  // namespace strun::rt
