#include "interpreter/source/beremiz_standard_blocks.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <string_view>
#include <vector>

namespace strun::source {

namespace {

// IEC 61131-3 (2nd ed.) blocks as matiec implements them. matiec's
// TIME_TO_REAL counts seconds, strun's (as CODESYS') milliseconds: the
// sampling period is converted here, so the formulas give matiec's values.
struct Block {
    const char* name;
    std::vector<const char*> uses;
    const char* text;
};

const std::vector<Block>& blocks() {
    static const std::vector<Block> all = {
        {"INTEGRAL", {},
         "FUNCTION_BLOCK INTEGRAL\n"
         "VAR_INPUT RUN : BOOL; R1 : BOOL; XIN : REAL; X0 : REAL; CYCLE : TIME; END_VAR\n"
         "VAR_OUTPUT Q : BOOL; XOUT : REAL; END_VAR\n"
         "Q := NOT R1;\n"
         "IF R1 THEN\n"
         "    XOUT := X0;\n"
         "ELSIF RUN THEN\n"
         "    XOUT := XOUT + XIN * (TIME_TO_REAL(CYCLE) / 1000.0);\n"
         "END_IF;\n"
         "END_FUNCTION_BLOCK\n"},
        {"DERIVATIVE", {},
         "FUNCTION_BLOCK DERIVATIVE\n"
         "VAR_INPUT RUN : BOOL; XIN : REAL; CYCLE : TIME; END_VAR\n"
         "VAR_OUTPUT XOUT : REAL; END_VAR\n"
         "VAR X1, X2, X3 : REAL; END_VAR\n"
         "IF RUN THEN\n"
         "    XOUT := (3.0 * (XIN - X3) + X1 - X2) / (10.0 * (TIME_TO_REAL(CYCLE) / 1000.0));\n"
         "    X3 := X2;\n"
         "    X2 := X1;\n"
         "    X1 := XIN;\n"
         "ELSE\n"
         "    XOUT := 0.0;\n"
         "    X1 := XIN;\n"
         "    X2 := XIN;\n"
         "    X3 := XIN;\n"
         "END_IF;\n"
         "END_FUNCTION_BLOCK\n"},
        {"PID", {"INTEGRAL", "DERIVATIVE"},
         "FUNCTION_BLOCK PID\n"
         "VAR_INPUT AUTO : BOOL; PV : REAL; SP : REAL; X0 : REAL; KP : REAL; TR : REAL; TD : REAL; CYCLE : TIME; END_VAR\n"
         "VAR_OUTPUT XOUT : REAL; END_VAR\n"
         "VAR ERROR : REAL; ITERM : INTEGRAL; DTERM : DERIVATIVE; END_VAR\n"
         "ERROR := PV - SP;\n"
         "(* in manual (AUTO FALSE) the integral term is set so that XOUT is X0 *)\n"
         "ITERM(RUN := AUTO, R1 := NOT AUTO, XIN := ERROR, X0 := TR * (X0 - ERROR), CYCLE := CYCLE);\n"
         "DTERM(RUN := AUTO, XIN := ERROR, CYCLE := CYCLE);\n"
         "XOUT := KP * (ERROR + ITERM.XOUT / TR + DTERM.XOUT * TD);\n"
         "END_FUNCTION_BLOCK\n"},
        {"RAMP", {},
         "FUNCTION_BLOCK RAMP\n"
         "VAR_INPUT RUN : BOOL; X0 : REAL; X1 : REAL; TR : TIME; CYCLE : TIME; END_VAR\n"
         "VAR_OUTPUT BUSY : BOOL; XOUT : REAL; END_VAR\n"
         "VAR XI : REAL; T : TIME; END_VAR\n"
         "BUSY := RUN;\n"
         "IF RUN THEN\n"
         "    IF T >= TR THEN\n"
         "        BUSY := FALSE;\n"
         "        XOUT := X1;\n"
         "    ELSE\n"
         "        XOUT := XI + (X1 - XI) * TIME_TO_REAL(T) / TIME_TO_REAL(TR);\n"
         "        T := T + CYCLE;\n"
         "    END_IF;\n"
         "ELSE\n"
         "    XOUT := X0;\n"
         "    XI := X0;\n"
         "    T := T#0s;\n"
         "END_IF;\n"
         "END_FUNCTION_BLOCK\n"},
        {"HYSTERESIS", {},
         "FUNCTION_BLOCK HYSTERESIS\n"
         "VAR_INPUT XIN1 : REAL; XIN2 : REAL; EPS : REAL; END_VAR\n"
         "VAR_OUTPUT Q : BOOL; END_VAR\n"
         "IF Q THEN\n"
         "    IF XIN1 < XIN2 - EPS THEN Q := FALSE; END_IF;\n"
         "ELSIF XIN1 > XIN2 + EPS THEN\n"
         "    Q := TRUE;\n"
         "END_IF;\n"
         "END_FUNCTION_BLOCK\n"},
    };
    return all;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// `<element name="X"` (or with ') occurs in `xml` (lower case), X in lower case.
bool hasNamed(const std::string& xml, const std::string& element, const std::string& name) {
    for (const char quote : {'"', '\''}) {
        const std::string tag = "<" + element;
        const std::string attr = std::string("name=") + quote + name + quote;
        for (size_t at = xml.find(tag); at != std::string::npos; at = xml.find(tag, at + 1)) {
            const size_t end = std::min(xml.find('>', at), xml.size());
            const size_t found = std::string_view(xml).substr(at, end - at).find(attr);
            if (found != std::string_view::npos && std::isspace(static_cast<unsigned char>(xml[at + found - 1]))) return true;
        }
    }
    return false;
}

}  // namespace

std::string beremizStandardBlocks(const std::string& plcXml) {
    const std::string xml = lower(plcXml);
    std::set<std::string> wanted;
    std::vector<std::string> pending;
    for (const Block& b : blocks())
        if (hasNamed(xml, "derived", lower(b.name))) pending.push_back(b.name);
    while (!pending.empty()) {
        const std::string name = pending.back();
        pending.pop_back();
        // The project's own block of that name is the one it uses.
        if (wanted.count(name) || hasNamed(xml, "pou", lower(name))) continue;
        wanted.insert(name);
        for (const Block& b : blocks())
            if (b.name == name)
                for (const char* used : b.uses) pending.push_back(used);
    }
    std::string text;
    for (const Block& b : blocks())
        if (wanted.count(b.name)) text += std::string(b.text) + "\n";
    return text;
}

}  // namespace strun::source
