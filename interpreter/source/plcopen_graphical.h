// LD, FBD and SFC bodies of PLCopen TC6 XML, translated to ST (docs/graphical.md).
// A graphical body becomes ST statements that the ST parser and checker read
// like any other body, so the runtime rules, diagnostics, tracing and tests
// of ST apply unchanged; every generated line points at the XML element it
// comes from and names it (`rung 3, contact 'bStart'`, `block 12 (TON)`,
// `step 'Fill'`). Variables the translation needs (temporaries, edge
// detectors, step states, action control) are declared in one extra VAR
// section of the POU.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "interpreter/source/xml_conversion.h"

namespace strun::source::plcopen {

// One line of generated ST: written by strun for an element (`verbatim`
// false), or ST copied from the XML (an inline SFC condition or action body).
// Put before the declaration of a variable the translation needs for itself
// (temporaries, edge detectors, transition flags, action control): the
// checker marks it hidden, so --dump, --vcd, --watch and the live API leave
// it out (docs/graphical.md). Steps are declared without it.
inline constexpr const char* kHiddenPragma = "{attribute 'strun_hidden'} ";

struct StLine {
    std::string text;
    int line = 1, col = 1;
    std::string element;  // what diagnostics on this line name; empty: nothing
    bool verbatim = false;
};

// What a translation knows about the project around the body (names upper case).
struct ProjectTypes {
    std::map<std::string, std::string> globals;                             // global variable -> type text
    std::map<std::string, std::string> functionResults;                     // user FUNCTION -> result type
    std::map<std::string, std::vector<std::string>> functionInputs;         // user FUNCTION -> its input names in order
    std::map<std::string, std::map<std::string, std::string>> blockOutputs;  // user FUNCTION_BLOCK -> output -> type
};

struct PouContext {
    const ProjectTypes* project = nullptr;
    std::string pouName;
    std::map<std::string, std::string> variables;  // the POU's variables (upper case) -> type text
    std::set<std::string> actions;                 // the POU's actions (upper case)
    std::map<std::string, pugi::xml_node> transitions;  // the POU's named transitions (upper case) -> <transition>
    int bodies = 0;                                // bodies translated so far (names of hidden variables)

    // The type of a variable of the POU or a global (upper-case lookup), or "".
    std::string typeOf(const std::string& name) const;
    // True when the variable `name` is an instance of a standard or user function block.
    bool isBlockInstance(const std::string& name) const;
};

// Generated ST of one body, and the hidden variables it declares.
struct Translation {
    std::vector<StLine> body;
    std::vector<StLine> declarations;
};

// An LD or FBD network (<LD>/<FBD> element) as ST statements.
void translateNetwork(XmlConversion& conv, const pugi::xml_node& lang, bool ld, PouContext& ctx, Translation& out);

// Transition conditions drawn as LD/FBD networks inside an SFC body: each
// condition's value is written to `variable`.
struct ChartCondition {
    pugi::xml_node transition;
    pugi::xml_node pointIn;  // the condition's <connectionPointIn>
    std::string variable;
    std::string label;
};
void translateChartConditions(XmlConversion& conv, const pugi::xml_node& sfc, PouContext& ctx, const std::vector<ChartCondition>& conditions,
                              Translation& out);

// An action block in an LD/FBD body: each of its actions runs under the
// action control of IEC 61131-3 with `activity` (the block's power flow or
// input) in the place of a step's X. Hidden variables are named from
// `prefix`; messages start with `where`.
void translateActionBlock(XmlConversion& conv, const pugi::xml_node& block, const std::string& activity, const std::string& prefix,
                          const std::string& where, PouContext& ctx, Translation& out);

// An SFC chart (<SFC> element) as ST statements.
void translateChart(XmlConversion& conv, const pugi::xml_node& lang, PouContext& ctx, Translation& out);

// The ST of <ST> / <inline><ST> ... text: copied with its XML positions.
void copyStText(XmlConversion& conv, const pugi::xml_node& n, const std::string& element, std::vector<StLine>& out, int depth = 0);

}  // namespace strun::source::plcopen
