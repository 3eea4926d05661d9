// IL to ST (il_body.h, decision 0415). Two passes: the lines are read into
// instructions, then written as ST with the current result (CR) carried as
// an expression. A liveness pass first tells, for every instruction,
// whether the CR it leaves is read again before an instruction replaces it:
// only then must an expression that reads variables be kept in a temporary
// (a later store could change what it reads), and only then does a label
// need a temporary that every path into it assigns.
#include "interpreter/source/il_body.h"

#include <cctype>
#include <cstring>
#include <map>
#include <string_view>
#include <vector>

namespace strun::source::il {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string trim(std::string_view s) {
    size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return std::string(s.substr(b, e - b));
}

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The text with comments `(* *)`, `/* */`, `// ...` and pragmas `{ }`
// blanked out (line breaks kept, so positions stay); strings are kept.
std::string withoutComments(std::string_view s) {
    std::string out(s);
    size_t i = 0;
    auto blank = [&](size_t from, size_t to) {
        for (size_t k = from; k < to && k < out.size(); ++k)
            if (out[k] != '\n') out[k] = ' ';
    };
    while (i < out.size()) {
        const char c = out[i];
        if (c == '\'' || c == '"') {
            size_t e = i + 1;
            while (e < out.size() && out[e] != c && out[e] != '\n') e += out[e] == '$' ? 2 : 1;
            i = e + 1;
        } else if (out.compare(i, 2, "(*") == 0 || out.compare(i, 2, "/*") == 0) {
            size_t e = out.find(out[i] == '(' ? "*)" : "*/", i + 2);
            e = e == std::string::npos ? out.size() : e + 2;
            blank(i, e);
            i = e;
        } else if (out.compare(i, 2, "//") == 0) {
            size_t e = out.find('\n', i);
            e = e == std::string::npos ? out.size() : e;
            blank(i, e);
            i = e;
        } else if (c == '{') {
            size_t e = out.find('}', i);
            e = e == std::string::npos ? out.size() : e + 1;
            blank(i, e);
            i = e;
        } else {
            ++i;
        }
    }
    return out;
}

// Parentheses still open at the end of `s` (outside strings).
int openParens(std::string_view s) {
    int depth = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '\'' || s[i] == '"') {
            const char q = s[i];
            for (++i; i < s.size() && s[i] != q; ++i)
                if (s[i] == '$') ++i;
        } else if (s[i] == '(') {
            ++depth;
        } else if (s[i] == ')') {
            --depth;
        }
    }
    return depth;
}

// The operands of a function call written `LIMIT 0, 100`, split at the commas outside parentheses and strings.
std::vector<std::string> splitOperands(const std::string& s) {
    std::vector<std::string> out;
    int depth = 0;
    size_t start = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '\'' || c == '"') {
            for (++i; i < s.size() && s[i] != c; ++i)
                if (s[i] == '$') ++i;
        } else if (c == '(' || c == '[') {
            ++depth;
        } else if (c == ')' || c == ']') {
            --depth;
        } else if (c == ',' && depth == 0) {
            out.push_back(trim(std::string_view(s).substr(start, i - start)));
            start = i + 1;
        }
    }
    out.push_back(trim(std::string_view(s).substr(start)));
    return out;
}

// A literal: re-reading it later gives the same value, whatever was stored meanwhile.
bool isLiteral(const std::string& s) {
    if (s.empty()) return false;
    const char c = s[0];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '\'' || c == '"') return true;
    if ((c == '-' || c == '+') && s.size() > 1 && std::isdigit(static_cast<unsigned char>(s[1]))) return true;
    const std::string u = upper(s);
    if (u == "TRUE" || u == "FALSE") return true;
    size_t k = 0;
    while (k < s.size() && identChar(s[k])) ++k;
    return k > 0 && k < s.size() && s[k] == '#';  // INT#5, T#5s, 16#FF, Color#Red
}

enum class Op {
    Label, Load, Store, Set, Reset, FbInput, Binary, Not, Jump, Call, Return, Open, Close, Function, FormalFunction,
};

struct Instr {
    Op op = Op::Load;
    std::string word;     // the operator as written, upper case
    std::string operand;  // as written
    bool negated = false;       // LDN, STN, ANDN, &N, ORN, XORN; ANDN( ... )
    bool conditional = false;   // JMPC, CALC, RETC (and the N forms)
    bool onFalse = false;       // JMPCN, CALCN, RETCN
    std::string infix;          // Binary / Open: the ST operator
    std::string param;          // FbInput: the input
    int line = 1, col = 1;      // of the instruction in the file
    std::string text;           // the instruction as written (one line)
    std::string element;        // what diagnostics on its lines name
    int target = -1;            // Jump: the Label instruction
    int close = -1;             // Open: its Close
};

const std::map<std::string, std::pair<std::string, bool>>& binaryOperators() {
    // operator -> (ST operator, negated operand)
    static const std::map<std::string, std::pair<std::string, bool>> ops = {
        {"AND", {"AND", false}}, {"&", {"AND", false}}, {"ANDN", {"AND", true}}, {"&N", {"AND", true}},
        {"OR", {"OR", false}},   {"ORN", {"OR", true}}, {"XOR", {"XOR", false}}, {"XORN", {"XOR", true}},
        {"ADD", {"+", false}},   {"SUB", {"-", false}}, {"MUL", {"*", false}},   {"DIV", {"/", false}},
        {"MOD", {"MOD", false}}, {"GT", {">", false}},  {"GE", {">=", false}},   {"EQ", {"=", false}},
        {"NE", {"<>", false}},   {"LE", {"<=", false}}, {"LT", {"<", false}},
    };
    return ops;
}

// The inputs of the standard blocks that are IL operators of their own (`CU C10`: C10(CU := CR)).
constexpr std::string_view kBlockInputOperators[] = {"S1", "R1", "CLK", "CU", "CD", "PV", "IN", "PT"};
bool isBlockInputOperator(const std::string& w) {
    for (std::string_view k : kBlockInputOperators)
        if (k == w) return true;
    return false;
}

// A piece of ST and the instruction it belongs to (its lines carry that instruction's place).
struct Frag {
    std::string text;
    int instr = 0;
};

struct Cr {
    std::vector<Frag> frags;
    bool defined = false;
    bool stable = false;  // a literal or a temporary
    bool temp = false;    // a temporary: its lines are those of the instruction reading it
};

class Translator {
public:
    Translator(const Surroundings& a, plcopen::Translation& o, bool nestedList = false) : around(a), out(o), nested(nestedList) {}

    bool run(std::string_view text, int line, int col) {
        read(text, line, col);
        if (failed) return false;
        link();
        if (failed) return false;
        liveness();
        write();
        return !failed;
    }

private:
    const Surroundings& around;
    plcopen::Translation& out;
    std::vector<Instr> code;
    std::vector<bool> liveIn;  // liveIn[i]: the CR before instruction i is read before it is replaced
    std::map<std::string, int> labels;  // upper-case name -> Label instruction
    std::map<int, std::string> labelTemps;  // Label instruction -> its temporary
    bool failed = false;
    int temps = 0;
    const bool nested;  // the instructions of a nested list `IN := ( LD a AND b )` in a formal call
    int nestedLists = 0;

    void fail(const Instr& in, const std::string& message) {
        if (failed) return;  // one mistake, one message: the body is left out after the first
        failed = true;
        around.fail(in.line, in.col, message);
    }

    // --- reading -----------------------------------------------------------

    void read(std::string_view raw, int firstLine, int firstCol) {
        const std::string text = withoutComments(raw);
        std::vector<std::string> lines;
        for (size_t start = 0;;) {
            size_t end = text.find('\n', start);
            std::string l = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
            if (!l.empty() && l.back() == '\r') l.pop_back();
            lines.push_back(std::move(l));
            if (end == std::string::npos) break;
            start = end + 1;
        }
        for (size_t k = 0; k < lines.size() && !failed; ++k) {
            const int fileLine = firstLine + static_cast<int>(k);
            const int colBase = k == 0 ? firstCol : 1;
            std::string& l = lines[k];
            size_t i = 0;
            auto skipBlanks = [&] { while (i < l.size() && std::isspace(static_cast<unsigned char>(l[i]))) ++i; };
            skipBlanks();
            if (i == l.size()) continue;
            // A label `name:` (not `name :=`), alone or before an instruction.
            if (identStart(l[i])) {
                size_t e = i;
                while (e < l.size() && identChar(l[e])) ++e;
                size_t c = e;
                while (c < l.size() && (l[c] == ' ' || l[c] == '\t')) ++c;
                if (c < l.size() && l[c] == ':' && (c + 1 == l.size() || l[c + 1] != '=')) {
                    Instr in;
                    in.op = Op::Label;
                    in.operand = l.substr(i, e - i);
                    in.line = fileLine;
                    in.col = colBase + static_cast<int>(i);
                    in.element = "IL label '" + in.operand + "'";
                    in.text = in.operand + ":";
                    code.push_back(in);
                    i = c + 1;
                    skipBlanks();
                    if (i == l.size()) continue;
                }
            }
            Instr in;
            in.line = fileLine;
            in.col = colBase + static_cast<int>(i);
            std::string rest = l.substr(i);
            // An instruction whose parentheses stay open (`CAL fb(` ... `)`,
            // a formal call) goes on over the next lines; a deferred `AND(` does not.
            if (!isDeferred(rest))
                while (openParens(rest) > 0 && k + 1 < lines.size()) rest += " " + trim(lines[++k]);
            in.text = trim(rest);
            in.element = "IL instruction '" + in.text.substr(0, 60) + "'";
            parseInstruction(in, trim(rest));
            code.push_back(in);
        }
    }

    // `AND(`, `ADD( 5`: an operator deferred until its `)`.
    static bool isDeferred(const std::string& rest) {
        std::string t = trim(rest);
        size_t e = 0;
        if (!t.empty() && t[0] == '&') e = (t.size() > 1 && (t[1] == 'N' || t[1] == 'n')) ? 2 : 1;
        else while (e < t.size() && identChar(t[e])) ++e;
        size_t p = e;
        while (p < t.size() && (t[p] == ' ' || t[p] == '\t')) ++p;
        return p < t.size() && t[p] == '(' && binaryOperators().count(upper(t.substr(0, e)));
    }

    void parseInstruction(Instr& in, const std::string& t) {
        if (t == ")") { in.op = Op::Close; return; }
        size_t e = 0;
        if (t[0] == '&') e = (t.size() > 1 && (t[1] == 'N' || t[1] == 'n')) ? 2 : 1;
        else if (identStart(t[0])) while (e < t.size() && identChar(t[e])) ++e;
        if (e == 0) { fail(in, "'" + t.substr(0, 40) + "' is not an IL instruction"); return; }
        in.word = upper(t.substr(0, e));
        std::string rest = trim(std::string_view(t).substr(e));
        const std::string& w = in.word;
        auto needOperand = [&]() {
            if (rest.empty()) fail(in, w + " needs an operand");
            in.operand = rest;
        };
        auto noOperand = [&]() {
            if (!rest.empty()) fail(in, w + " takes no operand, but '" + rest.substr(0, 40) + "' follows it");
        };
        if (auto b = binaryOperators().find(w); b != binaryOperators().end()) {
            in.infix = b->second.first;
            in.negated = b->second.second;
            if (!rest.empty() && rest[0] == '(') {
                in.op = Op::Open;
                in.operand = trim(std::string_view(rest).substr(1));
                return;
            }
            in.op = Op::Binary;
            needOperand();
            if (!failed && splitOperands(rest).size() > 1) fail(in, w + " takes one operand");
            return;
        }
        if (w == "LD" || w == "LDN") { in.op = Op::Load; in.negated = w == "LDN"; needOperand(); return; }
        if (w == "ST" || w == "STN") { in.op = Op::Store; in.negated = w == "STN"; needOperand(); return; }
        if (w == "NOT") { in.op = Op::Not; noOperand(); return; }
        if (w == "S" || w == "R") {
            needOperand();
            if (around.isBlockInstance && around.isBlockInstance(rest)) {
                in.op = Op::FbInput;
                in.param = w;
            } else {
                in.op = w == "S" ? Op::Set : Op::Reset;
            }
            return;
        }
        if (isBlockInputOperator(w)) { in.op = Op::FbInput; in.param = w; needOperand(); return; }
        // JMP/CAL/RET and their C (CR TRUE) and CN (CR FALSE) forms.
        static const std::pair<const char*, Op> flow[] = {{"JMP", Op::Jump}, {"CAL", Op::Call}, {"RET", Op::Return}};
        for (const auto& [base, op] : flow) {
            if (w != base && w != std::string(base) + "C" && w != std::string(base) + "CN") continue;
            in.op = op;
            in.conditional = w != base;
            in.onFalse = w.size() == std::strlen(base) + 2;
            if (op == Op::Return) noOperand();
            else needOperand();
            // `CAL fb` calls it without arguments.
            if (op == Op::Call && !failed && in.operand.find('(') == std::string::npos) in.operand += "()";
            return;
        }
        // Any other word is a function: `LIMIT 0, 100` (the CR is the first
        // argument) or `LIMIT(MN := 0, IN := x, MX := 100)` (formal, without the CR).
        if (!rest.empty() && rest[0] == '(') {
            in.op = Op::FormalFunction;
            in.operand = t.substr(0, e) + rest;
            return;
        }
        in.op = Op::Function;
        in.operand = t.substr(0, e);
        in.param = rest;  // the further operands
    }

    // Jump targets and the parentheses of the deferred operators.
    void link() {
        for (size_t i = 0; i < code.size(); ++i)
            if (code[i].op == Op::Label && !labels.emplace(upper(code[i].operand), static_cast<int>(i)).second)
                return fail(code[i], "label '" + code[i].operand + "' is defined twice");
        std::vector<int> open;
        for (size_t i = 0; i < code.size() && !failed; ++i) {
            Instr& in = code[i];
            if (in.op == Op::Open) open.push_back(static_cast<int>(i));
            if (in.op == Op::Close) {
                if (open.empty()) return fail(in, "')' closes no deferred operator such as 'AND('");
                code[open.back()].close = static_cast<int>(i);
                open.pop_back();
            }
            if (!open.empty() && (in.op == Op::Label || in.op == Op::Jump || in.op == Op::Return))
                return fail(in, "a label, jump or return inside the parentheses of '" + code[open.back()].word + "(' (line " +
                                    std::to_string(code[open.back()].line) + ")");
            if (in.op == Op::Jump) {
                auto it = labels.find(upper(in.operand));
                if (it == labels.end()) return fail(in, in.word + " to undefined label '" + in.operand + "'");
                in.target = it->second;
            }
        }
        if (!open.empty() && !failed) fail(code[open.back()], "'" + code[open.back()].word + "(' has no closing ')'");
    }

    // --- which current results are read again --------------------------------

    static bool readsCr(const Instr& in) {
        switch (in.op) {
            case Op::Load:
            case Op::FormalFunction:
            case Op::Label: return false;
            case Op::Jump:
            case Op::Call:
            case Op::Return: return in.conditional;
            default: return true;
        }
    }
    static bool replacesCr(const Instr& in) { return in.op == Op::Load || in.op == Op::FormalFunction; }

    void liveness() {
        const size_t n = code.size();
        liveIn.assign(n + 1, false);
        for (bool changed = true; changed;) {
            changed = false;
            for (size_t k = n; k-- > 0;) {
                const Instr& in = code[k];
                bool live = readsCr(in);
                if (!live && !replacesCr(in)) {
                    const bool fallsThrough = !((in.op == Op::Jump || in.op == Op::Return) && !in.conditional);
                    if (fallsThrough) live = liveIn[k + 1];
                    if (in.op == Op::Jump) live = live || liveIn[in.target];
                }
                if (live != liveIn[k]) {
                    liveIn[k] = live;
                    changed = true;
                }
            }
        }
    }

    // --- writing -------------------------------------------------------------

    Cr cr;
    struct Group {
        int open;
        Cr outer;
    };
    std::vector<Group> groups;
    bool reachable = true;

    // ST lines from pieces: a new line wherever the instruction changes.
    void emit(const std::vector<Frag>& pieces) {
        int current = -1;
        for (const Frag& f : pieces) {
            if (f.instr != current || out.body.empty()) {
                const Instr& in = code[f.instr];
                out.body.push_back({f.text, in.line, in.col, in.element, false});
                current = f.instr;
            } else {
                out.body.back().text += f.text;
            }
        }
    }

    std::string declareTemp(int at, const std::string& name) {
        const Instr& in = code[at];
        out.declarations.push_back({"    {attribute 'strun_inferred_temp'} " + name + " : BOOL;", in.line, in.col, in.element, false});
        return name;
    }

    // The CR must be set here (instruction k reads it).
    bool needCr(int k) {
        if (cr.defined) return true;
        fail(code[k], "'" + code[k].text + "' reads the current result, but no instruction before it sets one (load a value with LD first)");
        return false;
    }

    // Keeps the CR in a temporary: what it reads may change before it is read again.
    void materialize(int k) {
        if (cr.stable) return;
        const std::string t = declareTemp(k, around.prefix + "cr" + std::to_string(++temps));
        std::vector<Frag> s{{t + " := ", k}};
        for (const Frag& f : crAt(k)) s.push_back(f);
        s.push_back({";", k});
        emit(s);
        cr.frags = {{t, k}};
        cr.stable = cr.temp = true;
    }

    // The CR as instruction k reads it: a temporary is named at k's line, so
    // that a type error of its use (`ST`, a condition) is at the instruction
    // using it; an expression keeps the lines of its operators.
    // In parentheses opened on k's line: a node of k's (`ADD`: the binary
    // node, located where its left operand starts; `ST`: the assigned value)
    // is located at k's line, the operands inside keep theirs.
    std::vector<Frag> crAt(int k) const {
        std::vector<Frag> f{{"(", k}};
        if (cr.temp) f.push_back({cr.frags[0].text, k});
        else f.insert(f.end(), cr.frags.begin(), cr.frags.end());
        f.push_back({")", k});
        return f;
    }

    // Before a statement of instruction k that reads the CR `uses` times:
    // the CR survives it (read again later) or is read twice -> a temporary.
    void beforeStatement(int k, int uses) {
        if (cr.defined && !cr.stable && (liveIn[k + 1] || uses > 1)) materialize(k);
    }

    std::vector<Frag> condition(int k) {
        const Instr& in = code[k];
        std::vector<Frag> s{{in.onFalse ? "IF NOT (" : "IF (", k}};
        for (const Frag& f : crAt(k)) s.push_back(f);
        s.push_back({") THEN ", k});
        return s;
    }

    // The label's temporary, declared at its first use.
    std::string labelTemp(int label) {
        auto it = labelTemps.find(label);
        if (it != labelTemps.end()) return it->second;
        return labelTemps[label] = declareTemp(label, around.prefix + "L_" + code[label].operand);
    }

    void assignLabel(int k, int label, std::vector<Frag>& s) {
        const std::string t = labelTemp(label);
        if (cr.frags.size() == 1 && cr.frags[0].text == t) return;
        s.push_back({t + " := ", k});
        for (const Frag& f : crAt(k)) s.push_back(f);
        s.push_back({"; ", k});
    }

    static bool emitsStatement(const Instr& in) {
        return in.op == Op::Store || in.op == Op::Set || in.op == Op::Reset || in.op == Op::FbInput || in.op == Op::Call;
    }

    void write() {
        for (int k = 0; k < static_cast<int>(code.size()) && !failed; ++k) writeOne(k);
        if (failed && !nested) {
            out.body.clear();
            out.declarations.clear();
        }
    }

    // The current result at the end of the instructions, as one ST expression.
    std::string finalValue() const {
        std::string v;
        for (const Frag& f : cr.frags) v += f.text;
        return v;
    }

    // The `(` of a nested instruction list when `:= ( LD ...` starts at i, else npos.
    static size_t nestedListAt(const std::string& operand, size_t i) {
        for (; i + 1 < operand.size(); ++i) {
            if (operand.compare(i, 2, ":=") != 0) continue;
            size_t open = i + 2;
            while (open < operand.size() && operand[open] == ' ') ++open;
            if (open >= operand.size() || operand[open] != '(') continue;
            size_t w = open + 1;
            while (w < operand.size() && operand[w] == ' ') ++w;
            size_t we = w;
            while (we < operand.size() && identChar(operand[we])) ++we;
            if (we > w && isOperator(upper(operand.substr(w, we - w)))) return open;  // `IN := (a + b)` is ST
        }
        return std::string::npos;
    }

    // `CAL fb(IN := ( LD a AND b ), PT := T#1s)`: each argument that is a
    // nested instruction list (IEC 61131-3 2nd edition 3.2.3, il_param_assignment)
    // is translated where the call is: its statements (an ST inside it) come
    // before the call, and its current result at `)` is the argument.
    bool expandNestedLists(int k, std::string& operand) {
        for (size_t i = 0; i + 1 < operand.size(); ++i) {
            if (operand[i] == '\'' || operand[i] == '"') {
                const char q = operand[i];
                for (++i; i < operand.size() && operand[i] != q; ++i)
                    if (operand[i] == '$') ++i;
                continue;
            }
            const size_t open = nestedListAt(operand, i);
            if (open == std::string::npos) continue;
            int depth = 0;
            size_t close = open;
            for (; close < operand.size(); ++close) {
                if (operand[close] == '(') ++depth;
                if (operand[close] == ')' && --depth == 0) break;
            }
            if (close >= operand.size()) return fail(code[k], "the nested instruction list after ':=' has no closing ')'"), false;
            Surroundings inner = around;
            inner.prefix = around.prefix + "n" + std::to_string(++nestedLists) + "_";
            Translator sub(inner, out, true);
            if (!sub.run(oneInstructionPerLine(operand.substr(open + 1, close - open - 1)), code[k].line, code[k].col)) {
                failed = true;
                return false;
            }
            if (!sub.cr.defined) return fail(code[k], "the nested instruction list after ':=' leaves no current result"), false;
            const std::string value = "(" + sub.finalValue() + ")";
            operand.replace(open, close - open + 1, value);
            i = open + value.size() - 1;
        }
        return true;
    }

    // `LD a AND b` written on one line (the nested list of a call is read as
    // one line): a line per instruction, a new one at each operator word
    // that does not stand where the previous operator's operand goes.
    static std::string oneInstructionPerLine(const std::string& s) {
        std::string out;
        bool wantsOperand = false;
        int depth = 0;
        for (size_t i = 0; i < s.size();) {
            if (std::isspace(static_cast<unsigned char>(s[i]))) {
                out += ' ';
                ++i;
                continue;
            }
            size_t e = i;
            if (identStart(s[i]) && depth == 0) {
                while (e < s.size() && identChar(s[e])) ++e;
                const std::string w = upper(s.substr(i, e - i));
                if (!wantsOperand && isOperator(w)) {
                    if (!trim(out).empty()) out += '\n';
                    out += s.substr(i, e - i);
                    wantsOperand = w != "NOT" && w.rfind("RET", 0) != 0;
                    i = e;
                    continue;
                }
            }
            // an operand: up to the next blank outside parentheses and strings
            while (e < s.size() && (depth > 0 || !std::isspace(static_cast<unsigned char>(s[e])))) {
                if (s[e] == '(') ++depth;
                if (s[e] == ')') --depth;
                if (s[e] == '\'' || s[e] == '"') {
                    const char q = s[e];
                    for (++e; e < s.size() && s[e] != q; ++e)
                        if (s[e] == '$') ++e;
                }
                ++e;
            }
            out += s.substr(i, e - i);
            wantsOperand = false;
            i = e;
        }
        return out;
    }

    void writeOne(int k) {
        const Instr& in = code[k];
        switch (in.op) {
            case Op::Label: {
                std::vector<Frag> s;
                if (liveIn[k]) {
                    if (reachable) {
                        if (!cr.defined)
                            return fail(in, "label '" + in.operand +
                                                "' is reached from the line before it without a current result, but its instructions read one");
                        assignLabel(k, k, s);
                    }
                    cr = {{{labelTemp(k), k}}, true, true, true};
                } else {
                    cr = {};
                }
                s.push_back({in.operand + ":", k});
                emit(s);
                reachable = true;
                return;
            }
            case Op::Load:
                cr.frags = {{in.negated ? "NOT (" + in.operand + ")" : "(" + in.operand + ")", k}};
                if (!in.negated && isLiteral(in.operand)) cr.frags[0].text = in.operand;
                cr.defined = true;
                cr.stable = isLiteral(in.operand);
                cr.temp = false;
                return;
            case Op::Store:
            case Op::Set:
            case Op::Reset:
            case Op::FbInput: {
                if (!needCr(k)) return;
                beforeStatement(k, 1);
                std::vector<Frag> s;
                if (in.op == Op::Store) {
                    s.push_back({in.operand + " := " + (in.negated ? "NOT (" : ""), k});
                    for (const Frag& f : crAt(k)) s.push_back(f);
                    s.push_back({in.negated ? ");" : ";", k});
                } else if (in.op == Op::FbInput) {
                    s.push_back({in.operand + "(" + in.param + " := ", k});
                    for (const Frag& f : crAt(k)) s.push_back(f);
                    s.push_back({");", k});
                } else {
                    s.push_back({"IF ", k});
                    for (const Frag& f : crAt(k)) s.push_back(f);
                    s.push_back({" THEN " + in.operand + (in.op == Op::Set ? " := TRUE" : " := FALSE") + "; END_IF;", k});
                }
                emit(s);
                return;
            }
            case Op::Binary: {
                if (!needCr(k)) return;
                std::vector<Frag> f{{"(", k}};
                for (const Frag& p : crAt(k)) f.push_back(p);
                f.push_back({" " + in.infix + " " + (in.negated ? "NOT (" + in.operand + "))" : "(" + in.operand + "))"), k});
                cr.frags = std::move(f);
                cr.stable = cr.temp = false;
                return;
            }
            case Op::Not: {
                if (!needCr(k)) return;
                std::vector<Frag> f{{"NOT (", k}};
                for (const Frag& p : crAt(k)) f.push_back(p);
                f.push_back({")", k});
                cr.frags = std::move(f);
                cr.stable = cr.temp = false;
                return;
            }
            case Op::Jump: {
                const bool toLive = liveIn[in.target];
                if (!in.conditional && toLive && !cr.defined)
                    return fail(in, "the instructions after label '" + code[in.target].operand + "' read the current result, but '" + in.text +
                                        "' jumps there without one (load a value with LD first)");
                if (in.conditional && !needCr(k)) return;
                std::vector<Frag> s;
                if (in.conditional) {
                    beforeStatement(k, toLive ? 2 : 1);
                    s = condition(k);
                }
                if (toLive) assignLabel(k, in.target, s);
                s.push_back({"JMP " + in.operand + ";", k});
                if (in.conditional) s.push_back({" END_IF;", k});
                emit(s);
                if (!in.conditional) {
                    reachable = false;
                    cr = {};
                }
                return;
            }
            case Op::Call:
            case Op::Return: {
                if (in.conditional && !needCr(k)) return;
                beforeStatement(k, in.conditional ? 1 : 0);
                std::string operand = in.operand;
                // A nested list's statements run before the call (and its condition): the CR read after them must not change under them.
                if (in.op == Op::Call && cr.defined && (in.conditional || liveIn[k + 1]) && nestedListAt(operand, 0) != std::string::npos)
                    materialize(k);
                if (in.op == Op::Call && !expandNestedLists(k, operand)) return;
                std::vector<Frag> s;
                if (in.conditional) s = condition(k);
                s.push_back({in.op == Op::Call ? operand + ";" : std::string("RETURN;"), k});
                if (in.conditional) s.push_back({" END_IF;", k});
                emit(s);
                if (in.op == Op::Return && !in.conditional) {
                    reachable = false;
                    cr = {};
                }
                return;
            }
            case Op::Open: {
                if (!needCr(k)) return;
                // Statements inside the parentheses run before the outer CR is combined: it must not change under them.
                for (int j = k + 1; j < in.close; ++j)
                    if (emitsStatement(code[j])) {
                        materialize(k);
                        break;
                    }
                groups.push_back({k, cr});
                cr = {};
                if (!in.operand.empty()) cr = {{{isLiteral(in.operand) ? in.operand : "(" + in.operand + ")", k}}, true, isLiteral(in.operand)};
                return;
            }
            case Op::Close: {
                if (!needCr(k)) return;
                Group g = groups.back();
                groups.pop_back();
                const Instr& open = code[g.open];
                std::vector<Frag> f{{"(", g.open}, {"(", g.open}};  // located at the `AND(` line
                if (g.outer.temp) f.push_back({g.outer.frags[0].text, g.open});
                else f.insert(f.end(), g.outer.frags.begin(), g.outer.frags.end());
                f.push_back({") " + open.infix + (open.negated ? " NOT (" : " ("), k});
                for (const Frag& p : crAt(k)) f.push_back(p);
                f.push_back({"))", k});
                cr = {std::move(f), true, false};
                return;
            }
            case Op::Function: {
                if (!needCr(k)) return;
                std::vector<Frag> f{{in.operand + "(", k}};
                for (const Frag& p : crAt(k)) f.push_back(p);
                std::string args;
                if (!in.param.empty())
                    for (const std::string& a : splitOperands(in.param)) args += ", " + a;
                f.push_back({args + ")", k});
                cr = {std::move(f), true, false};
                return;
            }
            case Op::FormalFunction: {
                std::string operand = in.operand;
                if (!expandNestedLists(k, operand)) return;
                cr = {{{operand, k}}, true, false};
                return;
            }
        }
    }
};

}  // namespace

bool isOperator(const std::string& w) {
    if (w.size() > kLongestOperator) return false;  // none is longer: mayHoldTextualIl relies on it
    // Every operator word once, collected from the lists the translator
    // uses: mayHoldTextualIl asks after every END_VAR of every ST file.
    static const std::vector<std::string_view> all = [] {
        std::vector<std::string_view> words = {"LD",   "LDN",   "ST",  "STN", "S",     "R",   "NOT",  "JMP",
                                               "JMPC", "JMPCN", "CAL", "CALC", "CALCN", "RET", "RETC", "RETCN"};
        for (const auto& op : binaryOperators()) words.emplace_back(op.first);
        for (std::string_view k : kBlockInputOperators) words.push_back(k);
        return words;
    }();
    for (std::string_view k : all)
        if (k == w) return true;
    return false;
}

bool translate(std::string_view text, int line, int col, const Surroundings& around, plcopen::Translation& out) {
    Translator t(around, out);
    return t.run(text, line, col);
}

}  // namespace strun::source::il
