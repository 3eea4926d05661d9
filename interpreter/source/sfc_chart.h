// An SFC chart, however it was written (PLCopen XML: plcopen_sfc.cpp;
// textual SFC in ST: st_textual_sfc.cpp), and its translation to ST
// (docs/graphical.md, decision 0232). Every step becomes a variable of type
// __SFC_STEP (stdlib/st/sfc.st); one evaluation of the chart runs the step
// times, the action control and the actions (with their final scan), then
// the transitions, then deactivates and activates steps.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "interpreter/source/plcopen_graphical.h"

namespace strun::source {

struct SfcChart {
    struct Where {
        int line = 1, col = 1;
    };
    struct Step {
        std::string name;
        bool initial = false;
        Where at;
    };
    struct Transition {
        std::vector<int> pre, post;             // steps (indices)
        std::vector<plcopen::StLine> before;    // statements run first (a named transition's body)
        std::vector<plcopen::StLine> condition; // the condition's lines (copied ST), or empty ...
        std::string expr;                       // ... and then this expression
        double x = 0;                           // leftmost first among alternatives
        int priority = 0;                       // smaller first when both have one
        std::string id;                         // unique among the chart's transitions (hidden variable names)
        std::string label;
        Where at;
    };
    struct Association {
        int step = -1;
        std::string activity;  // instead of the step's X: what activates it (an action block's power flow in LD/FBD)
        std::string qualifier = "N";
        std::string duration;  // an IEC literal
    };
    struct Action {
        std::string name;                  // empty: inline
        bool isVariable = false;           // a BOOL variable: it is Q
        std::vector<plcopen::StLine> body;  // inline ST
        std::vector<Association> uses;
        std::string label;
        Where at;
    };
    std::vector<Step> steps;
    std::vector<plcopen::StLine> conditionNetworks;  // evaluated before the transitions
    std::vector<Transition> transitions;
    std::vector<Action> actions;
    // CODESYS' implicit SFC flags, used when the POU declares them (BOOL):
    // SFCInit resets the chart to its initial steps and holds it there,
    // SFCReset resets it and goes on, SFCPause freezes it (decision 0293).
    bool sfcInit = false, sfcReset = false, sfcPause = false;
};

// Writes one action (its action control, the call and the final scan) whose
// associations all have an `activity`: an action block of an LD/FBD body.
// Hidden variables are named from `prefix`.
void writeSfcAction(const SfcChart::Action& action, const std::string& prefix, plcopen::Translation& out);

// Checks the chart (an initial step, every step reachable) and writes it;
// problems go to `fail` with the position of the element. False on errors.
bool writeSfcChart(const SfcChart& chart, const std::string& prefix, plcopen::Translation& out,
                   const std::function<void(SfcChart::Where, const std::string&)>& fail);

}  // namespace strun::source
