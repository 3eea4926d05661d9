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
#include "stdlib/number_scan.h"

namespace strun::source::plcopen {

namespace {

using FailAt = std::function<void(const pugi::xml_node&, const std::string&)>;

// IEC durations: T#5s as given; ISO 8601 (PT5S) as CODESYS writes it becomes T#5s.
std::string sfcDurationText(const std::string& d) {
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

// One <action> of an action block (in an SFC chart, or in an LD/FBD body):
// its qualifier and duration into `as`, and in `act` either the name of an
// action of the POU or of a BOOL variable (act.name), or an inline body in
// ST, LD or FBD (act.name empty; as is then its only use). `owner` names
// what activates it in messages (`step 'Fill'`, `action block 7`). False
// after `fail` when the action is wrong.
bool readAction(XmlConversion& conv, const pugi::xml_node& a, PouContext& ctx, const std::string& owner, SfcChart::Association& as,
                SfcChart::Action& act, Translation& out, const FailAt& fail) {
    as.qualifier = stdlib::upperAscii(a.attribute("qualifier").value());
    if (as.qualifier.empty()) as.qualifier = "N";
    as.duration = a.attribute("duration").value();
    static const std::set<std::string> known = {"N", "R", "S", "L", "D", "P", "P1", "P0", "SD", "DS", "SL"};
    if (!known.count(as.qualifier)) {
        fail(a, "action qualifier '" + as.qualifier + "' of " + owner + " is not one of N R S L D P P1 P0 SD DS SL");
        return false;
    }
    const bool timed = as.qualifier == "L" || as.qualifier == "D" || as.qualifier == "SD" || as.qualifier == "DS" || as.qualifier == "SL";
    if (timed && as.duration.empty()) {
        fail(a, "action qualifier " + as.qualifier + " of " + owner + " needs a duration");
        return false;
    }
    as.duration = sfcDurationText(as.duration);
    act.at = {conv.where(a).first, conv.where(a).second};
    if (pugi::xml_node ref = child(a, "reference")) {
        act.name = ref.attribute("name").value();
        act.label = "action '" + act.name + "'";
        act.isVariable = !ctx.actions.count(stdlib::upperAscii(act.name));
        if (act.isVariable && ctx.typeOf(act.name).empty()) {
            fail(a, "action '" + act.name + "' of " + owner + " is neither an action of '" + ctx.pouName + "' nor a variable");
            return false;
        }
        return true;
    }
    pugi::xml_node in = child(a, "inline");
    if (!in) {
        fail(a, "an action of " + owner + " names no action and has no body");
        return false;
    }
    act.label = "inline action of " + owner;
    act.uses.push_back(as);
    // ST is copied; an LD or FBD network is translated like a POU's (docs/graphical.md).
    pugi::xml_node body = firstElement(in);
    const std::string k = body ? localName(body) : "";
    if (k == "ST") {
        copyStText(conv, body, act.label, act.body);
    } else if (k == "LD" || k == "FBD") {
        Translation tr;
        translateNetwork(conv, body, k == "LD", ctx, tr);
        act.body = std::move(tr.body);
        out.declarations.insert(out.declarations.end(), tr.declarations.begin(), tr.declarations.end());
    } else {
        fail(in, act.label + " is written in " + (k.empty() ? "no language" : k) + "; strun runs ST, LD and FBD actions");
        return false;
    }
    return true;
}

struct Chart {
    XmlConversion& conv;
    PouContext& ctx;
    Translation& out;
    std::string prefix;
    bool failed = false;

    // Element ids: the localId, plus an offset for the elements in the body
    // of a macro step (each body numbers its elements from its own 0).
    using Id = long long;
    std::map<Id, pugi::xml_node> byId;
    std::map<Id, std::vector<pugi::xml_node>> readers;  // id -> elements connected to its output
    std::vector<pugi::xml_node> steps, transitions;
    std::map<std::string, int> stepByName;  // upper -> index
    std::map<Id, int> stepIndex;            // id -> index
    SfcChart model;
    // Macro steps: the chart of each body is read into this one; a macro is
    // entered through its body's initial step and left from its final step.
    struct Macro {
        pugi::xml_node node, body;
        int entry = -1, exit = -1;
    };
    std::map<Id, Macro> macros;                       // the macro step's id -> its body
    std::map<const void*, Id> offsets;                // an <SFC> element -> the offset of its ids
    std::set<int> macroEntries;                       // steps that are initial only inside their macro

    Id offsetOf(const pugi::xml_node& sfc) const {
        auto it = offsets.find(sfc.internal_object());
        return it == offsets.end() ? 0 : it->second;
    }
    Id idOf(const pugi::xml_node& n) const { return n.attribute("localId").as_llong() + offsetOf(n.parent()); }
    // Unique among the chart's elements, for hidden variable names: `7`, or `m1_7` inside the first macro body.
    std::string uid(const pugi::xml_node& n) const {
        Id off = offsetOf(n.parent());
        return (off ? "m" + std::to_string(off >> 32) + "_" : std::string()) + n.attribute("localId").value();
    }

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

    std::vector<Id> inputRefs(const pugi::xml_node& n) const {
        std::vector<Id> refs;
        const Id off = offsetOf(n.parent());
        for (pugi::xml_node in : children(n, "connectionPointIn"))
            for (pugi::xml_node c : children(in, "connection")) refs.push_back(c.attribute("refLocalId").as_llong() + off);
        return refs;
    }

    void read(const pugi::xml_node& lang, int depth = 0) {
        const bool inMacro = depth > 0;
        for (pugi::xml_node n : lang.children()) {
            if (n.type() != pugi::node_element) continue;
            const std::string k = localName(n);
            if (k == "comment" || k == "documentation" || k == "addData") continue;
            if (!n.attribute("localId")) {
                fail(n, "the " + k + " element" + (n.attribute("name") ? " '" + std::string(n.attribute("name").value()) + "'" : std::string()) +
                            " has no localId (PLCopen TC6 requires one)");
                continue;
            }
            const Id id = idOf(n);
            if (byId.count(id)) {
                fail(n, "two elements have localId " + std::string(n.attribute("localId").value()));
                continue;
            }
            byId[id] = n;
            if (k == "step") {
                std::string name = n.attribute("name").value();
                if (name.empty() || stepByName.count(stdlib::upperAscii(name))) {
                    fail(n, name.empty() ? "a step has no name" : "two steps are named '" + name + "'");
                    continue;
                }
                stepByName[stdlib::upperAscii(name)] = static_cast<int>(steps.size());
                stepIndex[id] = static_cast<int>(steps.size());
                steps.push_back(n);
            } else if (k == "transition") {
                transitions.push_back(n);
            } else if (k == "macroStep") {
                // Its body's chart joins this one (decision 0292).
                pugi::xml_node body = child(child(n, "body"), "SFC");
                const std::string label = "macro step " + std::string(n.attribute("localId").value()) + " '" + n.attribute("name").value() + "'";
                if (!body) {
                    fail(n, label + " has no SFC body");
                    continue;
                }
                if (depth >= 16) {
                    fail(n, label + " is nested more than 16 macro steps deep");
                    continue;
                }
                const Id offset = static_cast<Id>(offsets.size() + 1) << 32;
                offsets[body.internal_object()] = offset;
                macros[id] = {n, body};
                read(body, depth + 1);
            } else if (inMacro && networkElements().count(k)) {
                fail(n, "the " + k + " element " + std::string(n.attribute("localId").value()) +
                            " is in the body of a macro step: strun reads conditions drawn as networks only in the chart itself");
            } else if (k != "selectionDivergence" && k != "selectionConvergence" && k != "simultaneousDivergence" &&
                       k != "simultaneousConvergence" && k != "jumpStep" && k != "actionBlock" && !networkElements().count(k)) {
                fail(n, "the " + k + " element " + std::string(n.attribute("localId").value()) + " is not supported in SFC bodies (docs/graphical.md)");
            }
        }
        if (depth > 0) return;
        for (auto& [id, n] : byId)
            for (Id r : inputRefs(n)) readers[r].push_back(n);
        for (auto& [id, m] : macros) macroEnds(m);
    }

    // The entry (the initial step) and exit (the step nothing follows) of a macro's body.
    void macroEnds(Macro& m) {
        const std::string label = "macro step " + std::string(m.node.attribute("localId").value()) + " '" + m.node.attribute("name").value() + "'";
        std::vector<int> entries, exits;
        for (pugi::xml_node n : m.body.children()) {
            if (localName(n) != "step" || !stepIndex.count(idOf(n))) continue;
            const int s = stepIndex[idOf(n)];
            if (n.attribute("initialStep").as_bool()) entries.push_back(s);
            bool followed = false;
            for (const pugi::xml_node& r : readers[idOf(n)]) followed = followed || localName(r) != "actionBlock";
            if (!followed) exits.push_back(s);
        }
        if (entries.size() != 1) {
            fail(m.node, label + ": its body needs exactly one initial step (where the macro is entered), it has " + std::to_string(entries.size()));
            return;
        }
        if (exits.size() != 1) {
            fail(m.node, label + ": its body needs exactly one final step (nothing after it; the macro is left from it), it has " +
                             std::to_string(exits.size()));
            return;
        }
        m.entry = entries[0];
        m.exit = exits[0];
        macroEntries.insert(m.entry);
        // A jump to the macro enters it.
        const std::string name = stdlib::upperAscii(m.node.attribute("name").value());
        if (!name.empty() && !stepByName.count(name)) stepByName[name] = m.entry;
    }

    // The steps that must be active for transition input `ref` (through
    // selection divergences and simultaneous convergences).
    void stepsBefore(Id ref, const pugi::xml_node& t, std::vector<int>& into, int depth) {
        auto it = byId.find(ref);
        if (it == byId.end() || depth > 1000) {
            fail(t, transitionLabel(t) + " is connected to element " + std::to_string(ref & 0xffffffffLL) + ", which the chart does not have");
            return;
        }
        const std::string k = localName(it->second);
        if (k == "step") {
            into.push_back(stepIndex[ref]);
        } else if (k == "macroStep") {
            if (macros[ref].exit >= 0) into.push_back(macros[ref].exit);
        } else if (k == "selectionDivergence" || k == "simultaneousConvergence") {
            for (Id r : inputRefs(it->second)) stepsBefore(r, t, into, depth + 1);
        } else {
            fail(t, transitionLabel(t) + " follows a " + k + "; a transition follows a step, a selection divergence or a simultaneous convergence");
        }
    }

    // The steps transition (or divergence) `id` activates.
    void stepsAfter(Id id, const pugi::xml_node& t, std::vector<int>& into, int depth) {
        if (depth > 1000) return;
        for (const pugi::xml_node& r : readers[id]) {
            const std::string k = localName(r);
            if (k == "step") {
                into.push_back(stepIndex[idOf(r)]);
            } else if (k == "macroStep") {
                if (macros[idOf(r)].entry >= 0) into.push_back(macros[idOf(r)].entry);
            } else if (k == "selectionConvergence" || k == "simultaneousDivergence") {
                stepsAfter(idOf(r), t, into, depth + 1);
            } else if (k == "jumpStep") {
                auto s = stepByName.find(stdlib::upperAscii(r.attribute("targetName").value()));
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
            std::vector<Id> refs = inputRefs(n);
            if (refs.size() != 1 || !stepIndex.count(refs[0])) {
                fail(n, "action block " + std::string(n.attribute("localId").value()) + " is not connected to a step");
                continue;
            }
            for (pugi::xml_node a : children(n, "action")) {
                SfcChart::Association as;
                as.step = stepIndex[refs[0]];
                SfcChart::Action act;
                if (!readAction(conv, a, ctx, stepLabel(as.step), as, act, out, [&](const pugi::xml_node& where, const std::string& what) { fail(where, what); }))
                    continue;
                if (act.name.empty()) {
                    model.actions.push_back(act);
                    continue;
                }
                auto [it, added] = byName.emplace(stdlib::upperAscii(act.name), static_cast<int>(model.actions.size()));
                if (added) model.actions.push_back(act);
                model.actions[static_cast<size_t>(it->second)].uses.push_back(as);
            }
        }
    }

    // The condition of a transition as ST lines ending in an expression.
    void conditionLines(const pugi::xml_node& t, SfcChart::Transition& tr) {
        std::vector<StLine>& pre = tr.before;
        std::string& expr = tr.expr;
        pugi::xml_node cond = child(t, "condition");
        const std::string label = transitionLabel(t);
        if (pugi::xml_node ref = child(cond, "reference")) {
            std::string name = ref.attribute("name").value();
            auto it = ctx.transitions.find(stdlib::upperAscii(name));
            if (it != ctx.transitions.end()) {
                // A named transition: its body (ST assigning the name, or an LD/FBD network writing it) runs first.
                pugi::xml_node body = firstElement(child(it->second, "body"));
                const std::string k = body ? localName(body) : "";
                if (ctx.typeOf(name).empty() && !declaredTransitions.count(stdlib::upperAscii(name))) {
                    declare(it->second, name + " : BOOL;", "transition '" + name + "'");
                    declaredTransitions.insert(stdlib::upperAscii(name));
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
            pugi::xml_node body = firstElement(in);
            const std::string k = body ? localName(body) : "";
            if (k == "ST") {
                copyStText(conv, body, label, tr.condition);
                return;
            }
            if (k != "LD" && k != "FBD") {
                fail(in, label + " has a condition in " + (k.empty() ? "no language" : k) + "; strun runs ST, LD and FBD conditions");
                return;
            }
            // An LD/FBD condition writes the inline's name (a coil or an output variable), as a named transition's body does.
            std::string name = in.attribute("name").value();
            if (name.empty()) {
                fail(in, label + ": an inline " + k + " condition needs a name (<inline name=\"...\">) that its network writes");
                return;
            }
            if (ctx.typeOf(name).empty() && !declaredTransitions.count(stdlib::upperAscii(name))) {
                declare(in, name + " : BOOL;", label);
                declaredTransitions.insert(stdlib::upperAscii(name));
            }
            Translation net;
            translateNetwork(conv, body, k == "LD", ctx, net);
            tr.before.insert(tr.before.end(), net.body.begin(), net.body.end());
            out.declarations.insert(out.declarations.end(), net.declarations.begin(), net.declarations.end());
            expr = name;
            return;
        }
        if (pugi::xml_node in = child(cond, "connectionPointIn")) {
            std::vector<Id> refs;
            for (pugi::xml_node c : children(in, "connection")) refs.push_back(c.attribute("refLocalId").as_llong() + offsetOf(t.parent()));
            if (refs.size() == 1 && byId.count(refs[0]) && localName(byId[refs[0]]) == "inVariable") {
                expr = "(" + textOf(child(byId[refs[0]], "expression")) + ")";
                return;
            }
            // A network drawn in the chart: translated with the others (translateChartConditions), into a BOOL.
            expr = prefix + "c" + uid(t);
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
            model.steps.push_back({stepName(static_cast<int>(s)),
                                   steps[s].attribute("initialStep").as_bool() && !macroEntries.count(static_cast<int>(s)), at(steps[s])});
        for (size_t t = 0; t < transitions.size(); ++t) {
            SfcChart::Transition tr;
            for (Id r : inputRefs(transitions[t])) stepsBefore(r, transitions[t], tr.pre, 0);
            stepsAfter(idOf(transitions[t]), transitions[t], tr.post, 0);
            if (!failed && (tr.pre.empty() || tr.post.empty()))
                fail(transitions[t], transitionLabel(transitions[t]) + (tr.pre.empty() ? " has no preceding step" : " has no following step"));
            tr.x = child(transitions[t], "position").attribute("x").as_double();
            tr.priority = transitions[t].attribute("priority").as_int(0);
            tr.id = uid(transitions[t]);
            tr.label = transitionLabel(transitions[t]);
            tr.at = at(transitions[t]);
            model.transitions.push_back(std::move(tr));
        }
        readActions();
        if (failed) return;
        model.sfcInit = ctx.variables.count("SFCINIT") != 0;
        model.sfcReset = ctx.variables.count("SFCRESET") != 0;
        model.sfcPause = ctx.variables.count("SFCPAUSE") != 0;
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

void translateActionBlock(XmlConversion& conv, const pugi::xml_node& block, const std::string& activity, const std::string& prefix,
                          const std::string& where, PouContext& ctx, Translation& out) {
    const std::string owner = "action block " + std::string(block.attribute("localId").value());
    int k = 0;
    for (pugi::xml_node a : children(block, "action")) {
        SfcChart::Association as;
        as.activity = activity;
        SfcChart::Action act;
        if (!readAction(conv, a, ctx, owner, as, act, out, [&](const pugi::xml_node& n, const std::string& what) { conv.error(n, where + what); }))
            continue;
        if (!act.name.empty()) act.uses.push_back(as);
        else act.uses[0] = as;
        writeSfcAction(act, prefix + std::to_string(k++), out);
    }
}

void translateChart(XmlConversion& conv, const pugi::xml_node& lang, PouContext& ctx, Translation& out) {
    Chart c(conv, ctx, out);
    c.run(lang);
}

}  // namespace strun::source::plcopen
