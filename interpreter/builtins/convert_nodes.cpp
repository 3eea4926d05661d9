#include "interpreter/builtins/convert_nodes.h"

#include "stdlib/text_encoding.h"
#include "stdlib/value_encodings.h"
#include "stdlib/value_format.h"

namespace strun::stdlib::bind {

std::string valueText(ValueClass k, Expr* a, Ctx& c) {
    switch (k) {
        case ValueClass::Bool: return stdlib::boolToString(a->i(c) != 0);
        case ValueClass::Signed: return stdlib::signedToString(a->i(c));
        case ValueClass::Unsigned: return stdlib::unsignedToString(static_cast<uint64_t>(a->i(c)));
        case ValueClass::Real: return stdlib::formatReal(static_cast<float>(a->f(c)));
        case ValueClass::LReal: return stdlib::formatLReal(a->f(c));
        case ValueClass::RealTwinCat: return stdlib::formatRealTwinCat(static_cast<float>(a->f(c)));
        case ValueClass::LRealTwinCat: return stdlib::formatLRealTwinCat(a->f(c));
        case ValueClass::Time: return stdlib::formatDuration(stdlib::timeValueToNs(static_cast<int32_t>(a->i(c))), "T#");
        case ValueClass::LTime: return stdlib::formatDuration(a->i(c), "LTIME#");
        case ValueClass::LTimeUnsigned: return stdlib::formatUnsignedDuration(static_cast<uint64_t>(a->i(c)), "LTIME#");
        case ValueClass::TimeUnsigned: return stdlib::formatUnsignedDuration(uint64_t{static_cast<uint32_t>(a->i(c))} * 1000000u, "T#");
        case ValueClass::Date: return stdlib::formatDate(stdlib::dateValueToNs(static_cast<uint32_t>(a->i(c))), "D#");
        case ValueClass::LDate: return stdlib::formatDate(a->i(c), "LDATE#");
        case ValueClass::Tod: return stdlib::formatTimeOfDay(stdlib::todValueToNs(static_cast<uint32_t>(a->i(c))), "TOD#");
        case ValueClass::LTod: return stdlib::formatTimeOfDay(a->i(c), "LTOD#");
        case ValueClass::Dt: return stdlib::formatDateTime(stdlib::dtValueToNs(static_cast<uint32_t>(a->i(c))), "DT#");
        case ValueClass::LDt: return stdlib::formatDateTime(a->i(c), "LDT#");
        case ValueClass::Char: return std::string(1, static_cast<char>(a->i(c)));
        case ValueClass::WChar: {
            char16_t ch = static_cast<char16_t>(a->i(c));
            return stdlib::wstringToString(std::u16string_view(&ch, 1));
        }
        case ValueClass::String: return std::string(viewOf<char>(a, c));
        case ValueClass::WString: return stdlib::wstringToString(viewOf<char16_t>(a, c));
    }
    return {};
}

template <>
uint8_t* ToStringNode<char>::addr(Ctx& c) {
    std::string s = valueText(from, a, c);
    return writeString<char>(c, off, maxLen, s);
}

template <>
uint8_t* ToStringNode<char16_t>::addr(Ctx& c) {
    std::u16string w = from == ValueClass::String ? stdlib::stringToWString(viewOf<char>(a, c))
                                                   : stdlib::stringToWString(valueText(from, a, c));
    return writeString<char16_t>(c, off, maxLen, w);
}

namespace {
std::string sourceText(Expr* a, bool wide, Ctx& c) {
    if (wide) return stdlib::wstringToString(viewOf<char16_t>(a, c));
    return std::string(viewOf<char>(a, c));
}
}  // namespace

int64_t FromStringNode::i(Ctx& c) {
    std::string text = sourceText(a, wide, c);
    switch (to) {
        case ValueClass::Bool: return stdlib::stringToBool(text).value();
        case ValueClass::Signed:
        case ValueClass::Unsigned: return static_cast<int64_t>(stdlib::stringToInteger(text, bits, isSigned).value());
        case ValueClass::Time: case ValueClass::TimeUnsigned: {
            auto ns = stdlib::stringToDuration(text);
            auto ms = stdlib::nsToTimeValue(ns.value());
            return ns.ok() && ms.ok() ? ms.value() : 0;
        }
        case ValueClass::LTime: case ValueClass::LTimeUnsigned: return stdlib::stringToDuration(text).value();
        case ValueClass::Date: {
            auto ns = stdlib::stringToDate(text);
            auto s = stdlib::nsToDateValue(ns.value());
            return ns.ok() && s.ok() ? s.value() : 0;
        }
        case ValueClass::LDate: return stdlib::stringToDate(text).value();
        case ValueClass::Tod: {
            auto ns = stdlib::stringToTimeOfDay(text);
            auto ms = stdlib::nsToTodValue(ns.value());
            return ns.ok() && ms.ok() ? ms.value() : 0;
        }
        case ValueClass::LTod: return stdlib::stringToTimeOfDay(text).value();
        case ValueClass::Dt: {
            auto ns = stdlib::stringToDateTime(text);
            auto s = stdlib::nsToDtValue(ns.value());
            return ns.ok() && s.ok() ? s.value() : 0;
        }
        case ValueClass::LDt: return stdlib::stringToDateTime(text).value();
        case ValueClass::Char: return text.empty() ? 0 : static_cast<uint8_t>(text[0]);
        case ValueClass::WChar: {
            if (!wide) return text.empty() ? 0 : static_cast<uint8_t>(text[0]);
            auto v = viewOf<char16_t>(a, c);
            return v.empty() ? 0 : v[0];
        }
        default: return 0;
    }
}

double FromStringNode::f(Ctx& c) {
    std::string text = sourceText(a, wide, c);
    if (to == ValueClass::Real) return static_cast<double>(stdlib::stringToReal(text).value());
    return stdlib::stringToLReal(text).value();
}

}  // namespace strun::stdlib::bind
