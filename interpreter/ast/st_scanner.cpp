#include "interpreter/ast/st_scanner.h"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "grammar/STLexer.h"
#include "stdlib/number_scan.h"

namespace strun::ast {

namespace {

using L = strun_grammar::STLexer;

bool isDigit(unsigned char c) { return c >= '0' && c <= '9'; }
bool isHex(unsigned char c) { return isDigit(c) || ((c | 0x20) >= 'a' && (c | 0x20) <= 'f'); }
bool isIdentStart(unsigned char c) { return ((c | 0x20) >= 'a' && (c | 0x20) <= 'z') || c == '_'; }
bool isIdentPart(unsigned char c) { return isIdentStart(c) || isDigit(c); }
unsigned char lower(unsigned char c) { return c >= 'A' && c <= 'Z' ? static_cast<unsigned char>(c | 0x20) : c; }

bool isOneOf(std::string_view word, std::initializer_list<std::string_view> keywords) {
    return std::any_of(keywords.begin(), keywords.end(), [&](std::string_view k) { return stdlib::equalsIgnoreCase(word, k); });
}

struct Quoted {
    size_t length;
    bool closed;
};

// The matchers return the length of the longest text their grammar rule (or
// fragment) matches at byte offset p, 0 for none. Past the end at() reads
// 0, which no rule accepts where it is used.
class Scanner {
public:
    Scanner(std::string_view text, size_t maxTokens) : s_(text), n_(text.size()), maxTokens_(maxTokens) {
        // ST has about one token per 4-8 bytes: room for a quarter of the
        // bytes as tokens, so that a large file's vector is not grown and
        // copied a dozen times (decision 0494). Pages never written cost nothing.
        result_.tokens.reserve(std::min(n_ / 4, maxTokens) + 16);
    }

    ScanResult run() {
        size_t p = 0;
        while (p < n_) {
            const size_t next = token(p);
            p = next;
            if (result_.tokens.size() > maxTokens_) {
                result_.overLimit = true;
                break;
            }
        }
        moveCursor(p);
        result_.tokens.push_back({antlr4::Token::EOF, antlr4::Token::DEFAULT_CHANNEL, static_cast<std::uint32_t>(p),
                                  static_cast<std::uint32_t>(p - 1), line_, column_});
        return std::move(result_);
    }

private:
    unsigned char at(size_t i) const { return i < n_ ? static_cast<unsigned char>(s_[i]) : 0; }

    // Line and column of byte offset p; p only grows, so each byte is counted once.
    void moveCursor(size_t p) {
        for (; cursor_ < p; ++cursor_) {
            const unsigned char c = static_cast<unsigned char>(s_[cursor_]);
            if (c == '\n') {
                ++line_;
                column_ = 0;
            } else if ((c & 0xC0) != 0x80) {
                ++column_;  // a code point's first byte
            }
        }
    }

    void emit(size_t type, size_t p, size_t length, size_t channel = antlr4::Token::DEFAULT_CHANNEL) {
        moveCursor(p);
        result_.tokens.push_back({type, static_cast<std::uint32_t>(channel), static_cast<std::uint32_t>(p),
                                  static_cast<std::uint32_t>(p + length - 1), line_, column_});
    }

    // Scans the token (or skipped text) at p; returns where the next one starts.
    size_t token(size_t p) {
        const unsigned char c = at(p);
        const unsigned char c1 = at(p + 1);
        switch (c) {
            case ' ': case '\t': case '\r': case '\n': case '\f': case '\v': {
                size_t i = p + 1;
                while (i < n_ && (s_[i] == ' ' || s_[i] == '\t' || s_[i] == '\r' || s_[i] == '\n' || s_[i] == '\f' || s_[i] == '\v')) ++i;
                return i;
            }
            case '(':
                if (c1 == '*') return blockComment(p);
                return single(L::LPAREN, p);
            case '/':
                if (c1 == '*') return cComment(p);
                if (c1 == '/') {
                    size_t i = p + 2;
                    while (i < n_ && s_[i] != '\r' && s_[i] != '\n') ++i;
                    return i;
                }
                return single(L::SLASH, p);
            case '{': {
                // `{{ ... }}`: matiec/Beremiz inline C code, whose braces nest;
                // it ends at the first `}}` (decision 0351). Without a `}}` it is
                // an ordinary pragma, as the grammar's longest match has it.
                const size_t cClose = c1 == '{' ? s_.find("}}", p + 2) : std::string_view::npos;
                const bool cBlock = cClose != std::string_view::npos;
                const size_t close = cBlock ? cClose : s_.find('}', p + 1);
                if (close == std::string_view::npos) return rest(L::UNTERMINATED_PRAGMA, p);
                const size_t end = close + (cBlock ? 2 : 1);
                emit(L::PRAGMA, p, end - p, L::PRAGMAS);
                return end;
            }
            case '\'': return quotedToken(p, '\'', L::STRING_LITERAL, L::UNTERMINATED_STRING);
            case '"': return quotedToken(p, '"', L::WSTRING_LITERAL, L::UNTERMINATED_WSTRING);
            case '%': return percent(p);
            case ':': return c1 == '=' ? pair(L::ASSIGN, p) : single(L::COLON, p);
            case '=': return c1 == '>' ? pair(L::ARROW, p) : single(L::EQ, p);
            case '?': return c1 == '=' ? pair(L::TRY_ASSIGN, p) : errorChar(p);
            case '.': return c1 == '.' ? pair(L::DOTDOT, p) : single(L::DOT, p);
            case '*': return c1 == '*' ? pair(L::POW, p) : single(L::STAR, p);
            case '<': return c1 == '=' ? pair(L::LE, p) : c1 == '>' ? pair(L::NE, p) : single(L::LT_OP, p);
            case '>': return c1 == '=' ? pair(L::GE, p) : single(L::GT_OP, p);
            case '+': return single(L::PLUS, p);
            case '-': return single(L::MINUS, p);
            case '&': return single(L::AMP, p);
            case '^': return single(L::CARET, p);
            case ',': return single(L::COMMA, p);
            case ';': return single(L::SEMI, p);
            case ')': return single(L::RPAREN, p);
            case '[': return single(L::LBRACK, p);
            case ']': return single(L::RBRACK, p);
            case '#': return single(L::HASH, p);
            default: break;
        }
        if (isDigit(c)) return number(p);
        if (isIdentStart(c)) return word(p);
        return errorChar(p);
    }

    size_t single(size_t type, size_t p) {
        emit(type, p, 1);
        return p + 1;
    }
    size_t pair(size_t type, size_t p) {
        emit(type, p, 2);
        return p + 2;
    }
    // A token from p to the end of the text, on the ERRORS channel.
    size_t rest(size_t type, size_t p) {
        emit(type, p, n_ - p, L::ERRORS);
        return n_;
    }
    // One code point nothing else accepts.
    size_t errorChar(size_t p) {
        const unsigned char c = at(p);
        const size_t length = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
        emit(L::ERROR_CHAR, p, std::min(length, n_ - p), L::ERRORS);
        return p + std::min(length, n_ - p);
    }

    // (* ... *) nests; an unterminated one becomes one error token to the end.
    size_t blockComment(size_t p) {
        int depth = 1;
        size_t i = p + 2;
        while (i < n_) {
            if (s_[i] == '(' && at(i + 1) == '*') {
                ++depth;
                i += 2;
            } else if (s_[i] == '*' && at(i + 1) == ')') {
                i += 2;
                if (--depth == 0) return i;
            } else {
                ++i;
            }
        }
        return rest(L::UNTERMINATED_BLOCK_COMMENT, p);
    }

    size_t cComment(size_t p) {
        const size_t close = s_.find("*/", p + 2);
        if (close == std::string_view::npos) return rest(L::UNTERMINATED_C_COMMENT, p);
        return close + 2;
    }

    // A string body up to the closing quote or, unterminated, up to the end
    // of the line (a '$' just before it included).
    Quoted quoted(size_t p, char quote) const {
        size_t i = p + 1;
        while (i < n_) {
            const char c = s_[i];
            if (c == quote) return {i + 1 - p, true};
            if (c == '\r' || c == '\n') break;
            if (c == '$') {
                if (i + 1 < n_ && s_[i + 1] != '\r' && s_[i + 1] != '\n') {
                    i += 2;
                    continue;
                }
                ++i;
                break;
            }
            ++i;
        }
        return {i - p, false};
    }

    size_t quotedToken(size_t p, char quote, size_t closedType, size_t unterminatedType) {
        const Quoted q = quoted(p, quote);
        if (q.closed)
            emit(closedType, p, q.length);
        else
            emit(unterminatedType, p, q.length, L::ERRORS);
        return p + q.length;
    }

    size_t digits(size_t p) const {
        size_t i = p;
        while (isDigit(at(i))) ++i;
        return i - p;
    }

    // Where `d ('_'* d)*` ends when its first digit ends at i.
    template <typename IsDigit>
    size_t restOfDigits(size_t i, IsDigit isDigitOf) const {
        for (;;) {
            if (isDigitOf(at(i))) {
                ++i;
                continue;
            }
            size_t j = i;
            while (at(j) == '_') ++j;
            if (j == i || !isDigitOf(at(j))) return i;
            i = j + 1;
        }
    }

    // [0-9] ('_'* [0-9])*
    size_t decInt(size_t p) const { return isDigit(at(p)) ? restOfDigits(p + 1, isDigit) - p : 0; }

    // ('2' | '8' | '10' | '16') '#' '_'? hex ('_'* hex)*
    size_t basedInt(size_t p) const {
        size_t base = 0;
        if (at(p) == '2' || at(p) == '8')
            base = 1;
        else if (at(p) == '1' && (at(p + 1) == '0' || at(p + 1) == '6'))
            base = 2;
        if (base == 0 || at(p + base) != '#') return 0;
        size_t i = p + base + 1;
        if (at(i) == '_') ++i;
        return isHex(at(i)) ? restOfDigits(i + 1, isHex) - p : 0;
    }

    // E ('+' | '-')? DEC_INT
    size_t exponent(size_t p) const {
        if (lower(at(p)) != 'e') return 0;
        size_t i = p + 1;
        if (at(i) == '+' || at(i) == '-') ++i;
        const size_t d = decInt(i);
        return d == 0 ? 0 : i + d - p;
    }

    // DEC_INT '.' DEC_INT EXPONENT? | DEC_INT EXPONENT
    size_t realFrag(size_t p) const {
        const size_t whole = decInt(p);
        if (whole == 0) return 0;
        if (at(p + whole) == '.') {
            const size_t fraction = decInt(p + whole + 1);
            if (fraction == 0) return 0;
            const size_t length = whole + 1 + fraction;
            return length + exponent(p + length);
        }
        const size_t e = exponent(p + whole);
        return e == 0 ? 0 : whole + e;
    }

    size_t identFrag(size_t p) const {
        if (!isIdentStart(at(p))) return 0;
        size_t i = p + 1;
        while (isIdentPart(at(i))) ++i;
        return i - p;
    }

    // [0-9] [0-9_]* ('.' [0-9]+)? (D | H | M | S | MS | US | NS) '_'?
    size_t durationPart(size_t p) const {
        if (!isDigit(at(p))) return 0;
        size_t i = p + 1;
        while (isDigit(at(i)) || at(i) == '_') ++i;
        if (at(i) == '.' && isDigit(at(i + 1))) i += 1 + digits(i + 1);
        const unsigned char unit = lower(at(i));
        if (unit == 'm') {
            i += lower(at(i + 1)) == 's' ? 2 : 1;
        } else if (unit == 'u' || unit == 'n') {
            if (lower(at(i + 1)) != 's') return 0;
            i += 2;
        } else if (unit == 'd' || unit == 'h' || unit == 's') {
            i += 1;
        } else {
            return 0;
        }
        if (at(i) == '_') ++i;
        return i - p;
    }

    // [0-9]+ '-' [0-9]+ '-' [0-9]+
    size_t dateValue(size_t p) const {
        size_t i = p;
        for (int field = 0; field < 3; ++field) {
            if (field > 0) {
                if (at(i) != '-') return 0;
                ++i;
            }
            const size_t d = digits(i);
            if (d == 0) return 0;
            i += d;
        }
        return i - p;
    }

    // [0-9]+ ':' [0-9]+ (':' [0-9]+ ('.' [0-9]+)?)?
    size_t todValue(size_t p) const {
        const size_t hours = digits(p);
        if (hours == 0 || at(p + hours) != ':') return 0;
        const size_t minutes = digits(p + hours + 1);
        if (minutes == 0) return 0;
        size_t i = p + hours + 1 + minutes;
        if (at(i) == ':' && isDigit(at(i + 1))) {
            i += 1 + digits(i + 1);
            if (at(i) == '.' && isDigit(at(i + 1))) i += 1 + digits(i + 1);
        }
        return i - p;
    }

    // The prefix `word` (a whole identifier) is followed by '#' at `hash`.
    size_t duration(std::string_view word, size_t hash) const {
        if (!isOneOf(word, {"T", "TIME", "LT", "LTIME"})) return 0;
        size_t i = hash + 1;
        while (at(i) == ' ' || at(i) == '\t') ++i;  // `T# 30ms`, as matiec (Beremiz, OpenPLC) reads it (decision 0357)
        if (at(i) == '+' || at(i) == '-') ++i;
        size_t part = durationPart(i);
        if (part == 0) return 0;
        while (part != 0) {
            i += part;
            part = durationPart(i);
        }
        return i - (hash - word.size());
    }

    size_t date(std::string_view word, size_t hash) const {
        if (!isOneOf(word, {"D", "DATE", "LD", "LDATE"})) return 0;
        const size_t v = dateValue(hash + 1);
        return v == 0 ? 0 : word.size() + 1 + v;
    }

    size_t timeOfDay(std::string_view word, size_t hash) const {
        if (!isOneOf(word, {"TOD", "TIME_OF_DAY", "LTOD", "LTIME_OF_DAY"})) return 0;
        const size_t v = todValue(hash + 1);
        return v == 0 ? 0 : word.size() + 1 + v;
    }

    size_t dateAndTime(std::string_view word, size_t hash) const {
        if (!isOneOf(word, {"DT", "DATE_AND_TIME", "LDT", "LDATE_AND_TIME"})) return 0;
        const size_t d = dateValue(hash + 1);
        if (d == 0 || at(hash + 1 + d) != '-') return 0;
        const size_t t = todValue(hash + 2 + d);
        return t == 0 ? 0 : word.size() + 2 + d + t;
    }

    // TYPE#value: ('+' | '-')? (DEC_INT | BASED_INT | REAL_FRAG) | IDENT_FRAG | SQ_STRING | DQ_STRING
    size_t typed(std::string_view word, size_t hash) const {
        const size_t i = hash + 1;
        const unsigned char c = at(i);
        size_t value = 0;
        if (c == '+' || c == '-') {
            const size_t number = std::max({decInt(i + 1), basedInt(i + 1), realFrag(i + 1)});
            value = number == 0 ? 0 : 1 + number;
        } else if (isDigit(c)) {
            value = std::max({decInt(i), basedInt(i), realFrag(i)});
        } else if (isIdentStart(c)) {
            value = identFrag(i);
        } else if (c == '\'' || c == '"') {
            const Quoted q = quoted(i, static_cast<char>(c));
            value = q.closed ? q.length : 0;
        }
        return value == 0 ? 0 : word.size() + 1 + value;
    }

    // An identifier, a keyword, or a literal with a TYPE# prefix.
    size_t word(size_t p) {
        const size_t length = identFrag(p);
        const std::string_view text = s_.substr(p, length);
        if (at(p + length) == '#') {
            const size_t hash = p + length;
            // Longest match; on a tie the rule listed first in STLexer.g4.
            size_t best = 0, type = 0;
            auto consider = [&](size_t candidate, size_t candidateType) {
                if (candidate > best) best = candidate, type = candidateType;
            };
            consider(duration(text, hash), L::DURATION_LITERAL);
            consider(date(text, hash), L::DATE_LITERAL);
            consider(timeOfDay(text, hash), L::TOD_LITERAL);
            consider(dateAndTime(text, hash), L::DT_LITERAL);
            consider(typed(text, hash), L::TYPED_LITERAL);
            if (best != 0) {
                emit(type, p, best);
                return p + best;
            }
        }
        emit(keywordOrIdentifier(text), p, length);
        return p + length;
    }

    size_t number(size_t p) {
        size_t best = basedInt(p), type = L::BASED_INTEGER;
        if (const size_t real = realFrag(p); real > best) best = real, type = L::REAL_LITERAL;
        if (const size_t integer = decInt(p); integer > best) best = integer, type = L::INTEGER;
        emit(type, p, best);
        return p + best;
    }

    // [0-9]+ ('.' [0-9]+)* | '*'
    size_t addressTail(size_t p) const {
        if (at(p) == '*') return 1;
        size_t i = p + digits(p);
        if (i == p) return 0;
        while (at(i) == '.' && isDigit(at(i + 1))) i += 1 + digits(i + 1);
        return i - p;
    }

    // %IX0.0 and the like (DIRECT_ADDRESS), %X3 (PARTIAL_ACCESS), else a stray '%'.
    size_t percent(size_t p) {
        const unsigned char area = lower(at(p + 1));
        auto isSize = [](unsigned char c) { return c == 'x' || c == 'b' || c == 'w' || c == 'd' || c == 'l'; };
        if (area == 'i' || area == 'q' || area == 'm' || area == 's') {
            size_t best = 0;
            if (isSize(lower(at(p + 2))))
                if (const size_t tail = addressTail(p + 3)) best = 3 + tail;
            if (const size_t tail = addressTail(p + 2); tail != 0 && 2 + tail > best) best = 2 + tail;
            if (best != 0) {
                emit(L::DIRECT_ADDRESS, p, best);
                return p + best;
            }
        } else if (isSize(area)) {
            if (const size_t d = digits(p + 2)) {
                emit(L::PARTIAL_ACCESS, p, 2 + d);
                return p + 2 + d;
            }
        }
        return errorChar(p);
    }

    std::string_view s_;
    size_t n_;
    size_t maxTokens_;
    size_t cursor_ = 0;
    std::uint32_t line_ = 1, column_ = 0;
    ScanResult result_;
};

}  // namespace

std::size_t keywordOrIdentifier(std::string_view word) {
    static const std::unordered_map<std::string_view, std::size_t> keywords = {
        {"PROGRAM", L::PROGRAM}, {"END_PROGRAM", L::END_PROGRAM}, {"FUNCTION", L::FUNCTION},
        {"END_FUNCTION", L::END_FUNCTION}, {"FUNCTION_BLOCK", L::FUNCTION_BLOCK},
        {"END_FUNCTION_BLOCK", L::END_FUNCTION_BLOCK}, {"METHOD", L::METHOD}, {"END_METHOD", L::END_METHOD},
        {"END_ACTION", L::END_ACTION}, {"ACTION", L::ACTION}, {"PROPERTY", L::PROPERTY},
        {"END_PROPERTY", L::END_PROPERTY}, {"INTERFACE", L::INTERFACE}, {"END_INTERFACE", L::END_INTERFACE},
        {"NAMESPACE", L::NAMESPACE}, {"END_NAMESPACE", L::END_NAMESPACE},
        {"CLASS", L::CLASS}, {"END_CLASS", L::END_CLASS}, {"USING", L::USING},
        {"TYPE", L::TYPE}, {"END_TYPE", L::END_TYPE}, {"STRUCT", L::STRUCT}, {"END_STRUCT", L::END_STRUCT},
        {"UNION", L::UNION}, {"END_UNION", L::END_UNION}, {"ARRAY", L::ARRAY}, {"OF", L::OF},
        {"STRING", L::STRING}, {"WSTRING", L::WSTRING}, {"POINTER", L::POINTER}, {"REF_TO", L::REF_TO},
        {"REFERENCE", L::REFERENCE}, {"TO", L::TO}, {"EXTENDS", L::EXTENDS}, {"IMPLEMENTS", L::IMPLEMENTS},
        {"ABSTRACT", L::ABSTRACT}, {"FINAL", L::FINAL}, {"PUBLIC", L::PUBLIC}, {"PRIVATE", L::PRIVATE},
        {"PROTECTED", L::PROTECTED}, {"INTERNAL", L::INTERNAL}, {"THIS", L::THIS}, {"SUPER", L::SUPER},
        {"END_GET", L::END_GET}, {"END_SET", L::END_SET}, {"GET", L::GET}, {"SET", L::SET}, {"VAR", L::VAR},
        {"VAR_INPUT", L::VAR_INPUT}, {"VAR_OUTPUT", L::VAR_OUTPUT}, {"VAR_IN_OUT", L::VAR_IN_OUT},
        {"VAR_TEMP", L::VAR_TEMP}, {"VAR_STAT", L::VAR_STAT}, {"VAR_INST", L::VAR_INST}, {"VAR_GENERIC", L::VAR_GENERIC},
        {"VAR_GLOBAL", L::VAR_GLOBAL}, {"VAR_EXTERNAL", L::VAR_EXTERNAL}, {"VAR_ACCESS", L::VAR_ACCESS},
        {"VAR_CONFIG", L::VAR_CONFIG}, {"END_VAR", L::END_VAR}, {"CONSTANT", L::CONSTANT},
        {"RETAIN", L::RETAIN}, {"NON_RETAIN", L::NON_RETAIN}, {"PERSISTENT", L::PERSISTENT}, {"AT", L::AT},
        {"CONFIGURATION", L::CONFIGURATION}, {"END_CONFIGURATION", L::END_CONFIGURATION},
        {"RESOURCE", L::RESOURCE}, {"END_RESOURCE", L::END_RESOURCE}, {"TASK", L::TASK}, {"ON", L::ON},
        {"WITH", L::WITH}, {"READ_ONLY", L::READ_ONLY}, {"READ_WRITE", L::READ_WRITE}, {"IF", L::IF},
        {"THEN", L::THEN}, {"ELSIF", L::ELSIF}, {"ELSE", L::ELSE}, {"END_IF", L::END_IF}, {"CASE", L::CASE},
        {"END_CASE", L::END_CASE}, {"FOR", L::FOR}, {"BY", L::BY}, {"DO", L::DO}, {"END_FOR", L::END_FOR},
        {"WHILE", L::WHILE}, {"END_WHILE", L::END_WHILE}, {"REPEAT", L::REPEAT}, {"UNTIL", L::UNTIL},
        {"END_REPEAT", L::END_REPEAT}, {"EXIT", L::EXIT}, {"CONTINUE", L::CONTINUE}, {"RETURN", L::RETURN},
        {"JMP", L::JMP}, {"AND_THEN", L::AND_THEN}, {"OR_ELSE", L::OR_ELSE}, {"AND", L::AND}, {"OR", L::OR},
        {"XOR", L::XOR}, {"NOT", L::NOT}, {"MOD", L::MOD}, {"TRUE", L::TRUE}, {"FALSE", L::FALSE},
    };
    constexpr size_t kLongestKeyword = 18;  // END_FUNCTION_BLOCK
    if (word.size() < 2 || word.size() > kLongestKeyword) return L::IDENTIFIER;
    char upper[kLongestKeyword];
    for (size_t i = 0; i < word.size(); ++i) {
        const char c = word[i];
        upper[i] = c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
    }
    const auto it = keywords.find(std::string_view(upper, word.size()));
    return it == keywords.end() ? static_cast<std::size_t>(L::IDENTIFIER) : it->second;
}

ScanResult scanSource(std::string_view text, std::size_t maxTokens) { return Scanner(text, maxTokens).run(); }

}  // namespace strun::ast
