#include "stdlib/literals.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stdlib/number_scan.h"
#include "stdlib/text_encoding.h"

namespace strun::stdlib {

namespace {

// Explains why scanDigits stopped before the end of `text`.
std::string digitError(std::string_view text, size_t stop, unsigned base) {
    const char c = text[stop];
    if (c == '_') {
        return fmt::format("misplaced underscore in integer literal {}", quoted(text));
    }
    return fmt::format("invalid digit '{}' for base {} in integer literal {}", c, base,
                       quoted(text));
}

}  // namespace

Result<uint64_t> parseIntegerLiteral(std::string_view text) {
    if (text.empty()) return Result<uint64_t>::failure("empty integer literal");
    unsigned base = 10;
    size_t start = 0;
    if (const size_t hash = text.find('#'); hash != std::string_view::npos) {
        const std::string_view prefix = text.substr(0, hash);
        if (prefix == "2") {
            base = 2;
        } else if (prefix == "8") {
            base = 8;
        } else if (prefix == "16") {
            base = 16;
        } else if (prefix == "10") {
            base = 10;  // 10#0: CODESYS/TwinCAT accept the decimal base written out
        } else {
            return Result<uint64_t>::failure(
                fmt::format("unknown base '{}' in integer literal {} (2#, 8#, 10# or 16#)", prefix,
                            quoted(text)));
        }
        start = hash + 1;
    }
    if (start >= text.size()) {
        return Result<uint64_t>::failure(fmt::format("integer literal {} has no digits", quoted(text)));
    }
    if (text[start] == '_') {
        return Result<uint64_t>::failure(
            fmt::format("misplaced underscore in integer literal {}", quoted(text)));
    }
    const DigitScan scan = scanDigits(text, start, base);
    if (scan.digits == 0) return Result<uint64_t>::failure(digitError(text, start, base));
    if (scan.end != text.size()) return Result<uint64_t>::failure(digitError(text, scan.end, base));
    if (scan.overflow) {
        return Result<uint64_t>::failure(
            fmt::format("integer literal {} is too large (more than 64 bits)", quoted(text)));
    }
    return Result<uint64_t>::success(scan.value);
}

Result<int64_t> parseSignedIntegerLiteral(std::string_view text) {
    bool negative = false;
    std::string_view digits = text;
    if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) {
        negative = digits[0] == '-';
        digits.remove_prefix(1);
        if (digits.find('#') != std::string_view::npos) {
            return Result<int64_t>::failure(
                fmt::format("a based integer literal cannot have a sign: {}", quoted(text)));
        }
    }
    const Result<uint64_t> magnitude = parseIntegerLiteral(digits);
    if (!magnitude) return Result<int64_t>::failure(magnitude.error());
    constexpr uint64_t kMaxPositive = static_cast<uint64_t>(std::numeric_limits<int64_t>::max());
    if (negative) {
        if (magnitude.value() > kMaxPositive + 1) {
            return Result<int64_t>::failure(
                fmt::format("integer literal {} is below -2^63", quoted(text)));
        }
        // Negate in unsigned arithmetic so that -2^63 does not overflow.
        return Result<int64_t>::success(static_cast<int64_t>(0 - magnitude.value()));
    }
    if (magnitude.value() > kMaxPositive) {
        return Result<int64_t>::failure(
            fmt::format("integer literal {} is above 2^63-1", quoted(text)));
    }
    return Result<int64_t>::success(static_cast<int64_t>(magnitude.value()));
}

Result<double> parseRealLiteral(std::string_view text) {
    if (text.empty()) return Result<double>::failure("empty real literal");
    const RealScan scan = scanReal(text, 0);
    if (!scan.matched || scan.end != text.size()) {
        return Result<double>::failure(fmt::format("malformed real literal {}", quoted(text)));
    }
    bool overflowed = false;
    const double value = realScanToDouble(scan, &overflowed);
    if (overflowed) {
        return Result<double>::failure(
            fmt::format("real literal {} is out of the LREAL range", quoted(text)));
    }
    return Result<double>::success(value);
}

namespace {

// Decodes the text between the quotes. `hexDigits` is 2 or 4; `emit` receives
// literal source bytes (as a run) and escape-produced code units.
template <typename Emitter>
std::string decodeStringBody(std::string_view literal, char quote, int hexDigits,
                             Emitter&& emitByte, std::string& raw) {
    const std::string_view body = literal.substr(1, literal.size() - 2);
    for (size_t i = 0; i < body.size(); ++i) {
        const char c = body[i];
        if (c == quote) {
            return fmt::format("unescaped {} inside string literal {} (write ${})", quote,
                               quoted(literal), quote);
        }
        if (c != '$') {
            raw.push_back(c);
            continue;
        }
        if (i + 1 >= body.size()) {
            return fmt::format("string literal {} ends inside an escape", quoted(literal));
        }
        const char e = body[i + 1];
        switch (e) {
            case '$': emitByte(u'$'); ++i; continue;
            case '\'': emitByte(u'\''); ++i; continue;
            case '"': emitByte(u'"'); ++i; continue;
            case 'L': case 'l': emitByte(u'\n'); ++i; continue;
            case 'N': case 'n': emitByte(u'\n'); ++i; continue;
            case 'P': case 'p': emitByte(u'\f'); ++i; continue;
            case 'R': case 'r': emitByte(u'\r'); ++i; continue;
            case 'T': case 't': emitByte(u'\t'); ++i; continue;
            default: break;
        }
        char16_t unit = 0;
        for (int k = 0; k < hexDigits; ++k) {
            const size_t at = i + 1 + static_cast<size_t>(k);
            const int digit = at < body.size() ? digitValue(body[at]) : -1;
            if (digit < 0 || digit > 15) {
                return fmt::format("invalid escape '${}' in string literal {} (expected {} hex digits)",
                                   body.substr(i + 1, static_cast<size_t>(hexDigits)), quoted(literal),
                                   hexDigits);
            }
            unit = static_cast<char16_t>(unit * 16 + digit);
        }
        emitByte(unit);
        i += static_cast<size_t>(hexDigits);
    }
    return {};
}

std::string checkQuotes(std::string_view text, std::string_view allowed) {
    if (text.size() < 2 || allowed.find(text.front()) == std::string_view::npos ||
        text.back() != text.front()) {
        return fmt::format("string literal {} is not enclosed in matching quotes", quoted(text));
    }
    return {};
}

}  // namespace

Result<std::string> parseStringLiteral(std::string_view text) {
    if (std::string error = checkQuotes(text, "'"); !error.empty()) {
        return Result<std::string>::failure(std::move(error));
    }
    std::string out;
    // Source bytes and escapes both land in `out` in order.
    auto emit = [&out](char16_t unit) { out.push_back(static_cast<char>(unit)); };
    std::string error = decodeStringBody(text, '\'', 2, emit, out);
    if (!error.empty()) return Result<std::string>::failure(std::move(error));
    return Result<std::string>::success(std::move(out));
}

Result<std::u16string> parseWideStringLiteral(std::string_view text) {
    if (std::string error = checkQuotes(text, "'\""); !error.empty()) {
        return Result<std::u16string>::failure(std::move(error));
    }
    const char quote = text.front();
    std::u16string out;
    std::string pendingUtf8;  // source bytes since the last escape
    std::string transcodeError;
    auto flush = [&]() {
        if (pendingUtf8.empty() || !transcodeError.empty()) return;
        Result<std::u16string> units = utf8ToUtf16(pendingUtf8);
        if (!units) {
            transcodeError = fmt::format("string literal {}: {}", quoted(text), units.error());
        } else {
            out += units.value();
        }
        pendingUtf8.clear();
    };
    auto emit = [&](char16_t unit) {
        flush();
        out.push_back(unit);
    };
    std::string error = decodeStringBody(text, quote, quote == '"' ? 4 : 2, emit, pendingUtf8);
    flush();
    if (error.empty()) error = transcodeError;
    if (!error.empty()) return Result<std::u16string>::failure(std::move(error));
    return Result<std::u16string>::success(std::move(out));
}

std::string quoteStringLiteral(std::string_view text, bool wide) {
    const char quote = wide ? '"' : '\'';
    std::string out(1, quote);
    out.reserve(text.size() + 2);
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (ch == '$' || ch == quote) {
            out.push_back('$');
            out.push_back(ch);
        } else if (ch == '\n') {
            out += "$N";
        } else if (ch == '\r') {
            out += "$R";
        } else if (ch == '\t') {
            out += "$T";
        } else if (c < 0x20) {
            out += wide ? fmt::format("${:04X}", c) : fmt::format("${:02X}", c);
        } else {
            out.push_back(ch);
        }
    }
    out.push_back(quote);
    return out;
}

}  // namespace strun::stdlib
