// Textual SFC in ST files (IEC 61131-3 3rd edition 6.7.5 / 2nd edition
// 2.6.6): INITIAL_STEP, STEP ... END_STEP with action associations,
// TRANSITION [name] [(PRIORITY := n)] FROM steps TO steps := condition;
// END_TRANSITION (or `: statements END_TRANSITION` assigning the name), and
// the POU's ACTIONs. A POU holding an INITIAL_STEP has its SFC elements
// replaced by the same ST an SFC chart from PLCopen XML becomes
// (sfc_chart.cpp); the rest of the file is kept, and every line knows where
// it came from, as for XML files. This is a reading stage of its own, like
// the XML readers, so the LL(1) ST grammar (decisions 0157-0159) is not
// changed (decision 0233).
#include "interpreter/source/st_textual_sfc.h"

#include <array>
#include <cctype>
#include <cstring>
#include <map>
#include <set>

#include "interpreter/source/sfc_chart.h"
#include "interpreter/source/st_splice.h"
#include "interpreter/source/st_tokens.h"
#include "stdlib/number_scan.h"

namespace strun::source {

namespace {

using Token = StToken;

struct Reader {
    const std::string& src;
    std::vector<Token> toks;
    Converted result;
    std::vector<std::pair<size_t, size_t>> blanked;  // SFC spans, replaced by blanks
    struct Insert {
        size_t at;
        plcopen::Translation tr;
    };
    std::vector<Insert> inserts;
    int charts = 0;

    explicit Reader(const std::string& s) : src(s), toks(tokenizeSt(s)) {}

    bool failed = false;
    std::string pou;
    void fail(const Token& t, const std::string& what) {
        result.errors.push_back({t.line, t.col, "in the SFC chart of '" + pou + "': " + what});
        failed = true;
    }

    const Token& at(size_t k) const {
        static const Token end;
        return k < toks.size() ? toks[k] : end;
    }
    bool isSfcStart(size_t k) const {
        const std::string& u = at(k).up;
        return (u == "INITIAL_STEP" || u == "STEP" || u == "TRANSITION") && (u == "TRANSITION" || (at(k + 1).word && at(k + 2).text == ":"));
    }

    // One POU from token `b` (its keyword) to `e` (its END_ keyword).
    void pouRange(size_t b, size_t e) {
        bool hasInitial = false;
        for (size_t k = b; k < e; ++k)
            if (at(k).up == "INITIAL_STEP" && at(k + 1).word) hasInitial = true;
        if (!hasInitial) return;
        pou = at(b + 1).text;
        failed = false;
        SfcChart chart;
        std::map<std::string, int> steps;
        std::set<std::string> actions;
        size_t first = std::string::npos;
        for (size_t k = b; k < e; ++k)
            if (at(k).up == "ACTION" && at(k + 1).word) actions.insert(at(k + 1).up);
        struct PendingTransition {
            size_t k;
            std::vector<size_t> from, to;  // token indices of the step names
        };
        std::vector<PendingTransition> pending;
        std::vector<std::pair<std::string, SfcChart::Association>> uses;
        std::set<std::string> declaredNames;
        plcopen::Translation tr;
        for (size_t k = b; k < e && !failed; ++k) {
            if (at(k).up == "ACTION" && at(k + 1).word) {  // the POU's actions stay; skip to their end
                if (first == std::string::npos) first = at(k).begin;
                while (k < e && at(k).up != "END_ACTION") ++k;
                continue;
            }
            if (!isSfcStart(k)) continue;
            if (first == std::string::npos) first = at(k).begin;
            const size_t start = k;
            if (at(k).up == "INITIAL_STEP" || at(k).up == "STEP") {
                const Token& name = at(k + 1);
                if (steps.count(name.up)) { fail(name, "two steps are named '" + name.text + "'"); break; }
                steps[name.up] = static_cast<int>(chart.steps.size());
                chart.steps.push_back({name.text, at(k).up == "INITIAL_STEP", {name.line, name.col}});
                k += 3;
                while (k < e && at(k).up != "END_STEP") {
                    // action_name [( qualifier [, duration] )] ;
                    const Token& a = at(k);
                    if (!a.word) { fail(a, "expected an action association (name(qualifier)) or END_STEP, found '" + a.text + "'"); break; }
                    SfcChart::Association as;
                    as.step = steps[name.up];
                    ++k;
                    if (at(k).text == "(") {
                        ++k;
                        if (at(k).word) as.qualifier = at(k++).up;
                        if (at(k).text == ",") { as.duration = at(k + 1).text; k += 2; }
                        while (at(k).text == ",") k += 2;  // indicator variables: shown by IDEs, not run
                        if (at(k).text != ")") { fail(at(k), "expected ')' after the action qualifier"); break; }
                        ++k;
                    }
                    if (at(k).text == ";") ++k;
                    static const std::set<std::string> known = {"N", "R", "S", "L", "D", "P", "P1", "P0", "SD", "DS", "SL"};
                    if (!known.count(as.qualifier)) { fail(a, "action qualifier '" + as.qualifier + "' of step '" + name.text + "' is not one of N R S L D P P1 P0 SD DS SL"); break; }
                    const bool timed = as.qualifier == "L" || as.qualifier == "D" || as.qualifier == "SD" || as.qualifier == "DS" || as.qualifier == "SL";
                    if (timed && as.duration.empty()) { fail(a, "action qualifier " + as.qualifier + " of step '" + name.text + "' needs a duration"); break; }
                    uses.push_back({a.text, as});
                }
                if (at(k).up != "END_STEP") { if (!failed) fail(at(start), "STEP without END_STEP"); break; }
            } else {  // TRANSITION
                SfcChart::Transition t;
                const Token& kw = at(k);
                ++k;
                std::string name;
                if (at(k).word && at(k).up != "FROM") name = at(k++).text;
                if (at(k).text == "(" && at(k + 1).up == "PRIORITY") {
                    t.priority = std::atoi(at(k + 3).text.c_str());
                    k += 5;
                }
                auto stepList = [&](std::vector<size_t>& into) {
                    if (at(k).text == "(") {
                        ++k;
                        while (at(k).word) {
                            into.push_back(k);
                            ++k;
                            if (at(k).text == ",") ++k;
                        }
                        if (at(k).text == ")") ++k;
                    } else if (at(k).word) {
                        into.push_back(k++);
                    }
                };
                PendingTransition p{k, {}, {}};
                if (at(k).up != "FROM") { fail(at(k), "expected FROM after TRANSITION"); break; }
                ++k;
                p.k = k;
                stepList(p.from);
                if (at(k).up != "TO") { fail(at(k), "expected TO and the following steps"); break; }
                ++k;
                stepList(p.to);
                t.label = "transition " + (name.empty() ? "from " + at(p.k).text : "'" + name + "'");
                t.at = {kw.line, kw.col};
                t.id = std::to_string(chart.transitions.size());
                t.x = static_cast<double>(chart.transitions.size());  // written order among alternatives
                if (at(k).text == ":=") {
                    ++k;
                    const size_t cb = k;
                    while (k < e && at(k).text != ";" && at(k).up != "END_TRANSITION") ++k;
                    if (k == cb) { fail(at(k), "expected the transition's condition after ':='"); break; }
                    t.condition.push_back({src.substr(at(cb).begin, at(k - 1).end - at(cb).begin), at(cb).line, at(cb).col, t.label, true});
                    if (at(k).text == ";") ++k;
                } else if (at(k).text == ":") {
                    if (name.empty()) { fail(kw, "a transition with a body needs a name (the body assigns it)"); break; }
                    ++k;
                    const size_t cb = k;
                    while (k < e && at(k).up != "END_TRANSITION") ++k;
                    if (k > cb) t.before.push_back({src.substr(at(cb).begin, at(k - 1).end - at(cb).begin), at(cb).line, at(cb).col, t.label, true});
                    t.expr = name;
                    if (!declaredNames.count(stdlib::upperAscii(name))) {
                        tr.declarations.push_back({"    " + std::string(plcopen::kHiddenPragma) + name + " : BOOL;", kw.line, kw.col, t.label, false});
                        declaredNames.insert(stdlib::upperAscii(name));
                    }
                } else {
                    fail(at(k), "expected ':=' and the condition, or ':' and a body");
                    break;
                }
                if (at(k).up != "END_TRANSITION") { fail(at(k), "expected END_TRANSITION"); break; }
                chart.transitions.push_back(std::move(t));
                pending.push_back(p);
            }
            blanked.push_back({at(start).begin, at(k).end});
        }
        if (failed) return;
        // Steps named by transitions and associations.
        for (size_t t = 0; t < pending.size(); ++t) {
            for (int side = 0; side < 2; ++side)
                for (size_t s : side ? pending[t].to : pending[t].from) {
                    auto it = steps.find(at(s).up);
                    if (it == steps.end()) {
                        fail(at(s), chart.transitions[t].label + " names step '" + at(s).text + "', which the chart does not have");
                        continue;
                    }
                    (side ? chart.transitions[t].post : chart.transitions[t].pre).push_back(it->second);
                }
        }
        std::map<std::string, int> byName;
        for (auto& [name, as] : uses) {
            auto [it, added] = byName.emplace(stdlib::upperAscii(name), static_cast<int>(chart.actions.size()));
            if (added) {
                SfcChart::Action a;
                a.name = name;
                a.isVariable = !actions.count(stdlib::upperAscii(name));
                a.label = "action '" + name + "'";
                a.at = chart.steps[static_cast<size_t>(as.step)].at;
                chart.actions.push_back(a);
            }
            chart.actions[static_cast<size_t>(it->second)].uses.push_back(as);
        }
        if (failed) return;
        // CODESYS' SFC flags, when the POU declares them (`SFCInit : BOOL;`, `SFCInit, x : BOOL;`).
        for (size_t k = b; k + 1 < e; ++k) {
            if (at(k + 1).text != ":" && at(k + 1).text != ",") continue;
            chart.sfcInit = chart.sfcInit || at(k).up == "SFCINIT";
            chart.sfcReset = chart.sfcReset || at(k).up == "SFCRESET";
            chart.sfcPause = chart.sfcPause || at(k).up == "SFCPAUSE";
        }
        const std::string prefix = "_g" + std::to_string(++charts) + "_";
        if (!writeSfcChart(chart, prefix, tr, [&](SfcChart::Where w, const std::string& what) {
                result.errors.push_back({w.line, w.col, "in the SFC chart of '" + pou + "': " + what});
            }))
            return;
        inserts.push_back({first, std::move(tr)});
    }

    void run() {
        size_t b = std::string::npos;
        for (size_t k = 0; k < toks.size(); ++k) {
            const std::string& u = toks[k].up;
            if ((u == "PROGRAM" || u == "FUNCTION_BLOCK" || u == "FUNCTION") && b == std::string::npos) b = k;
            else if ((u == "END_PROGRAM" || u == "END_FUNCTION_BLOCK" || u == "END_FUNCTION") && b != std::string::npos) {
                pouRange(b, k);
                b = std::string::npos;
            }
        }
        if (!result.errors.empty()) return;
        if (inserts.empty()) {  // INITIAL_STEP only in a comment or a string: plain ST, no origins
            result.text = src;
            return;
        }
        // The text with the SFC elements blanked and each chart's ST inserted where its POU's body starts.
        std::vector<StSplice> splices;
        for (Insert& ins : inserts) splices.push_back({ins.at, std::move(ins.tr.declarations), std::move(ins.tr.body)});
        spliceSt(src, blanked, std::move(splices), result);
    }
};

}  // namespace

bool mayHoldTextualSfc(const std::string& text) {
    // Case-insensitive Boyer-Moore-Horspool for INITIAL_STEP: most bytes of
    // ST let it skip several bytes, so plain ST pays well under one
    // instruction per byte (it runs on every ST file).
    static constexpr char kWord[] = "INITIAL_STEP";
    static constexpr size_t kLen = sizeof(kWord) - 1;
    static const auto tables = [] {
        std::pair<std::array<unsigned char, 256>, std::array<unsigned char, 256>> t;  // skip, folded
        for (int c = 0; c < 256; ++c) {
            t.first[static_cast<size_t>(c)] = kLen;
            t.second[static_cast<size_t>(c)] = static_cast<unsigned char>(std::toupper(c));
        }
        for (size_t k = 0; k + 1 < kLen; ++k) {
            const auto u = static_cast<unsigned char>(kWord[k]);
            t.first[u] = t.first[static_cast<unsigned char>(std::tolower(u))] = static_cast<unsigned char>(kLen - 1 - k);
        }
        return t;
    }();
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    for (size_t at = 0; at + kLen <= text.size(); at += tables.first[bytes[at + kLen - 1]]) {
        size_t k = kLen;
        while (k > 0 && tables.second[bytes[at + k - 1]] == static_cast<unsigned char>(kWord[k - 1])) --k;
        if (k == 0) return true;
    }
    return false;
}

Converted convertTextualSfc(const std::string& text) {
    Reader r(text);
    r.run();
    return std::move(r.result);
}

}  // namespace strun::source
