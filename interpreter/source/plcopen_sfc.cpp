// SFC charts of PLCopen TC6 XML as ST (docs/graphical.md, decisions 0233-0235).
// Each step is a variable of type __SFC_STEP (stdlib/st/sfc.st: .X, .T and
// CODESYS' ._X, ._T), so ST code, --dump and --vcd see it like any other
// variable. One evaluation of the chart (one call of the POU):
//   1. the times of the active steps;
//   2. action control: every action's activity Q from the qualifiers of its
//      active steps, then the actions with Q, and once more (the final scan)
//      those whose Q fell in this evaluation;
//   3. the transitions: all that are enabled (every preceding step active)
//      and whose condition is TRUE are cleared at once; among transitions
//      leaving one step (selection divergence) the leftmost wins;
//   4. their preceding steps are deactivated, then their following steps
//      activated (T restarts at 0).
// Charts that cannot work (no initial step, a step that cannot be reached, a
// jump to an unknown step, a transition without steps) are errors naming the
// element.
#include <algorithm>
#include <cctype>
#include <functional>
#include <map>
#include <set>

#include "interpreter/source/plcopen_graphical.h"
#include "interpreter/source/plcopen_xml.h"

namespace strun::source::plcopen {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

struct Association {
    int step = -1;  // index into Chart::steps
    std::string qualifier = "N";
    std::string duration;
};

struct Action {
    std::string name;            // as referenced (empty for an inline action)
    pugi::xml_node node;         // the <action> element of the first association
    pugi::xml_node inlineBody;   // <inline> of an inline action
    std::vector<Association> uses;
    bool isVariable = false;     // a BOOL variable, not an action of the POU
};

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
    std::vector<Action> actions;

    Chart(XmlConversion& c, PouContext& x, Translation& o) : conv(c), ctx(x), out(o) { prefix = "_g" + std::to_string(++ctx.bodies) + "_"; }

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

    void line(const pugi::xml_node& n, const std::string& text, const std::string& element) {
        auto [l, c] = conv.where(n);
        out.body.push_back({text, l, c, element, false});
    }
    void declare(const pugi::xml_node& n, const std::string& text, const std::string& element) {
        auto [l, c] = conv.where(n);
        out.declarations.push_back({"    " + text, l, c, element, false});
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
                       k != "simultaneousConvergence" && k != "jumpStep" && k != "actionBlock" && k != "inVariable") {
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
                Association as;
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
                if (pugi::xml_node ref = child(a, "reference")) {
                    std::string name = ref.attribute("name").value();
                    auto [it, added] = byName.emplace(upper(name), static_cast<int>(actions.size()));
                    if (added) {
                        Action act;
                        act.name = name;
                        act.node = a;
                        act.isVariable = !ctx.actions.count(upper(name));
                        if (act.isVariable && ctx.typeOf(name).empty())
                            fail(a, "action '" + name + "' of " + stepLabel(as.step) + " is neither an action of '" + ctx.pouName + "' nor a variable");
                        actions.push_back(act);
                    }
                    actions[static_cast<size_t>(it->second)].uses.push_back(as);
                } else if (pugi::xml_node in = child(a, "inline")) {
                    Action act;
                    act.node = a;
                    act.inlineBody = in;
                    act.uses.push_back(as);
                    actions.push_back(act);
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
    void conditionLines(const pugi::xml_node& t, const std::string& var, std::vector<StLine>& pre, std::string& expr) {
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
            std::vector<StLine> text;
            copyStText(conv, st, label, text);
            // `var := (` condition `);` with the condition's own positions.
            auto [l, c] = conv.where(t);
            pre.push_back({var + " := (", l, c, label, false});
            for (StLine& s : text) {
                while (!s.text.empty() && (std::isspace(static_cast<unsigned char>(s.text.back())) || s.text.back() == ';')) s.text.pop_back();
                pre.push_back(s);
            }
            pre.push_back({");", l, c, label, false});
            expr = var;
            return;
        }
        if (pugi::xml_node in = child(cond, "connectionPointIn")) {
            std::vector<int> refs;
            for (pugi::xml_node c : children(in, "connection")) refs.push_back(c.attribute("refLocalId").as_int());
            if (refs.size() == 1 && byId.count(refs[0]) && localName(byId[refs[0]]) == "inVariable") {
                expr = "(" + textOf(child(byId[refs[0]], "expression")) + ")";
                return;
            }
            fail(t, label + ": a condition drawn in the chart must be one variable; write a named transition in LD or FBD instead");
            return;
        }
        fail(t, label + " has no condition");
    }
    std::set<std::string> declaredTransitions;

    void checkReachable(const std::vector<std::vector<int>>& pre, const std::vector<std::vector<int>>& post) {
        std::vector<bool> seen(steps.size(), false);
        std::vector<int> work;
        for (size_t s = 0; s < steps.size(); ++s)
            if (steps[s].attribute("initialStep").as_bool()) {
                seen[s] = true;
                work.push_back(static_cast<int>(s));
            }
        if (work.empty()) {
            fail(steps.empty() ? pugi::xml_node() : steps[0], "the SFC chart has no initial step");
            return;
        }
        // A transition can fire once all its preceding steps can be active.
        bool grew = true;
        while (grew) {
            grew = false;
            for (size_t t = 0; t < transitions.size(); ++t) {
                if (pre[t].empty() || !std::all_of(pre[t].begin(), pre[t].end(), [&](int s) { return seen[static_cast<size_t>(s)]; })) continue;
                for (int s : post[t])
                    if (!seen[static_cast<size_t>(s)]) seen[static_cast<size_t>(s)] = grew = true;
            }
        }
        for (size_t s = 0; s < steps.size(); ++s)
            if (!seen[s]) fail(steps[s], stepLabel(static_cast<int>(s)) + " can never become active (no path from the initial step reaches it)");
    }

    void run(const pugi::xml_node& lang) {
        read(lang);
        if (failed) return;
        if (steps.empty()) {
            fail(lang, "the SFC chart has no steps");
            return;
        }
        std::vector<std::vector<int>> pre(transitions.size()), post(transitions.size());
        for (size_t t = 0; t < transitions.size(); ++t) {
            for (int r : inputRefs(transitions[t])) stepsBefore(r, transitions[t], pre[t], 0);
            stepsAfter(transitions[t].attribute("localId").as_int(), transitions[t], post[t], 0);
            if (!failed && (pre[t].empty() || post[t].empty()))
                fail(transitions[t], transitionLabel(transitions[t]) + (pre[t].empty() ? " has no preceding step" : " has no following step"));
        }
        readActions();
        if (failed) return;
        checkReachable(pre, post);
        if (failed) return;

        // Declarations: the steps, the transitions' results, the actions' activity.
        for (size_t s = 0; s < steps.size(); ++s)
            declare(steps[s], stepName(static_cast<int>(s)) + " : __SFC_STEP" + (steps[s].attribute("initialStep").as_bool() ? " := (X := TRUE, _X := TRUE)" : "") + ";",
                    stepLabel(static_cast<int>(s)));

        // 1. Step times.
        for (size_t s = 0; s < steps.size(); ++s) {
            const std::string n = stepName(static_cast<int>(s));
            line(steps[s], "IF " + n + ".X THEN " + n + ".T := TIME() - " + n + ".START; " + n + "._T := " + n + ".T; END_IF;", stepLabel(static_cast<int>(s)));
        }
        // 2. Action control and the actions.
        for (size_t a = 0; a < actions.size(); ++a) writeAction(static_cast<int>(a));
        // 3. Transitions (evaluated on the steps as they are now), leftmost first among alternatives.
        std::vector<size_t> order(transitions.size());
        for (size_t t = 0; t < order.size(); ++t) order[t] = t;
        auto priority = [&](size_t t) {
            pugi::xml_node p = child(transitions[t], "position");
            return std::make_pair(p.attribute("x").as_double(), static_cast<double>(t));
        };
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            int pa = transitions[a].attribute("priority").as_int(0), pb = transitions[b].attribute("priority").as_int(0);
            if (pa != pb && pa > 0 && pb > 0) return pa < pb;
            return priority(a) < priority(b);
        });
        std::vector<std::string> fire(transitions.size());
        std::vector<size_t> done;
        for (size_t t : order) {
            const std::string label = transitionLabel(transitions[t]);
            fire[t] = prefix + "t" + transitions[t].attribute("localId").value();
            declare(transitions[t], fire[t] + " : BOOL;", label);
            std::vector<StLine> pre_;
            std::string expr;
            conditionLines(transitions[t], fire[t], pre_, expr);
            out.body.insert(out.body.end(), pre_.begin(), pre_.end());
            std::string enabled;
            for (int s : pre[t]) enabled += (enabled.empty() ? "" : " AND ") + stepName(s) + ".X";
            // A transition sharing a preceding step with one already cleared this evaluation does not fire.
            for (size_t u : done) {
                bool shares = false;
                for (int s : pre[t])
                    shares = shares || std::find(pre[u].begin(), pre[u].end(), s) != pre[u].end();
                if (shares) enabled += " AND NOT " + fire[u];
            }
            line(transitions[t], fire[t] + " := " + enabled + " AND " + expr + ";", label);
            done.push_back(t);
        }
        // 4. Deactivate, then activate.
        for (size_t t : order) {
            std::string s;
            for (int st : pre[t]) s += stepName(st) + ".X := FALSE; " + stepName(st) + "._X := FALSE; ";
            line(transitions[t], "IF " + fire[t] + " THEN " + s + "END_IF;", transitionLabel(transitions[t]));
        }
        for (size_t t : order) {
            std::string s;
            for (int st : post[t]) {
                const std::string n = stepName(st);
                s += n + ".X := TRUE; " + n + "._X := TRUE; " + n + ".START := TIME(); " + n + ".T := T#0s; " + n + "._T := T#0s; ";
            }
            line(transitions[t], "IF " + fire[t] + " THEN " + s + "END_IF;", transitionLabel(transitions[t]));
        }
    }

    void writeAction(int index) {
        Action& a = actions[static_cast<size_t>(index)];
        const std::string label = a.name.empty() ? "inline action of " + stepLabel(a.uses[0].step) : "action '" + a.name + "'";
        const std::string base = prefix + "a" + std::to_string(index);
        std::map<std::string, std::string> inputs;  // qualifier -> OR of steps
        std::map<std::string, std::string> times;
        bool onlyN = true, onlyPulses = true;
        for (const Association& as : a.uses) {
            std::string& in = inputs[as.qualifier];
            in += (in.empty() ? "" : " OR ") + stepName(as.step) + ".X";
            if (!as.duration.empty() && !times.count(as.qualifier)) times[as.qualifier] = durationText(as.duration);
            onlyN = onlyN && as.qualifier == "N";
            onlyPulses = onlyPulses && (as.qualifier == "P" || as.qualifier == "P1" || as.qualifier == "P0");
        }
        std::string q;
        if (onlyN) {
            q = inputs["N"];
        } else {
            const std::string control = base + "_control";
            declare(a.node, control + " : __SFC_ACTION_CONTROL;", label);
            std::string args;
            for (auto& [qual, in] : inputs) args += (args.empty() ? "" : ", ") + qual + " := " + in;
            for (auto& [qual, t] : times) args += ", T_" + qual + " := " + t;
            line(a.node, control + "(" + args + ");", label);
            q = control + ".Q";
        }
        if (a.isVariable) {
            line(a.node, a.name + " := " + q + ";", label);
            return;
        }
        const std::string active = base + "_q";
        declare(a.node, active + " : BOOL;", label);
        // The final scan: an action whose Q fell runs once more (not the pulse qualifiers, which run once; decision 0234).
        if (onlyPulses) line(a.node, active + " := " + q + "; IF " + active + " THEN", label);
        else line(a.node, "IF " + q + " OR " + active + " THEN " + active + " := " + q + ";", label);
        if (a.name.empty()) {
            pugi::xml_node st = child(a.inlineBody, "ST");
            if (!st) {
                fail(a.inlineBody, label + ": only ST inline actions are supported");
                return;
            }
            copyStText(conv, st, label, out.body);
        } else {
            line(a.node, a.name + "();", label);
        }
        line(a.node, "END_IF;", label);
    }
};

}  // namespace

void translateChart(XmlConversion& conv, const pugi::xml_node& lang, PouContext& ctx, Translation& out) {
    Chart c(conv, ctx, out);
    c.run(lang);
}

}  // namespace strun::source::plcopen
