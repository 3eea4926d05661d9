// Instruction List in text files, as matiec/Beremiz and IEC 61131-3 2nd and
// 3rd edition write it: a PROGRAM, FUNCTION_BLOCK, FUNCTION, METHOD,
// property accessor or ACTION whose body, after its declarations, is IL
// (`FUNCTION_BLOCK X VAR ... END_VAR LD a ST b END_FUNCTION_BLOCK`). Each such
// body is replaced by the ST that il_body.cpp makes of it, the rest of the
// file is kept, and every line knows where it came from: a reading stage of
// its own, like textual SFC (st_textual_sfc.cpp), so the LL(1) ST grammar is
// not changed (decision 0464).
//
// How a body is recognised as IL (matiec's rule, narrowed so that no ST body
// changes meaning): its first instruction, after an optional label `L1:`, is
// an IL operator word (LD, CAL, JMP, ...) that is not followed by what an ST
// statement would put after a name (`:=`, `(`, `[`, `.`, `^`, `;`, ...), on
// a line that does not end with `;` (`JMP L1;` is ST).
#include "interpreter/source/st_textual_il.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <cctype>
#include <map>
#include <set>

#include "interpreter/source/il_body.h"
#include "interpreter/source/plcopen_graphical.h"
#include "interpreter/source/st_splice.h"
#include "interpreter/source/st_tokens.h"
#include "stdlib/library_mentions.h"
#include "stdlib/number_scan.h"

namespace strun::source {

namespace {

// Where the statements of a body stop: the end of its POU or member, or the next member.
bool endsIlBody(const std::string& up) {
    static const std::set<std::string> words = {"END_PROGRAM", "END_FUNCTION_BLOCK", "END_FUNCTION", "END_METHOD", "END_ACTION",
                                                "END_GET",     "END_SET",            "END_PROPERTY", "METHOD",     "ACTION",
                                                "PROPERTY",    "END_TRANSITION",     "GET",          "SET"};
    return words.count(up) > 0;
}

bool isIlVarKeyword(const std::string& up) { return up.rfind("VAR", 0) == 0 && up != "VARIABLE"; }

struct IlTextReader {
    const std::string& src;
    std::vector<StToken> toks;
    Converted result;
    std::vector<std::pair<size_t, size_t>> blanked;  // IL spans, replaced by blanks
    std::vector<StSplice> inserts;  // declarations before the body where both go to one place
    int bodies = 0;

    // What `S x` / `R x` need: is x a function-block instance?
    plcopen::ProjectTypes project;
    plcopen::PouContext pou;

    explicit IlTextReader(const std::string& s) : src(s), toks(tokenizeSt(s)) { pou.project = &project; }

    const StToken& at(size_t k) const {
        static const StToken end;
        return k < toks.size() ? toks[k] : end;
    }

    // The IL rule of the header comment, at token k (the body's first).
    bool startsIl(size_t k) const {
        if (at(k).word && at(k + 1).text == ":" && !endsIlBody(at(k).up)) k += 2;  // a label
        const StToken& w = at(k);
        if (!w.word || !il::isOperator(w.up)) return false;
        static const std::set<std::string> stFollowers = {":=", "(", "[", ".", "^", ";", "=>", ",", ":", "=", "<>"};
        const StToken& next = at(k + 1);
        if (stFollowers.count(next.text)) return false;  // also on the next line: `IN\n := 5;` is ST
        size_t last = k;
        while (at(last + 1).line == w.line && last + 1 < toks.size()) ++last;
        return at(last).text != ";";
    }

    void fail(int line, int col, const std::string& message) {
        result.errors.push_back({line, col, message});
    }

    // The IL body from token b to e (exclusive), declarations at token `declAt`.
    void body(size_t b, size_t e, size_t declAt) {
        const size_t from = at(b).begin;
        const size_t to = e < toks.size() ? at(e).begin : src.size();
        il::Surroundings around;
        around.prefix = "_il" + std::to_string(++bodies) + "_";
        around.isBlockInstance = [this](const std::string& name) { return pou.isBlockInstance(name); };
        around.fail = [this](int line, int col, const std::string& message) { fail(line, col, message); };
        plcopen::Translation tr;
        const std::string text = src.substr(from, to - from);
        blanked.push_back({from, to});
        if (!il::translate(text, at(b).line, at(b).col, around, tr)) return;
        if (!tr.declarations.empty()) inserts.push_back({at(declAt).begin, std::move(tr.declarations), {}});
        inserts.push_back({from, {}, std::move(tr.body)});
    }

    void run() {
        // Function blocks and globals of the file first: `S fb` may name a block declared further down.
        for (size_t k = 0; k + 1 < toks.size(); ++k)
            if (at(k).up == "FUNCTION_BLOCK" && at(k + 1).word) project.blockOutputs[at(k + 1).up];
        declaredVariables(toks, 0, toks.size(), true, project.globals);
        size_t pouStart = 0;      // the POU keyword
        size_t elementsAt = 0;    // the POU's first declaration or member: where an ACTION's temporaries go
        bool elementsKnown = false;
        for (size_t k = 0; k < toks.size(); ++k) {
            const std::string& u = at(k).up;
            if (u == "PROGRAM" || u == "FUNCTION_BLOCK" || u == "FUNCTION") {
                pouStart = k;
                elementsKnown = false;
                pou.variables.clear();
                size_t end = k + 1;
                while (end < toks.size() && at(end).up != "END_" + u) ++end;
                declaredVariables(toks, k, end, false, pou.variables);
                continue;
            }
            if (!elementsKnown && k > pouStart && (isIlVarKeyword(u) || u == "METHOD" || u == "ACTION" || u == "PROPERTY")) {
                elementsAt = k;
                elementsKnown = true;
            }
            // A body starts after the declarations of its POU or member, or after an ACTION's header.
            size_t start = 0;
            bool action = false;
            if (u == "END_VAR" || u == "END_METHOD" || u == "END_ACTION" || u == "END_PROPERTY") {
                start = k + 1;
            } else if (u == "ACTION" && at(k + 1).word) {
                start = at(k + 2).text == ":" ? k + 3 : k + 2;
                action = true;
            } else {
                continue;
            }
            const std::string& first = at(start).up;
            if (start >= toks.size() || isIlVarKeyword(first) || endsIlBody(first) || !startsIl(start)) continue;
            size_t end = start;
            while (end < toks.size() && !endsIlBody(at(end).up)) ++end;
            const bool hasVarBlockPlace = !action;  // a METHOD, accessor or POU body may have a VAR section before it
            body(start, end, hasVarBlockPlace ? start : (elementsKnown ? elementsAt : start));
            k = end - 1;
        }
    }

    void write() {
        if (!result.errors.empty()) return;
        if (inserts.empty()) {
            result.text = src;
            return;
        }
        spliceSt(src, blanked, std::move(inserts), result);
    }
};

// Skips blanks, comments and pragmas from i.
size_t skipBlankIl(const std::string& s, size_t i) {
    while (i < s.size()) {
        if (std::isspace(static_cast<unsigned char>(s[i]))) { ++i; continue; }
        if (s.compare(i, 2, "(*") == 0 || s.compare(i, 2, "/*") == 0) {
            size_t e = s.find(s[i] == '(' ? "*)" : "*/", i + 2);
            i = e == std::string::npos ? s.size() : e + 2;
            continue;
        }
        if (s.compare(i, 2, "//") == 0) { size_t e = s.find('\n', i); i = e == std::string::npos ? s.size() : e; continue; }
        if (s[i] == '{') { size_t e = s.find('}', i); i = e == std::string::npos ? s.size() : e + 1; continue; }
        break;
    }
    return i;
}

// The length of the word (letters, digits, '_') at i.
size_t ilWordLength(const std::string& s, size_t i) {
    size_t e = i;
    while (e < s.size() && (std::isalnum(static_cast<unsigned char>(s[e])) || s[e] == '_')) ++e;
    return e - i;
}

std::string ilWordAt(const std::string& s, size_t i) { return stdlib::upperAscii(std::string_view(s).substr(i, ilWordLength(s, i))); }

// Case-insensitive: does `s` hold `word` at i?
bool ilHasWord(const std::string& s, size_t i, std::string_view word) {
    return stdlib::equalsIgnoreCase(std::string_view(s).substr(i, word.size()), word);
}

}  // namespace

bool mayHoldTextualIl(const std::string& s) {
    // Every 'e' and 'a' of the text starts a test; the second letter
    // decides most of them at once. The first test is a table lookup: the
    // scan runs over every byte of every ST file read, before the parse.
    static constexpr auto kStarts = [] {
        std::array<bool, 256> table{};
        table['E'] = table['e'] = table['A'] = table['a'] = true;
        return table;
    }();
    const auto* bytes = reinterpret_cast<const unsigned char*>(s.data());
    const size_t n = s.size();
    // The first of those letters at or after i (n when none): eight bytes at
    // a time (decision 0493). A byte b has b | 0x20 == 'e' only when it is
    // 'e' or 'E' (the same for 'a'), and a word has a zero byte exactly when
    // (v - 0x01..) & ~v & 0x80.. is not zero.
    auto nextStart = [&](size_t i) {
        constexpr uint64_t kOnes = 0x0101010101010101ull;
        constexpr uint64_t kHighs = 0x8080808080808080ull;
        for (; i + 8 <= n; i += 8) {
            uint64_t word;
            std::memcpy(&word, bytes + i, 8);
            const uint64_t folded = word | (kOnes * 0x20);
            const uint64_t e = folded ^ (kOnes * 'e');
            const uint64_t a = folded ^ (kOnes * 'a');
            if ((((e - kOnes) & ~e) | ((a - kOnes) & ~a)) & kHighs) break;
        }
        while (i < n && !kStarts[bytes[i]]) ++i;
        return i;
    };
    for (size_t i = nextStart(0); i + 1 < n; i = nextStart(i + 1)) {
        const char c = stdlib::upperAscii(s[i]);
        const char second = stdlib::upperAscii(s[i + 1]);
        if (!((c == 'E' && second == 'N') || (c == 'A' && second == 'C'))) continue;
        size_t after = 0;
        // END_VAR, END_METHOD, END_ACTION: the letter after END_ first
        // (END_IF, END_FOR, ... stop there).
        const char fifth = c == 'E' && i + 4 < n && s[i + 3] == '_' ? stdlib::upperAscii(s[i + 4]) : '\0';
        if (fifth == 'V' && ilHasWord(s, i, "END_VAR")) after = i + 7;
        else if (fifth == 'M' && ilHasWord(s, i, "END_METHOD")) after = i + 10;
        else if (fifth == 'A' && ilHasWord(s, i, "END_ACTION")) after = i + 10;
        else if (c == 'A' && ilHasWord(s, i, "ACTION") && (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1])))) {
            after = skipBlankIl(s, i + 6);
            after += ilWordLength(s, after);  // the action's name
            after = skipBlankIl(s, after);
            if (after < s.size() && s[after] == ':') ++after;
        } else {
            continue;
        }
        size_t w = skipBlankIl(s, after);
        size_t length = ilWordLength(s, w);
        if (length == 0) continue;
        size_t next = skipBlankIl(s, w + length);
        if (next < s.size() && s[next] == ':' && s.compare(next, 2, ":=") != 0) {  // a label: the word after it
            w = skipBlankIl(s, next + 1);
            length = ilWordLength(s, w);
        }
        // A word longer than every operator (the statement after an ST
        // END_VAR, mostly) is tested without being copied (decision 0493).
        if (length == 0 || length > il::kLongestOperator) continue;
        if (il::isOperator(ilWordAt(s, w))) return true;
    }
    return false;
}

Converted convertTextualIl(const std::string& text) {
    IlTextReader r(text);
    r.run();
    r.write();
    return std::move(r.result);
}

}  // namespace strun::source
