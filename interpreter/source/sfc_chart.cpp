#include "interpreter/source/sfc_chart.h"

#include <algorithm>
#include <map>
#include <set>

namespace strun::source {

namespace {

using plcopen::StLine;

struct Writer {
    const SfcChart& c;
    const std::string& prefix;
    plcopen::Translation& out;

    std::string stepLabel(int s) const { return "step '" + c.steps[static_cast<size_t>(s)].name + "'"; }
    const std::string& stepName(int s) const { return c.steps[static_cast<size_t>(s)].name; }

    void line(SfcChart::Where at, const std::string& text, const std::string& element) { out.body.push_back({text, at.line, at.col, element, false}); }
    // A variable of the translation's own (hidden), or a step (visible).
    void declare(SfcChart::Where at, const std::string& text, const std::string& element, bool hidden = true) {
        out.declarations.push_back({"    " + std::string(hidden ? plcopen::kHiddenPragma : "") + text, at.line, at.col, element, false});
    }

    static bool onlyN(const SfcChart::Action& a) {
        return std::all_of(a.uses.begin(), a.uses.end(), [](const SfcChart::Association& as) { return as.qualifier == "N"; });
    }

    // SFCInit / SFCReset: every step back to its initial state, stored
    // actions cleared, no final scan owed.
    void resetLines(const std::string& condition) {
        const SfcChart::Where at = c.steps.empty() ? SfcChart::Where{} : c.steps[0].at;
        line(at, "IF " + condition + " THEN", "");
        for (const SfcChart::Step& st : c.steps) {
            const std::string x = st.initial ? "TRUE" : "FALSE";
            line(st.at, st.name + ".X := " + x + "; " + st.name + "._X := " + x + "; " + st.name + ".START := TIME(); " + st.name +
                            ".T := T#0s; " + st.name + "._T := T#0s;",
                 "step '" + st.name + "'");
        }
        for (size_t i = 0; i < c.actions.size(); ++i) {
            const SfcChart::Action& a = c.actions[i];
            const std::string base = prefix + "a" + std::to_string(i);
            // R clears the stored qualifiers; the input is then released (the chart's calls pass only the qualifiers it uses).
            if (!onlyN(a)) line(a.at, base + "_control(R := TRUE); " + base + "_control.R := FALSE;", a.label);
            if (!a.isVariable) line(a.at, base + "_q := FALSE;", a.label);
            else line(a.at, a.name + " := FALSE;", a.label);
        }
        line(at, "END_IF;", "");
    }

    void action(int index) {
        const SfcChart::Action& a = c.actions[static_cast<size_t>(index)];
        const std::string base = prefix + "a" + std::to_string(index);
        std::map<std::string, std::string> inputs, times;  // qualifier -> OR of steps / duration
        bool onlyN = true, onlyPulses = true;
        for (const SfcChart::Association& as : a.uses) {
            std::string& in = inputs[as.qualifier];
            in += (in.empty() ? "" : " OR ") + (as.activity.empty() ? stepName(as.step) + ".X" : as.activity);
            if (!as.duration.empty() && !times.count(as.qualifier)) times[as.qualifier] = as.duration;
            onlyN = onlyN && as.qualifier == "N";
            onlyPulses = onlyPulses && (as.qualifier == "P" || as.qualifier == "P1" || as.qualifier == "P0");
        }
        std::string q;
        if (onlyN) {
            q = inputs["N"];
        } else {
            const std::string control = base + "_control";
            declare(a.at, control + " : __SFC_ACTION_CONTROL;", a.label);
            std::string args;
            for (auto& [qual, in] : inputs) args += (args.empty() ? "" : ", ") + qual + " := " + in;
            for (auto& [qual, t] : times) args += ", T_" + qual + " := " + t;
            line(a.at, control + "(" + args + ");", a.label);
            q = control + ".Q";
        }
        if (a.isVariable) {
            line(a.at, a.name + " := " + q + ";", a.label);
            return;
        }
        const std::string active = base + "_q";
        declare(a.at, active + " : BOOL;", a.label);
        // The final scan: an action whose Q fell runs once more (not the pulse qualifiers, which run once; decision 0232).
        if (onlyPulses) line(a.at, active + " := " + q + "; IF " + active + " THEN", a.label);
        else line(a.at, "IF " + q + " OR " + active + " THEN " + active + " := " + q + ";", a.label);
        if (a.name.empty()) out.body.insert(out.body.end(), a.body.begin(), a.body.end());
        else line(a.at, a.name + "();", a.label);
        line(a.at, "END_IF;", a.label);
    }

    // Explores the activity states the chart can reach (every condition may be
    // TRUE or FALSE; one transition at a time). A transition that activates a
    // step still active is unsafe (a simultaneous branch left through a
    // selection convergence); a step active in no reachable state can never
    // become active (also a selection divergence closed by a simultaneous
    // convergence). Charts whose states exceed kMaxStates get the simpler
    // check: a step is reachable when some transition can lead to it.
    static constexpr size_t kMaxStates = 20000;

    bool reachable(const std::function<void(SfcChart::Where, const std::string&)>& fail) {
        const size_t n = c.steps.size();
        std::vector<bool> start(n, false);
        bool any = false;
        for (size_t s = 0; s < n; ++s)
            if (c.steps[s].initial) start[s] = any = true;
        if (!any) {
            fail(c.steps.empty() ? SfcChart::Where{} : c.steps[0].at, "the SFC chart has no initial step");
            return false;
        }
        std::vector<bool> seen = start;
        std::set<std::vector<bool>> states{start};
        std::vector<std::vector<bool>> work{start};
        bool complete = true;
        while (!work.empty()) {
            std::vector<bool> state = std::move(work.back());
            work.pop_back();
            for (const SfcChart::Transition& t : c.transitions) {
                if (t.pre.empty() || !std::all_of(t.pre.begin(), t.pre.end(), [&](int s) { return state[static_cast<size_t>(s)]; })) continue;
                std::vector<bool> next = state;
                for (int s : t.pre) next[static_cast<size_t>(s)] = false;
                for (int s : t.post) {
                    if (next[static_cast<size_t>(s)]) {
                        fail(t.at, t.label + " can activate " + stepLabel(s) + " while it is still active (an unsafe chart: a simultaneous "
                                   "branch must end in a simultaneous convergence)");
                        return false;
                    }
                    next[static_cast<size_t>(s)] = true;
                    seen[static_cast<size_t>(s)] = true;
                }
                if (states.size() >= kMaxStates) {
                    complete = false;
                    break;
                }
                if (states.insert(next).second) work.push_back(std::move(next));
            }
            if (!complete) break;
        }
        if (!complete) {
            seen = start;
            for (bool grew = true; grew;) {
                grew = false;
                for (const SfcChart::Transition& t : c.transitions) {
                    if (t.pre.empty() || !std::all_of(t.pre.begin(), t.pre.end(), [&](int s) { return seen[static_cast<size_t>(s)]; })) continue;
                    for (int s : t.post)
                        if (!seen[static_cast<size_t>(s)]) seen[static_cast<size_t>(s)] = grew = true;
                }
            }
        }
        bool ok = true;
        for (size_t s = 0; s < n; ++s)
            if (!seen[s]) {
                fail(c.steps[s].at, stepLabel(static_cast<int>(s)) + " can never become active (no path from the initial step reaches it)");
                ok = false;
            }
        return ok;
    }

    void write() {
        for (size_t s = 0; s < c.steps.size(); ++s)
            declare(c.steps[s].at, c.steps[s].name + " : __SFC_STEP" + (c.steps[s].initial ? " := (X := TRUE, _X := TRUE)" : "") + ";",
                    stepLabel(static_cast<int>(s)), false);
        // CODESYS' flags: SFCPause skips the evaluation, SFCInit/SFCReset reset the chart first.
        if (c.sfcPause) line(c.steps[0].at, "IF NOT SFCPause THEN", "");
        if (c.sfcInit || c.sfcReset)
            resetLines(c.sfcInit && c.sfcReset ? "SFCInit OR SFCReset" : c.sfcInit ? "SFCInit" : "SFCReset");
        if (c.sfcInit) line(c.steps[0].at, "IF NOT SFCInit THEN", "");
        // 1. Step times.
        for (size_t s = 0; s < c.steps.size(); ++s) {
            const std::string& n = c.steps[s].name;
            line(c.steps[s].at, "IF " + n + ".X THEN " + n + ".T := TIME() - " + n + ".START; " + n + "._T := " + n + ".T; END_IF;",
                 stepLabel(static_cast<int>(s)));
        }
        // 2. Action control and the actions.
        for (size_t a = 0; a < c.actions.size(); ++a) action(static_cast<int>(a));
        // 3. Transitions, on the steps as they are now; among alternatives the first in priority order wins.
        std::vector<size_t> order(c.transitions.size());
        for (size_t t = 0; t < order.size(); ++t) order[t] = t;
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            const SfcChart::Transition &x = c.transitions[a], &y = c.transitions[b];
            if (x.priority != y.priority && x.priority > 0 && y.priority > 0) return x.priority < y.priority;
            return x.x < y.x;
        });
        out.body.insert(out.body.end(), c.conditionNetworks.begin(), c.conditionNetworks.end());
        std::vector<std::string> fire(c.transitions.size());
        std::vector<size_t> done;
        for (size_t t : order) {
            const SfcChart::Transition& tr = c.transitions[t];
            fire[t] = prefix + "t" + tr.id;
            declare(tr.at, fire[t] + " : BOOL;", tr.label);
            out.body.insert(out.body.end(), tr.before.begin(), tr.before.end());
            std::string expr = tr.expr;
            if (!tr.condition.empty()) {
                line(tr.at, fire[t] + " := (", tr.label);
                for (StLine s : tr.condition) {
                    while (!s.text.empty() && (std::isspace(static_cast<unsigned char>(s.text.back())) || s.text.back() == ';')) s.text.pop_back();
                    out.body.push_back(s);
                }
                line(tr.at, ");", tr.label);
                expr = fire[t];
            }
            std::string enabled;
            for (int s : tr.pre) enabled += (enabled.empty() ? "" : " AND ") + stepName(s) + ".X";
            // A transition sharing a preceding step with one already cleared in this evaluation does not fire.
            for (size_t u : done) {
                bool shares = false;
                for (int s : tr.pre) shares = shares || std::find(c.transitions[u].pre.begin(), c.transitions[u].pre.end(), s) != c.transitions[u].pre.end();
                if (shares) enabled += " AND NOT " + fire[u];
            }
            line(tr.at, fire[t] + " := " + enabled + " AND (" + expr + ");", tr.label);
            done.push_back(t);
        }
        // 4. Deactivate, then activate.
        for (size_t t : order) {
            std::string s;
            for (int st : c.transitions[t].pre) s += stepName(st) + ".X := FALSE; " + stepName(st) + "._X := FALSE; ";
            line(c.transitions[t].at, "IF " + fire[t] + " THEN " + s + "END_IF;", c.transitions[t].label);
        }
        for (size_t t : order) {
            std::string s;
            for (int st : c.transitions[t].post) {
                const std::string& n = stepName(st);
                s += n + ".X := TRUE; " + n + "._X := TRUE; " + n + ".START := TIME(); " + n + ".T := T#0s; " + n + "._T := T#0s; ";
            }
            line(c.transitions[t].at, "IF " + fire[t] + " THEN " + s + "END_IF;", c.transitions[t].label);
        }
        if (c.sfcInit) line(c.steps[0].at, "END_IF;", "");
        if (c.sfcPause) line(c.steps[0].at, "END_IF;", "");
    }
};

}  // namespace

void writeSfcAction(const SfcChart::Action& action, const std::string& prefix, plcopen::Translation& out) {
    SfcChart alone;
    alone.actions.push_back(action);
    Writer w{alone, prefix, out};
    w.action(0);
}

bool writeSfcChart(const SfcChart& chart, const std::string& prefix, plcopen::Translation& out,
                   const std::function<void(SfcChart::Where, const std::string&)>& fail) {
    Writer w{chart, prefix, out};
    if (!w.reachable(fail)) return false;
    w.write();
    return true;
}

}  // namespace strun::source
