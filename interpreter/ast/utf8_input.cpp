#include "interpreter/ast/utf8_input.h"

namespace strun::ast {

namespace {

// Length of the well-formed UTF-8 sequence starting at s[i], or 0 if none.
size_t validSequenceLength(const std::string& s, size_t i) {
    auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b0 = byte(i);
    if (b0 < 0x80) return 1;
    size_t len = 0;
    unsigned lo = 0x80, hi = 0xBF;  // allowed range of the second byte
    if (b0 >= 0xC2 && b0 <= 0xDF) len = 2;
    else if (b0 == 0xE0) { len = 3; lo = 0xA0; }
    else if (b0 >= 0xE1 && b0 <= 0xEC) len = 3;
    else if (b0 == 0xED) { len = 3; hi = 0x9F; }  // no surrogates
    else if (b0 >= 0xEE && b0 <= 0xEF) len = 3;
    else if (b0 == 0xF0) { len = 4; lo = 0x90; }
    else if (b0 >= 0xF1 && b0 <= 0xF3) len = 4;
    else if (b0 == 0xF4) { len = 4; hi = 0x8F; }  // at most U+10FFFF
    else return 0;
    if (i + len > s.size()) return 0;
    if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
    for (size_t k = 2; k < len; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
    return len;
}

}  // namespace

std::string sanitizeUtf8(const std::string& bytes, size_t* firstInvalid, size_t* invalidCount) {
    size_t count = 0;
    static const std::string kReplacement = "\xEF\xBF\xBD";
    size_t start = 0;
    if (bytes.size() >= 3 && bytes.compare(0, 3, "\xEF\xBB\xBF") == 0) start = 3;
    std::string out;
    out.reserve(bytes.size() - start);
    for (size_t i = start; i < bytes.size();) {
        // ASCII, nearly all of a source file, is copied a run at a time.
        size_t ascii = i;
        while (ascii < bytes.size() && static_cast<unsigned char>(bytes[ascii]) < 0x80) ++ascii;
        if (ascii > i) {
            out.append(bytes, i, ascii - i);
            i = ascii;
            continue;
        }
        const size_t len = validSequenceLength(bytes, i);
        if (len == 0) {
            if (count++ == 0 && firstInvalid != nullptr) *firstInvalid = out.size();
            out += kReplacement;
            ++i;
        } else {
            out.append(bytes, i, len);
            i += len;
        }
    }
    if (invalidCount != nullptr) *invalidCount = count;
    return out;
}

}  // namespace strun::ast
