#include "interpreter/project/literal_value.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>

#include "stdlib/literals.h"
#include "stdlib/number_scan.h"
#include "stdlib/time_literals.h"

namespace strun::project {

using sema::TK;
using sema::Type;

namespace {

// Drops a type prefix (`INT#`, `Color#`) but not a base (`16#`).
std::string_view withoutTypePrefix(std::string_view text) {
    size_t hash = text.find('#');
    if (hash == std::string_view::npos || hash == 0) return text;
    if (std::isdigit(static_cast<unsigned char>(text[0]))) return text;
    return text.substr(hash + 1);
}

template <typename T>
void put(std::vector<uint8_t>& bytes, T v) {
    std::memcpy(bytes.data(), &v, sizeof(T));
}

void putInt(std::vector<uint8_t>& bytes, uint32_t size, uint64_t bits) {
    switch (size) {
        case 1: put(bytes, uint8_t(bits)); break;
        case 2: put(bytes, uint16_t(bits)); break;
        case 4: put(bytes, uint32_t(bits)); break;
        default: put(bytes, bits); break;
    }
}

bool integerRange(TK k, __int128& lo, __int128& hi) {
    int width = sema::bitWidth(k);
    if (sema::isSignedInt(k)) {
        lo = -(__int128(1) << (width - 1));
        hi = (__int128(1) << (width - 1)) - 1;
    } else {
        lo = 0;
        hi = (__int128(1) << width) - 1;
    }
    return true;
}

// A signed or unsigned integer literal in 128 bits.
bool parseInteger(std::string_view text, __int128& value, std::string& error) {
    std::string_view t = withoutTypePrefix(text);
    bool negative = !t.empty() && t[0] == '-';
    std::string_view digits = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? t.substr(1) : t;
    auto r = stdlib::parseIntegerLiteral(digits);
    if (!r) {
        error = "'" + std::string(text) + "' is not an integer literal: " + r.error();
        return false;
    }
    value = negative ? -__int128(r.value()) : __int128(r.value());
    return true;
}

std::string int128Text(__int128 v) {
    if (v == 0) return "0";
    bool neg = v < 0;
    unsigned __int128 u = neg ? (unsigned __int128)(-(v + 1)) + 1 : (unsigned __int128)v;
    std::string s;
    while (u) {
        s.insert(s.begin(), char('0' + int(u % 10)));
        u /= 10;
    }
    return neg ? "-" + s : s;
}

bool encodeString(const Type* t, std::string_view text, std::vector<uint8_t>& bytes, std::string& error) {
    std::string_view lit = withoutTypePrefix(text);
    bool wide = t->kind == TK::WString || t->kind == TK::WChar;
    std::u16string units;
    std::string narrow;
    if (wide) {
        auto r = stdlib::parseWideStringLiteral(lit);
        if (!r) return error = "'" + std::string(text) + "' is not a string literal: " + r.error(), false;
        units = r.value();
    } else {
        auto r = stdlib::parseStringLiteral(lit);
        if (!r) return error = "'" + std::string(text) + "' is not a string literal ('text'): " + r.error(), false;
        narrow = r.value();
    }
    size_t length = wide ? units.size() : narrow.size();
    bool isChar = t->kind == TK::Char || t->kind == TK::WChar;
    size_t capacity = isChar ? 1 : t->maxLen;
    if (isChar ? length != 1 : length > capacity) {
        error = std::string(text) + " does not fit " + t->name + (isChar ? " (one character)" : " (" + std::to_string(capacity) + " characters)");
        return false;
    }
    if (wide) std::memcpy(bytes.data(), units.data(), units.size() * 2);
    else std::memcpy(bytes.data(), narrow.data(), narrow.size());
    return true;
}

bool encodeEnum(const Type* t, std::string_view text, std::vector<uint8_t>& bytes, std::string& error) {
    std::string name = stdlib::upperAscii(withoutTypePrefix(text));
    for (const auto& e : t->enumerators)
        if (stdlib::upperAscii(e.name) == name) {
            putInt(bytes, t->size, uint64_t(e.value));
            return true;
        }
    std::string names;
    for (const auto& e : t->enumerators) names += (names.empty() ? "" : ", ") + e.name;
    error = "'" + std::string(text) + "' is no value of " + t->name + " (" + names + ")";
    return false;
}

bool encodeTimeLike(const Type* t, std::string_view text, std::vector<uint8_t>& bytes, std::string& error) {
    // A TwinCAT project's TIME/LTIME is unsigned (decision 0367): up to
    // T#49d17h2m47s295ms and 2^64-1 ns, as the literals in its code (decision 0389).
    const bool unsignedRange = (t->kind == TK::Time || t->kind == TK::LTime) && t->unsignedDuration;
    bool saturated = false;
    uint64_t unsignedBits = 0;
    stdlib::Result<int64_t> r = [&] {
        switch (t->kind) {
            case TK::Time: case TK::LTime: return stdlib::parseDurationLiteral(text, unsignedRange, &saturated, &unsignedBits);
            case TK::Date: case TK::LDate: return stdlib::parseDateLiteral(text);
            case TK::Tod: case TK::LTod: return stdlib::parseTimeOfDayLiteral(text);
            default: return stdlib::parseDateTimeLiteral(text);
        }
    }();
    if (!r) return error = "'" + std::string(text) + "' is not a " + t->name + " literal: " + r.error(), false;
    if (saturated && t->kind == TK::LTime) return put(bytes, static_cast<int64_t>(unsignedBits)), true;
    if (saturated) return error = std::string(text) + " does not fit " + t->name, false;
    int64_t units = r.value() / sema::nanosPerUnit(t->kind);
    if (t->size == 4) {
        const int64_t highest = unsignedRange ? int64_t(std::numeric_limits<uint32_t>::max()) : std::numeric_limits<int32_t>::max();
        bool fits = t->kind == TK::Time ? (units >= std::numeric_limits<int32_t>::min() && units <= highest)
                                        : (units >= 0 && units <= int64_t(std::numeric_limits<uint32_t>::max()));
        if (!fits) return error = std::string(text) + " does not fit " + t->name, false;
        putInt(bytes, 4, uint64_t(units));
    } else {
        put(bytes, units);
    }
    return true;
}

}  // namespace

bool encodeLiteral(const Type* t, std::string_view rawText, std::vector<uint8_t>& bytes, std::string& error) {
    std::string trimmedText(rawText);
    while (!trimmedText.empty() && std::isspace(static_cast<unsigned char>(trimmedText.back()))) trimmedText.pop_back();
    size_t lead = 0;
    while (lead < trimmedText.size() && std::isspace(static_cast<unsigned char>(trimmedText[lead]))) ++lead;
    std::string_view text = std::string_view(trimmedText).substr(lead);
    bytes.assign(t->size, 0);
    if (text.empty()) return error = "no value given", false;
    switch (t->kind) {
        case TK::Bool: {
            std::string v = stdlib::upperAscii(withoutTypePrefix(text));
            if (v == "TRUE" || v == "1") bytes[0] = 1;
            else if (v != "FALSE" && v != "0") return error = "'" + std::string(text) + "' is not a BOOL (TRUE, FALSE, 1, 0)", false;
            return true;
        }
        case TK::Real: case TK::LReal: {
            auto r = stdlib::parseRealLiteral(withoutTypePrefix(text));
            if (!r) return error = "'" + std::string(text) + "' is not a number: " + r.error(), false;
            if (t->kind == TK::Real) {
                if (std::fabs(r.value()) > std::numeric_limits<float>::max())
                    return error = std::string(text) + " does not fit REAL", false;
                put(bytes, float(r.value()));
            } else {
                put(bytes, r.value());
            }
            return true;
        }
        case TK::Time: case TK::LTime: case TK::Date: case TK::Tod: case TK::Dt:
        case TK::LDate: case TK::LTod: case TK::LDt: return encodeTimeLike(t, text, bytes, error);
        case TK::Char: case TK::WChar: case TK::String: case TK::WString: return encodeString(t, text, bytes, error);
        case TK::Enum: return encodeEnum(t, text, bytes, error);
        default: break;
    }
    if (sema::isInteger(t->kind) || sema::isBitString(t->kind)) {
        __int128 value = 0, lo = 0, hi = 0;
        if (!parseInteger(text, value, error)) return false;
        integerRange(t->kind, lo, hi);
        if (t->isSubrange) {
            lo = t->rangeLo;
            hi = t->rangeHi;
        }
        if (value < lo || value > hi) {
            error = std::string(text) + " does not fit " + t->name + " (" + int128Text(lo) + ".." + int128Text(hi) + ")";
            return false;
        }
        putInt(bytes, t->size, uint64_t(value));
        return true;
    }
    error = "a " + t->name + " takes no literal; name one of its elements or members";
    return false;
}

}  // namespace strun::project
