// SFC charts of PLCopen TC6 XML: read into an SfcChart (steps, transitions
// with their preceding and following steps through divergences,
// convergences and jumps, actions with their qualifiers), which
// sfc_chart.cpp checks and writes as ST (docs/graphical.md, decision 0232).
#include <algorithm>
#include <cctype>
#include <functional>
#include <map>
#include <set>

#include "interpreter/source/plcopen_graphical.h"
#include "interpreter/source/plcopen_xml.h"
#include "interpreter/source/sfc_chart.h"

namespace strun::source::plcopen {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

struct Chart {
    XmlConversion& conv;
    PouContext& ctx;
    Translation& out;
    std::string prefix;
    bool failed = false;

    std::map<int, pugi::xml_node> byId;
    std::map<int, std::vector<pugi::xml_node>> readers;  // localId -> elements connected to its output
    std::vector<pugi::xml_node> steps, transitions;
    std::map<std::string, int> stepByName;  // upper -> index
    std::map<int, int> stepIndex;           // localId -> index
    SfcChart model;

    Chart(XmlConversion& c, PouContext& x, Translation& o) : conv(c), ctx(x), out(o) { prefix = "_g" + std::to_string(++ctx.bodies) + "_"; }

    // LD/FBD elements an SFC body may hold for its transition conditions.
    static const std::set<std::string>& networkElements() {
        static const std::set<std::string> k = {"inVariable", "outVariable", "inOutVariable", "block", "connector", "continuation",
                                                "contact", "coil", "leftPowerRail", "rightPowerRail", "error"};
        return k;
    }
    std::vector<ChartCondition> drawnConditions;

    void fail(const pugi::xml_node& n, const std::string& what) {
        conv.error(n, "in the SFC chart of '" + ctx.pouName + "': " + what);
        failed = true;
    }

    std::string stepName(int s) const { return steps[static_cast<size_t>(s)].attribute("name").value(); }
    std::string stepLabel(int s) const { return "step '" + stepName(s) + "'"; }
    std::string transitionLabel(const pugi::xml_node& t) const {
        std::string name = t.attribute("name").value();
        pugi::xml_node ref = child(child(t, "condition"), "reference");
        if (name.empty() && ref) name = ref.attribute("name").value();
        return "transition " + std::string(t.attribute("localId").value()) + (name.empty() ? "" : " '" + name + "'");
    }

    SfcChart::Where at(const pugi::xml_node& n) const {
        auto [l, c] = conv.where(n);
        return {l, c};
    }
    void declare(const pugi::xml_node& n, const std::string& text, const std::string& element) {
        auto [l, c] = conv.where(n);
        out.declarations.push_back({"    " + std::string(kHiddenPragma) + text, l, c, element, false});
    }

    static std::vector<int> inputRefs(const pugi::xml_node& n) {
        std::vector<int> refs;
        for (pugi::xml_node in : children(n, "connectionPointIn"))
            for (pugi::xml_node c : children(in, "connection")) refs.push_back(c.attribute("refLocalId").as_int());
        return refs;
    }

    void read(const pugi::xml_node& lang) {
        for (pugi::xml_node n : lang.children()) {
            if (n.type() != pugi::node_element) continue;
            const std::string k = localName(n);
            if (k == "comment" || k == "documentation" || k == "addData") continue;
            const int id = n.attribute("localId").as_int();
            if (byId.count(id)) {
                fail(n, "two elements have localId " + std::to_string(id));
                continue;
            }
            byId[id] = n;
            if (k == "step") {
                std::string name = n.attribute("name").value();
                if (name.empty() || stepByName.count(upper(name))) {
                    fail(n, name.empty() ? "a step has no name" : "two steps are named '" + name + "'");
                    continue;
                }
                stepByName[upper(name)] = static_cast<int>(steps.size());
                stepIndex[id] = static_cast<int>(steps.size());
                steps.push_back(n);
            } else if (k == "transition") {
                transitions.push_back(n);
            } else if (k == "macroStep") {
                fail(n, "macro step " + std::to_string(id) + " is not supported (docs/graphical.md)");
            } else if (k != "selectionDivergence" && k != "selectionConvergence" && k != "simultaneousDivergence" &&
                       k != "simultaneousConvergence" && k != "jumpStep" && k != "actionBlock" && !networkElements().count(k)) {
                fail(n, "the " + k + " element " + std::to_string(id) + " is not supported in SFC bodies (docs/graphical.md)");
            }
        }
        for (auto& [id, n] : byId)
            for (int r : inputRefs(n)) readers[r].push_back(n);
    }

    // The steps that must be active for transition input `ref` (through
    // selection divergences and simultaneous convergences).
    void stepsBefore(int ref, const pugi::xml_node& t, std::vector<int>& into, int depth) {
        auto it = byId.find(ref);
        if (it == byId.end() || depth > 1000) {
            fail(t, transitionLabel(t) + " is connected to element " + std::to_string(ref) + ", which the chart does not have");
            return;
        }
        const std::string k = localName(it->second);
        if (k == "step") {
            into.push_back(stepIndex[ref]);
        } else if (k == "selectionDivergence" || k == "simultaneousConvergence") {
            for (int r : inputRefs(it->second)) stepsBefore(r, t, into, depth + 1);
        } else {
            fail(t, transitionLabel(t) + " follows a " + k + "; a transition follows a step, a selection divergence or a simultaneous convergence");
        }
    }

    // The steps transition (or divergence) `id` activates.
    void stepsAfter(int id, const pugi::xml_node& t, std::vector<int>& into, int depth) {
        if (depth > 1000) return;
        for (const pugi::xml_node& r : readers[id]) {
            const std::string k = localName(r);
            if (k == "step") {
                into.push_back(stepIndex[r.attribute("localId").as_int()]);
            } else if (k == "selectionConvergence" || k == "simultaneousDivergence") {
                stepsAfter(r.attribute("localId").as_int(), t, into, depth + 1);
            } else if (k == "jumpStep") {
                auto s = stepByName.find(upper(r.attribute("targetName").value()));
                if (s == stepByName.end()) fail(r, "jump to step '" + std::string(r.attribute("targetName").value()) + "', which the chart does not have");
                else into.push_back(s->second);
            } else if (k != "actionBlock") {
                fail(t, transitionLabel(t) + " leads to a " + k + "; it must lead to a step, a jump, a selection convergence or a simultaneous divergence");
            }
        }
    }

    void readActions() {
        std::map<std::string, int> byName;
        for (auto& [id, n] : byId) {
            if (localName(n) != "actionBlock") continue;
            std::vector<int> refs = inputRefs(n);
            if (refs.size() != 1 || !stepIndex.count(refs[0])) {
                fail(n, "action block " + std::to_string(id) + " is not connected to a step");
                continue;
            }
            for (pugi::xml_node a : children(n, "action")) {
                SfcChart::Association as;
                as.step = stepIndex[refs[0]];
                as.qualifier = upper(a.attribute("qualifier").value());
                if (as.qualifier.empty()) as.qualifier = "N";
                as.duration = a.attribute("duration").value();
                static const std::set<std::string> known = {"N", "R", "S", "L", "D", "P", "P1", "P0", "SD", "DS", "SL"};
                if (!known.count(as.qualifier)) {
                    fail(a, "action qualifier '" + as.qualifier + "' of " + stepLabel(as.step) + " is not one of N R S L D P P1 P0 SD DS SL");
                    continue;
                }
                const bool timed = as.qualifier == "L" || as.qualifier == "D" || as.qualifier == "SD" || as.qualifier == "DS" || as.qualifier == "SL";
                if (timed && as.duration.empty()) {
                    fail(a, "action qualifier " + as.qualifier + " of " + stepLabel(as.step) + " needs a duration");
                    continue;
                }
                as.duration = durationText(as.duration);
                if (pugi::xml_node ref = child(a, "reference")) {
                    std::string name = ref.attribute("name").value();
                    auto [it, added] = byName.emplace(upper(name), static_cast<int>(model.actions.size()));
                    if (added) {
                        SfcChart::Action act;
                        act.name = name;
                        act.at = at(a);
                        act.label = "action '" + name + "'";
                        act.isVariable = !ctx.actions.count(upper(name));
                        if (act.isVariable && ctx.typeOf(name).empty())
                            fail(a, "action '" + name + "' of " + stepLabel(as.step) + " is neither an action of '" + ctx.pouName + "' nor a variable");
                        model.actions.push_back(act);
                    }
                    model.actions[static_cast<size_t>(it->second)].uses.push_back(as);
                } else if (pugi::xml_node in = child(a, "inline")) {
                    SfcChart::Action act;
                    act.at = at(a);
                    act.label = "inline action of " + stepLabel(as.step);
                    act.uses.push_back(as);
                    pugi::xml_node st = child(in, "ST");
                    if (!st) fail(in, act.label + ": only ST inline actions are supported");
                    else copyStText(conv, st, act.label, act.body);
                    model.actions.push_back(act);
                } else {
                    fail(a, "an action of " + stepLabel(as.step) + " names no action and has no body");
                }
            }
        }
    }

    // IEC durations: T#5s as given; ISO 8601 (PT5S) as CODESYS writes it is converted by the literal reader.
    static std::string durationText(const std::string& d) {
        if (d.size() > 1 && (d[0] == 'P' || d[0] == 'p')) {
            std::string out = "T#";
            std::string number;
            bool inTime = false;
            for (size_t i = 1; i < d.size(); ++i) {
                char c = static_cast<char>(std::toupper(static_cast<unsigned char>(d[i])));
                if (c == 'T') { inTime = true; continue; }
                if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') { number.push_back(c); continue; }
                const char* unit = c == 'D' ? "d" : c == 'H' ? "h" : (c == 'M' && inTime) ? "m" : c == 'S' ? "s" : nullptr;
                if (!unit) return "T#0s";
                out += number + unit;
                number.clear();
            }
            return out;
        }
        return d;
    }

    // The condition of a transition as ST lines ending in an expression.
    void conditionLines(const pugi::xml_node& t, SfcChart::Transition& tr) {
        std::vector<StLine>& pre = tr.before;
        std::string& expr = tr.expr;
        pugi::xml_node cond = child(t, "condition");
        const std::string label = transitionLabel(t);
        if (pugi::xml_node ref = child(cond, "reference")) {
            std::string name = ref.attribute("name").value();
            auto it = ctx.transitions.find(upper(name));
            if (it != ctx.transitions.end()) {
                // A named transition: its body (ST assigning the name, or an LD/FBD network writing it) runs first.
                pugi::xml_node body = firstElement(child(it->second, "body"));
                const std::string k = body ? localName(body) : "";
                if (ctx.typeOf(name).empty() && !declaredTransitions.count(upper(name))) {
                    declare(it->second, name + " : BOOL;", "transition '" + name + "'");
                    declaredTransitions.insert(upper(name));
                }
                if (k == "ST") {
                    copyStText(conv, body, "transition '" + name + "'", pre);
                } else if (k == "LD" || k == "FBD") {
                    Translation tr;
                    translateNetwork(conv, body, k == "LD", ctx, tr);
                    pre.insert(pre.end(), tr.body.begin(), tr.body.end());
                    out.declarations.insert(out.declarations.end(), tr.declarations.begin(), tr.declarations.end());
                } else {
                    fail(it->second, "transition '" + name + "' has a body in " + (k.empty() ? "no language" : k) + "; strun runs ST, LD and FBD transitions");
                }
                expr = name;
                return;
            }
            if (ctx.typeOf(name).empty()) fail(ref, label + " names '" + name + "', which is neither a transition nor a variable of '" + ctx.pouName + "'");
            expr = name;
            return;
        }
        if (pugi::xml_node in = child(cond, "inline")) {
            pugi::xml_node st = child(in, "ST");
            if (!st) {
                fail(in, label + ": only ST inline conditions are supported");
                return;
            }
            copyStText(conv, st, label, tr.condition);
            return;
        }
        if (pugi::xml_node in = child(cond, "connectionPointIn")) {
            std::vector<int> refs;
            for (pugi::xml_node c : children(in, "connection")) refs.push_back(c.attribute("refLocalId").as_int());
            if (refs.size() == 1 && byId.count(refs[0]) && localName(byId[refs[0]]) == "inVariable") {
                expr = "(" + textOf(child(byId[refs[0]], "expression")) + ")";
                return;
            }
            // A network drawn in the chart: translated with the others (translateChartConditions), into a BOOL.
            expr = prefix + "c" + std::string(t.attribute("localId").value());
            declare(t, expr + " : BOOL;", label);
            drawnConditions.push_back({t, in, expr, label});
            return;
        }
        fail(t, label + " has no condition");
    }
    std::set<std::string> declaredTransitions;

    void run(const pugi::xml_node& lang) {
        read(lang);
        if (failed) return;
        if (steps.empty()) {
            fail(lang, "the SFC chart has no steps");
            return;
        }
        for (size_t s = 0; s < steps.size(); ++s)
            model.steps.push_back({stepName(static_cast<int>(s)), steps[s].attribute("initialStep").as_bool(), at(steps[s])});
        for (size_t t = 0; t < transitions.size(); ++t) {
            SfcChart::Transition tr;
            for (int r : inputRefs(transitions[t])) stepsBefore(r, transitions[t], tr.pre, 0);
            stepsAfter(transitions[t].attribute("localId").as_int(), transitions[t], tr.post, 0);
            if (!failed && (tr.pre.empty() || tr.post.empty()))
                fail(transitions[t], transitionLabel(transitions[t]) + (tr.pre.empty() ? " has no preceding step" : " has no following step"));
            tr.x = child(transitions[t], "position").attribute("x").as_double();
            tr.priority = transitions[t].attribute("priority").as_int(0);
            tr.id = transitions[t].attribute("localId").value();
            tr.label = transitionLabel(transitions[t]);
            tr.at = at(transitions[t]);
            model.transitions.push_back(std::move(tr));
        }
        readActions();
        if (failed) return;
        for (size_t t = 0; t < transitions.size(); ++t) conditionLines(transitions[t], model.transitions[t]);
        if (failed) return;
        if (!drawnConditions.empty()) {
            Translation nets;
            const size_t errors = conv.result.errors.size();
            translateChartConditions(conv, lang, ctx, drawnConditions, nets);
            if (conv.result.errors.size() != errors) return;
            model.conditionNetworks = std::move(nets.body);
            out.declarations.insert(out.declarations.end(), nets.declarations.begin(), nets.declarations.end());
        }
        failed = !writeSfcChart(model, prefix, out, [&](SfcChart::Where w, const std::string& what) {
            conv.result.errors.push_back({w.line, w.col, "in the SFC chart of '" + ctx.pouName + "': " + what});
        });
    }
};

}  // namespace

void translateChart(XmlConversion& conv, const pugi::xml_node& lang, PouContext& ctx, Translation& out) {
    Chart c(conv, ctx, out);
    c.run(lang);
}

}  // namespace strun::source::plcopen
