#include "interpreter/testing/assert_text.h"

#include <cstring>

#include <fmt/format.h>

#include "interpreter/exec/node.h"
#include "stdlib/conversions.h"
#include "stdlib/text_encoding.h"
#include "stdlib/value_encodings.h"
#include "stdlib/value_format.h"

namespace strun::testing {

using exec::loadAs;
using sema::TK;

namespace {

int64_t loadSigned(const uint8_t* p, uint32_t size) {
    switch (size) {
        case 1: return loadAs<int8_t>(p);
        case 2: return loadAs<int16_t>(p);
        case 4: return loadAs<int32_t>(p);
        default: return loadAs<int64_t>(p);
    }
}

uint64_t loadUnsigned(const uint8_t* p, uint32_t size) {
    switch (size) {
        case 1: return loadAs<uint8_t>(p);
        case 2: return loadAs<uint16_t>(p);
        case 4: return loadAs<uint32_t>(p);
        default: return loadAs<uint64_t>(p);
    }
}

}  // namespace

size_t stringLength(const sema::Type* t, const uint8_t* p) {
    if (t->kind == TK::String) return strnlen(reinterpret_cast<const char*>(p), t->maxLen);
    size_t n = 0;
    while (n < t->maxLen && loadAs<char16_t>(p + 2 * n) != 0) ++n;
    return n;
}

std::string stringText(const sema::Type* t, const uint8_t* p) {
    size_t n = stringLength(t, p);
    if (t->kind == TK::String) return stdlib::bytesToUtf8(std::string_view(reinterpret_cast<const char*>(p), n));
    std::u16string w(n, u'\0');
    for (size_t k = 0; k < n; ++k) w[k] = loadAs<char16_t>(p + 2 * k);
    return stdlib::utf16ToUtf8(w);
}

std::string assertText(const sema::Type* t, const uint8_t* p) {
    switch (t->kind) {
        case TK::Bool: return stdlib::boolToString(*p != 0);
        case TK::SInt: case TK::Int: case TK::DInt: case TK::LInt: return stdlib::signedToString(loadSigned(p, t->size));
        case TK::USInt: case TK::UInt: case TK::UDInt: case TK::ULInt: return stdlib::unsignedToString(loadUnsigned(p, t->size));
        case TK::Byte: case TK::Word: case TK::DWord: case TK::LWord:
            return fmt::format("0x{:0{}X}", loadUnsigned(p, t->size), t->size * 2);
        case TK::Real: return stdlib::formatRealTwinCat(loadAs<float>(p));  // TcUnit's text is TwinCAT's
        case TK::LReal: return stdlib::formatLRealTwinCat(loadAs<double>(p));
        case TK::Time:  // unsigned in a TwinCAT project (decision 0367)
            return t->unsignedDuration ? stdlib::formatUnsignedDuration(uint64_t{loadAs<uint32_t>(p)} * 1000000u, "T#")
                                       : stdlib::formatDuration(stdlib::timeValueToNs(loadAs<int32_t>(p)), "T#");
        case TK::LTime:  // unsigned in a TwinCAT project (decision 0367)
            return t->unsignedDuration ? stdlib::formatUnsignedDuration(loadAs<uint64_t>(p), "LTIME#") : stdlib::formatDuration(loadAs<int64_t>(p), "LTIME#");
        case TK::Date: return stdlib::formatDate(stdlib::dateValueToNs(loadAs<uint32_t>(p)), "D#");
        case TK::LDate: return stdlib::formatDate(loadAs<int64_t>(p), "LDATE#");
        case TK::Tod: return stdlib::formatTimeOfDay(stdlib::todValueToNs(loadAs<uint32_t>(p)), "TOD#");
        case TK::LTod: return stdlib::formatTimeOfDay(loadAs<int64_t>(p), "LTOD#");
        case TK::Dt: return stdlib::formatDateTime(stdlib::dtValueToNs(loadAs<uint32_t>(p)), "DT#");
        case TK::LDt: return stdlib::formatDateTime(loadAs<int64_t>(p), "LDT#");
        case TK::Char: return stdlib::bytesToUtf8(std::string_view(reinterpret_cast<const char*>(p), *p ? 1 : 0));
        case TK::WChar: {
            char16_t ch = loadAs<char16_t>(p);
            return stdlib::utf16ToUtf8(std::u16string_view(&ch, ch ? 1 : 0));
        }
        case TK::String: case TK::WString: return stringText(t, p);
        case TK::Enum: {
            int64_t v = sema::isSignedInt(t->base->kind) ? loadSigned(p, t->size) : static_cast<int64_t>(loadUnsigned(p, t->size));
            for (const auto& e : t->enumerators)
                if (e.value == v) return e.name;
            return stdlib::signedToString(v);
        }
        default: return hexBytes(p, t->size);
    }
}

std::string typeClassName(const sema::Type* t) {
    switch (t->kind) {
        case TK::Dt: return "DATEANDTIME";
        case TK::Tod: return "TIMEOFDAY";
        case TK::LDt: return "LDATEANDTIME";
        case TK::LTod: return "LTIMEOFDAY";
        case TK::Enum: return "ENUM";
        case TK::Array: return "ARRAY";
        case TK::Struct: case TK::FunctionBlock: return "USERDEF";
        case TK::Pointer: return "POINTER";
        case TK::Reference: return "REFERENCE";
        case TK::Interface: return "INTERFACE";
        case TK::String: return "STRING";
        case TK::WString: return "WSTRING";
        default: return sema::typeName(t);
    }
}

std::string hexBytes(const uint8_t* p, uint32_t size) {
    std::string out = "0x";
    for (uint32_t k = 0; k < size && k < 39; ++k) out += fmt::format("{:02X}", p[k]);
    return out;
}

}  // namespace strun::testing
