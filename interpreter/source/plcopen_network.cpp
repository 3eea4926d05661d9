// LD and FBD networks of PLCopen TC6 XML as ST (docs/graphical.md, decisions
// 0230-0232). Every element is read into a graph of connections; the
// elements that act (coils, output variables, blocks, jumps, returns, labels)
// are visited in execution order (executionOrderId when every one has it,
// else rung/network top to bottom, then top to bottom, left to right), and
// each is written as ST after what it reads (data-flow order). Power flow is
// BOOL: a contact is `in AND v`, wired branches are OR. A value read in more
// than one place, an edge, a block with EN or on a feedback loop is kept in a
// hidden variable; other function blocks are written inline as operators or
// calls, so the ST is as fast as the same logic written by hand.
#include <algorithm>
#include <cctype>
#include <climits>
#include <functional>
#include <map>
#include <numeric>

#include "interpreter/source/plcopen_graphical.h"
#include "interpreter/source/plcopen_xml.h"
#include "stdlib/number_scan.h"

namespace strun::source::plcopen {

namespace {

enum class Kind { InVar, OutVar, InOutVar, Block, Connector, Continuation, Label, Jump, Return, LeftRail, RightRail, Contact, Coil, ActionBlock };

struct Conn {
    int ref = 0;
    std::string param;  // formalParameter of the source's output ("" = its only output)
};

struct PinIn {
    std::string name;
    bool negated = false;
    std::string edge;  // "", "rising", "falling"
    std::vector<Conn> conns;
};

struct PinOut {
    std::string name;
    bool negated = false;
};

struct Element {
    Kind kind = Kind::InVar;
    int id = 0;
    pugi::xml_node node;
    std::string text;      // expression, variable, label target, block type
    std::string instance;  // FB instance name
    bool negated = false;
    std::string edge, storage;
    std::vector<PinIn> ins, inouts;
    std::vector<PinOut> outs;
    double x = 0, y = 0;
    int order = 0;  // executionOrderId, 0: none
    int network = 0;
    std::string label;
    // Translation state.
    bool fb = false, stdFunction = false, materialized = false, trigger = false;
    int state = 0;  // 0 not written, 1 being written, 2 written
};

std::string prefixedEdge(const pugi::xml_node& n, const char* attr) {
    std::string e = n.attribute(attr).value();
    return e == "none" ? "" : e;
}

std::vector<Conn> connectionsOf(const pugi::xml_node& pointIn) {
    std::vector<Conn> out;
    for (pugi::xml_node c : children(pointIn, "connection")) out.push_back({c.attribute("refLocalId").as_int(), c.attribute("formalParameter").value()});
    return out;
}

const std::set<std::string>& standardBlocks() {
    static const std::set<std::string> fbs = {"TON", "TOF", "TP", "TON_LTIME", "TOF_LTIME", "TP_LTIME", "CTU", "CTD", "CTUD", "CTU_INT", "CTD_INT",
                                              "CTUD_INT", "CTU_DINT", "CTD_DINT", "CTUD_DINT", "CTU_UDINT", "CTD_UDINT", "CTUD_UDINT",
                                              "CTU_LINT", "CTD_LINT", "CTUD_LINT", "CTU_ULINT", "CTD_ULINT", "CTUD_ULINT", "R_TRIG", "F_TRIG",
                                              "SR", "RS", "RTC"};
    return fbs;
}

// Output types of the standard function blocks, for a function temporary fed by one.
std::string standardBlockOutputType(const std::string& type, const std::string& pin) {
    const std::string t = stdlib::upperAscii(type), p = stdlib::upperAscii(pin);
    if (p == "Q" || p == "Q1" || p == "QU" || p == "QD") return "BOOL";
    if (p == "ET") return t.find("LTIME") != std::string::npos ? "LTIME" : "TIME";
    if (p == "CV") {
        size_t u = t.find('_');
        return u == std::string::npos ? "INT" : t.substr(u + 1);
    }
    if (p == "CDT") return "DT";
    return "";
}

// The declared type of an expression of a variable block (a name, a member,
// an element, a literal), as far as it can be told without the checker.
std::string literalType(const std::string& e) {
    const std::string u = stdlib::upperAscii(e);
    if (u == "TRUE" || u == "FALSE") return "BOOL";
    size_t hash = u.find('#');
    if (hash != std::string::npos) {
        std::string head = u.substr(0, hash);
        if (head == "T" || head == "TIME") return "TIME";
        if (head == "LT" || head == "LTIME") return "LTIME";
        if (head == "D" || head == "DATE") return "DATE";
        if (head == "TOD" || head == "TIME_OF_DAY") return "TIME_OF_DAY";
        if (head == "DT" || head == "DATE_AND_TIME") return "DATE_AND_TIME";
        if (!head.empty() && !std::isdigit(static_cast<unsigned char>(head[0]))) return head;  // INT#5, REAL#1.5
    }
    if (!u.empty() && (u[0] == '\'')) return "STRING";
    if (!u.empty() && (u[0] == '"')) return "WSTRING";
    return "";
}

bool isSimpleName(const std::string& e) {
    if (e.empty() || !(std::isalpha(static_cast<unsigned char>(e[0])) || e[0] == '_')) return false;
    for (char c : e)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.')) return false;
    return true;
}

struct Network {
    XmlConversion& conv;
    PouContext& ctx;
    Translation& out;
    bool ld;
    std::string prefix;  // of hidden variables: _g<body>_
    std::vector<Element> els;
    std::map<int, int> byId;                     // localId -> index
    std::map<std::string, int> connectors;       // name (upper) -> index
    std::map<std::pair<int, std::string>, int> uses;  // (index, output upper) -> number of readers
    std::vector<StLine> lines;
    bool explicitOrder = false;
    int currentRoot = -1;
    bool failed = false;
    bool inChart = false;  // the LD/FBD elements of an SFC body: its SFC elements are skipped
    std::map<std::string, int> actionBlockOf;  // action (upper) -> the action block that uses it

    Network(XmlConversion& c, PouContext& x, Translation& o, bool isLd) : conv(c), ctx(x), out(o), ld(isLd) {
        prefix = "_g" + std::to_string(++ctx.bodies) + "_";
    }

    // The start of every message: which body (E0008).
    std::string where() const {
        return inChart ? "in the SFC chart of '" + ctx.pouName + "': " : std::string("in the ") + (ld ? "LD" : "FBD") + " body of '" + ctx.pouName + "': ";
    }

    // --- reading --------------------------------------------------------

    void readPosition(Element& e) {
        pugi::xml_node p = child(e.node, "position");
        e.x = p.attribute("x").as_double();
        e.y = p.attribute("y").as_double();
        e.order = e.node.attribute("executionOrderId").as_int();
    }

    PinIn pinIn(const pugi::xml_node& v) {
        PinIn p;
        p.name = v.attribute("formalParameter").value();
        p.negated = v.attribute("negated").as_bool();
        p.edge = prefixedEdge(v, "edge");
        p.conns = connectionsOf(child(v, "connectionPointIn"));
        return p;
    }

    void read(const pugi::xml_node& lang) {
        for (pugi::xml_node n : lang.children()) {
            if (n.type() != pugi::node_element) continue;
            const std::string k = localName(n);
            Element e;
            e.node = n;
            e.id = n.attribute("localId").as_int();
            readPosition(e);
            if (k == "inVariable" || k == "outVariable" || k == "inOutVariable") {
                e.kind = k == "inVariable" ? Kind::InVar : k == "outVariable" ? Kind::OutVar : Kind::InOutVar;
                e.text = textOf(child(n, "expression"));
                e.negated = n.attribute(k == "inOutVariable" ? "negatedOut" : "negated").as_bool();
                e.edge = prefixedEdge(n, k == "inOutVariable" ? "edgeIn" : "edge");
                e.storage = prefixedEdge(n, k == "inOutVariable" ? "storageIn" : "storage");
                if (k != "inVariable") e.ins.push_back({"", k == "inOutVariable" ? n.attribute("negatedIn").as_bool() : false, "", connectionsOf(child(n, "connectionPointIn"))});
                e.label = "variable '" + e.text + "'";
                if (e.text.empty()) {
                    conv.error(n, where() + k + " " + std::to_string(e.id) + " has no expression");
                    failed = true;
                }
            } else if (k == "block") {
                e.kind = Kind::Block;
                e.text = n.attribute("typeName").value();
                e.instance = n.attribute("instanceName").value();
                for (pugi::xml_node v : children(child(n, "inputVariables"), "variable")) e.ins.push_back(pinIn(v));
                for (pugi::xml_node v : children(child(n, "inOutVariables"), "variable")) e.inouts.push_back(pinIn(v));
                for (pugi::xml_node v : children(child(n, "outputVariables"), "variable"))
                    e.outs.push_back({v.attribute("formalParameter").value(), v.attribute("negated").as_bool()});
                e.label = "block " + std::to_string(e.id) + " (" + e.text + ")";
            } else if (k == "connector" || k == "continuation") {
                e.kind = k == "connector" ? Kind::Connector : Kind::Continuation;
                e.text = n.attribute("name").value();
                if (k == "connector") e.ins.push_back({"", false, "", connectionsOf(child(n, "connectionPointIn"))});
                e.label = k + " '" + e.text + "'";
            } else if (k == "label") {
                e.kind = Kind::Label;
                e.text = n.attribute("label").value();
                e.label = "label '" + e.text + "'";
            } else if (k == "jump") {
                e.kind = Kind::Jump;
                e.text = n.attribute("label").value();
                e.ins.push_back({"", false, "", connectionsOf(child(n, "connectionPointIn"))});
                e.label = "jump to '" + e.text + "'";
            } else if (k == "return") {
                e.kind = Kind::Return;
                e.ins.push_back({"", false, "", connectionsOf(child(n, "connectionPointIn"))});
                e.label = "return";
            } else if (k == "leftPowerRail" || k == "rightPowerRail") {
                e.kind = k == "leftPowerRail" ? Kind::LeftRail : Kind::RightRail;
                e.label = k == "leftPowerRail" ? "left power rail" : "right power rail";
            } else if (k == "contact" || k == "coil") {
                e.kind = k == "contact" ? Kind::Contact : Kind::Coil;
                e.text = textOf(child(n, "variable"));
                e.negated = n.attribute("negated").as_bool();
                e.edge = prefixedEdge(n, "edge");
                e.storage = prefixedEdge(n, "storage");
                e.ins.push_back({"", false, "", connectionsOf(child(n, "connectionPointIn"))});
                e.label = k + " '" + e.text + "'";
                if (e.text.empty()) {
                    conv.error(n, where() + k + " " + std::to_string(e.id) + " names no variable");
                    failed = true;
                }
            } else if (k == "actionBlock" && !inChart) {
                // Actions activated by the power flow (LD) or a BOOL input (FBD) instead of a step.
                e.kind = Kind::ActionBlock;
                e.ins.push_back({"", false, "", connectionsOf(child(n, "connectionPointIn"))});
                e.label = "action block " + std::to_string(e.id);
                // Each action block has its own action control: one action, one block (decision 0291).
                for (pugi::xml_node a : children(n, "action")) {
                    const std::string name = child(a, "reference").attribute("name").value();
                    if (name.empty()) continue;
                    auto [it, added] = actionBlockOf.emplace(stdlib::upperAscii(name), e.id);
                    if (!added && it->second != e.id) {
                        conv.error(a, where() + "action '" + name + "' is used by action blocks " + std::to_string(it->second) + " and " +
                                          std::to_string(e.id) + "; in LD/FBD an action may be used by one action block only");
                        failed = true;
                    }
                }
            } else if (k == "comment" || k == "error" || k == "documentation" || k == "addData") {
                continue;
            } else if (inChart && (k == "step" || k == "transition" || k == "selectionDivergence" || k == "selectionConvergence" ||
                                   k == "simultaneousDivergence" || k == "simultaneousConvergence" || k == "jumpStep" ||
                                   k == "actionBlock" || k == "macroStep")) {
                continue;
            } else {
                conv.error(n, where() + "the " + k + " element " + std::to_string(e.id) + " is not supported in " +
                                  (ld ? "LD" : "FBD") + " bodies (docs/graphical.md)");
                failed = true;
                continue;
            }
            if (!n.attribute("localId")) {
                conv.error(n, where() + "the " + k + " element has no localId (PLCopen TC6 requires one)");
                failed = true;
                continue;
            }
            if (byId.count(e.id)) {
                conv.error(n, where() + "two elements have localId " + std::to_string(e.id));
                failed = true;
                continue;
            }
            byId[e.id] = static_cast<int>(els.size());
            if (e.kind == Kind::Connector) connectors[stdlib::upperAscii(e.text)] = static_cast<int>(els.size());
            els.push_back(std::move(e));
        }
    }

    // --- structure --------------------------------------------------------

    int find(int id) const {
        auto it = byId.find(id);
        return it == byId.end() ? -1 : it->second;
    }

    // Checks every connection, counts the readers of each output, and numbers the
    // networks (rungs): connected parts ordered top to bottom.
    void link() {
        std::vector<int> parent(els.size());
        std::iota(parent.begin(), parent.end(), 0);
        std::function<int(int)> root = [&](int i) { return parent[i] == i ? i : parent[i] = root(parent[i]); };
        for (size_t i = 0; i < els.size(); ++i) {
            Element& e = els[i];
            auto check = [&](std::vector<PinIn>& pins) {
                for (PinIn& p : pins)
                    for (Conn& c : p.conns) {
                        int src = find(c.ref);
                        if (src < 0) {
                            conv.error(e.node, where() + e.label + " is connected to element " + std::to_string(c.ref) +
                                                   ", which the body does not have");
                            failed = true;
                            continue;
                        }
                        ++uses[{src, stdlib::upperAscii(c.param)}];
                        parent[root(src)] = root(static_cast<int>(i));
                    }
            };
            check(e.ins);
            check(e.inouts);
            if (e.kind == Kind::Continuation && !connectors.count(stdlib::upperAscii(e.text))) {
                conv.error(e.node, where() + "continuation '" + e.text + "' has no connector of that name");
                failed = true;
            }
        }
        // Networks: ordered by their topmost element, then leftmost.
        std::map<int, std::pair<double, double>> top;
        for (size_t i = 0; i < els.size(); ++i) {
            auto [it, added] = top.emplace(root(static_cast<int>(i)), std::pair<double, double>{els[i].y, els[i].x});
            if (!added) it->second = std::min(it->second, std::pair<double, double>{els[i].y, els[i].x});
        }
        std::vector<std::pair<std::pair<double, double>, int>> order;
        for (auto& [r, pos] : top) order.push_back({pos, r});
        std::sort(order.begin(), order.end());
        std::map<int, int> number;
        for (size_t k = 0; k < order.size(); ++k) number[order[k].second] = static_cast<int>(k) + 1;
        for (size_t i = 0; i < els.size(); ++i) {
            els[i].network = number[root(static_cast<int>(i))];
            if (ld) els[i].label = "rung " + std::to_string(els[i].network) + ", " + els[i].label;
        }
    }

    int totalReaders(int i) const {
        int n = 0;
        for (const auto& [key, count] : uses)
            if (key.first == i) n += count;
        return n;
    }

    // Decides what is kept in a variable: FB calls, functions with EN, read
    // more than once, with outputs besides the result, or on a loop; LD
    // elements read in several places; edges.
    void classify() {
        for (Element& e : els) {
            if (e.kind != Kind::Block) continue;
            const std::string t = stdlib::upperAscii(e.text);
            e.fb = !e.instance.empty() || standardBlocks().count(t) || ctx.project->blockOutputs.count(t);
            e.stdFunction = !e.fb && !ctx.project->functionResults.count(t);
        }
        for (size_t i = 0; i < els.size(); ++i) {
            Element& e = els[i];
            if (e.kind == Kind::Block && !e.fb) {
                bool en = false;
                for (const PinIn& p : e.ins)
                    if (stdlib::upperAscii(p.name) == "EN" && !p.conns.empty() && !fromRailOnly(p)) en = true;
                int results = 0;
                for (const auto& [key, count] : uses)
                    if (key.first == static_cast<int>(i) && key.second != "ENO") {
                        bool isResult = key.second.empty() || key.second == "OUT" || (e.outs.size() >= 1 && stdlib::upperAscii(e.outs[0].name) == key.second);
                        results += isResult ? count : 1000;
                    }
                e.materialized = en || results > 1;
                for (const PinIn& p : e.ins)
                    if (!p.edge.empty()) e.materialized = true;
            }
            if ((e.kind == Kind::Contact || e.kind == Kind::Coil) && totalReaders(static_cast<int>(i)) > 1) e.materialized = true;
            if (e.kind == Kind::Contact && !e.edge.empty()) e.trigger = true;
        }
        // Loops through elements written inline: the first element met twice is kept in a variable.
        std::vector<int> mark(els.size(), 0);
        std::function<void(int)> visit = [&](int i) {
            mark[i] = 1;
            for (const PinIn& p : allInputs(els[i]))
                for (const Conn& c : p.conns) {
                    int s = resolve(c);
                    // FB instances and in-out variables hold their value: a loop through them reads the previous one.
                    if (s < 0 || (els[s].kind == Kind::Block && els[s].fb) || els[s].kind == Kind::InOutVar) continue;
                    if (mark[s] == 1) {
                        els[s].materialized = true;
                        if (els[s].kind != Kind::Block && els[s].kind != Kind::Contact && els[s].kind != Kind::Coil) {
                            conv.error(els[s].node, where() + els[s].label + " is part of a loop without a block to hold its value");
                            failed = true;
                        }
                    } else if (mark[s] == 0) {
                        visit(s);
                    }
                }
            mark[i] = 2;
        };
        for (size_t i = 0; i < els.size(); ++i)
            if (mark[i] == 0) visit(static_cast<int>(i));
    }

    std::vector<PinIn> allInputs(const Element& e) const {
        std::vector<PinIn> all = e.ins;
        all.insert(all.end(), e.inouts.begin(), e.inouts.end());
        if (e.kind == Kind::Continuation) {
            auto it = connectors.find(stdlib::upperAscii(e.text));
            if (it != connectors.end()) all.push_back({"", false, "", {{els[it->second].id, ""}}});
        }
        return all;
    }

    // The element a connection reads from (continuations stay: they are resolved when read).
    int resolve(const Conn& c) const { return find(c.ref); }

    bool fromRailOnly(const PinIn& p) const {
        for (const Conn& c : p.conns) {
            int s = find(c.ref);
            if (s < 0 || els[s].kind != Kind::LeftRail) return false;
        }
        return !p.conns.empty();
    }

    // --- writing ------------------------------------------------------------

    // Switches the origin of the following ST text to element i (its XML line; its name in diagnostics).
    std::string at(int i) const { return "\x1f" + std::to_string(i) + "\x1e"; }

    std::string hidden(int i, const std::string& what) const {
        return prefix + std::to_string(els[i].id) + (what.empty() ? "" : "_" + what);
    }

    void declare(int i, const std::string& name, const std::string& type) {
        auto [line, col] = conv.where(els[i].node);
        out.declarations.push_back({"    " + std::string(kHiddenPragma) + name + " : " + type + ";", line, col, els[i].label, false});
    }

    // Writes element i's statement (and first the statements it reads) unless
    // it is being written (a loop: its variable holds the value of the
    // previous evaluation) or comes later in an explicit order.
    void require(int i) {
        Element& e = els[i];
        if (e.state != 0) return;
        if (explicitOrder && currentRoot >= 0 && e.order > 0 && e.order > els[currentRoot].order &&
            (e.fb || e.materialized))
            return;
        emit(i);
    }

    static std::string negate(const std::string& v) { return "NOT (" + v + ")"; }

    // The value of an input pin: one connection, or (LD) the OR of several.
    std::string inputValue(const PinIn& p, bool& connected) {
        connected = !p.conns.empty();
        if (!connected) return "";
        std::string v;
        for (size_t k = 0; k < p.conns.size(); ++k) {
            std::string one = outputValue(p.conns[k]);
            if (one == "TRUE" && p.conns.size() > 1) return "TRUE";
            v += (k ? " OR " : "") + one;
        }
        if (p.conns.size() > 1) v = "(" + v + ")";
        return v;
    }

    std::string powerIn(const Element& e) {
        bool connected = false;
        std::string v = inputValue(e.ins[0], connected);
        return connected ? v : "FALSE";
    }

    // The value of output `c.param` of element c.ref.
    std::string outputValue(const Conn& c) {
        int i = find(c.ref);
        if (i < 0) return "FALSE";
        Element& e = els[i];
        switch (e.kind) {
            case Kind::LeftRail: return "TRUE";
            case Kind::InVar:
            case Kind::InOutVar: {
                std::string v = at(i) + e.text;
                if (e.kind == Kind::InOutVar) require(i);
                return e.negated ? negate(v) : v;
            }
            case Kind::Continuation: {
                auto it = connectors.find(stdlib::upperAscii(e.text));
                if (it == connectors.end()) return "FALSE";
                bool connected = false;
                std::string v = inputValue(els[it->second].ins[0], connected);
                return connected ? v : "FALSE";
            }
            case Kind::Contact:
            case Kind::Coil:
                if (e.materialized) {
                    require(i);
                    return hidden(i, "");
                }
                return powerFlow(i);
            case Kind::Block: return blockOutput(i, c.param);
            case Kind::ActionBlock:
                require(i);
                return hidden(i, "");
            default: return "FALSE";
        }
    }

    // What passes through a contact or a coil.
    std::string powerFlow(int i) {
        Element& e = els[i];
        std::string in = powerIn(e);
        if (e.kind == Kind::Coil) return in;
        std::string term;
        if (e.trigger) {
            require(i);  // the edge detector's call
            term = hidden(i, "trig") + ".Q";
        } else {
            term = e.text;
        }
        if (e.negated) term = "NOT " + term;
        term = at(i) + term;
        return in == "TRUE" ? term : "(" + in + " AND " + term + ")";
    }

    bool pinIsResult(const Element& e, const std::string& pin) const {
        const std::string p = stdlib::upperAscii(pin);
        if (p.empty() || p == "OUT") return true;
        return !e.outs.empty() && stdlib::upperAscii(e.outs[0].name) == p && !e.fb;
    }

    std::string enValue(int i, bool& hasEn) {
        hasEn = false;
        for (const PinIn& p : els[i].ins)
            if (stdlib::upperAscii(p.name) == "EN") {
                bool connected = false;
                std::string v = inputValue(p, connected);
                if (connected) {
                    hasEn = v != "TRUE";
                    return v;
                }
            }
        return "TRUE";
    }

    std::string blockOutput(int i, const std::string& pin) {
        Element& e = els[i];
        const std::string p = stdlib::upperAscii(pin);
        bool negated = false;
        for (const PinOut& o : e.outs)
            if (stdlib::upperAscii(o.name) == p || (p.empty() && &o == &e.outs.front())) negated = o.negated;
        std::string v;
        if (p == "ENO") {
            bool hasEn = false;
            require(i);
            v = enValue(i, hasEn);
        } else if (e.fb) {
            require(i);
            std::string outName = pin.empty() && !e.outs.empty() ? e.outs[0].name : pin;
            v = at(i) + instanceName(i) + "." + outName;
        } else if (e.materialized) {
            require(i);
            v = at(i) + hidden(i, pinIsResult(e, pin) ? "OUT" : pin);
        } else {
            e.state = 2;  // written here, inline
            v = callText(i);
        }
        return negated ? negate(v) : v;
    }

    std::string instanceName(int i) const {
        return els[i].instance.empty() ? hidden(i, "fb") : els[i].instance;
    }

    // The value passed to one input of a block (negation and edges applied).
    std::string argument(int i, const PinIn& p, size_t k, bool& connected) {
        std::string v = inputValue(p, connected);
        if (!connected) return "";
        if (!p.edge.empty()) {
            std::string trig = hidden(i, "edge" + std::to_string(k));
            declare(i, trig, p.edge == "falling" ? "F_TRIG" : "R_TRIG");
            // Written before the statement that reads it (write() puts it first).
            pendingTriggers.push_back(at(i) + trig + "(CLK := " + v + ");");
            v = trig + ".Q";
        }
        return p.negated ? negate(v) : v;
    }
    std::vector<std::string> pendingTriggers;

    // A function block written as an operator or a call (its inputs in XML order).
    std::string callText(int i) {
        Element& e = els[i];
        const std::string t = stdlib::upperAscii(e.text);
        std::vector<std::string> args;
        std::vector<std::string> names;
        for (size_t k = 0; k < e.ins.size(); ++k) {
            const PinIn& p = e.ins[k];
            if (stdlib::upperAscii(p.name) == "EN") continue;
            bool connected = false;
            std::string v = argument(i, p, k, connected);
            if (!connected) {
                if (e.stdFunction) {
                    conv.error(e.node, where() + "input '" + p.name + "' of " + e.label + " is not connected");
                    failed = true;
                }
                continue;
            }
            args.push_back(v);
            names.push_back(p.name);
        }
        static const std::map<std::string, std::string> infix = {{"ADD", " + "}, {"MUL", " * "}, {"SUB", " - "}, {"DIV", " / "},
                                                                 {"MOD", " MOD "}, {"EXPT", " ** "}, {"AND", " AND "}, {"OR", " OR "},
                                                                 {"XOR", " XOR "}};
        static const std::map<std::string, std::string> compare = {{"GT", " > "}, {"GE", " >= "}, {"EQ", " = "}, {"LE", " <= "}, {"LT", " < "}, {"NE", " <> "}};
        std::string s;
        if (e.stdFunction && infix.count(t) && args.size() >= 2) {
            // The operator stands on the block's line: a fault of the operation (DIV_BY_ZERO) names the block.
            for (size_t k = 0; k < args.size(); ++k) s += (k ? at(i) + infix.at(t) : "") + args[k];
            return at(i) + "(" + s + ")";
        }
        if (e.stdFunction && compare.count(t) && args.size() >= 2) {
            for (size_t k = 0; k + 1 < args.size(); ++k) s += (k ? " AND " : "") + std::string("(") + args[k] + at(i) + compare.at(t) + args[k + 1] + ")";
            return at(i) + (args.size() > 2 ? "(" + s + ")" : s);
        }
        if (e.stdFunction && t == "NOT" && args.size() == 1) return at(i) + negate(args[0]);
        if (e.stdFunction && t == "MOVE" && args.size() == 1) return at(i) + args[0];
        for (size_t k = 0; k < args.size(); ++k) {
            s += k ? ", " : "";
            if (!e.stdFunction) s += names[k] + " := ";
            s += args[k];
        }
        return at(i) + e.text + "(" + s + ")";
    }

    // --- type of a function's temporary -------------------------------------

    std::string expressionType(const std::string& text) const {
        std::string t = literalType(text);
        if (!t.empty() || !isSimpleName(text)) return t;
        size_t dot = text.find('.');
        std::string base = dot == std::string::npos ? text : text.substr(0, dot);
        std::string type = ctx.typeOf(base);
        if (dot == std::string::npos) return type;
        // inst.OUT of a function block instance
        std::string member = text.substr(dot + 1);
        auto fb = ctx.project->blockOutputs.find(stdlib::upperAscii(type));
        if (fb != ctx.project->blockOutputs.end()) {
            auto o = fb->second.find(stdlib::upperAscii(member));
            if (o != fb->second.end()) return o->second;
        }
        if (standardBlocks().count(stdlib::upperAscii(type))) return standardBlockOutputType(type, member);
        return "";
    }

    std::string connectionType(const Conn& c, int depth) {
        int i = find(c.ref);
        if (i < 0 || depth > 64) return "";
        Element& e = els[i];
        switch (e.kind) {
            case Kind::InVar:
            case Kind::InOutVar: return expressionType(e.text);
            case Kind::LeftRail:
            case Kind::Contact:
            case Kind::Coil: return "BOOL";
            case Kind::Continuation: {
                auto it = connectors.find(stdlib::upperAscii(e.text));
                if (it == connectors.end() || els[it->second].ins[0].conns.empty()) return "";
                return connectionType(els[it->second].ins[0].conns[0], depth + 1);
            }
            case Kind::Block: return blockType(i, c.param, depth + 1);
            default: return "";
        }
    }

    std::string blockType(int i, const std::string& pin, int depth) {
        Element& e = els[i];
        const std::string t = stdlib::upperAscii(e.text), p = stdlib::upperAscii(pin);
        if (p == "ENO") return "BOOL";
        if (e.fb) {
            std::string type = e.instance.empty() ? e.text : ctx.typeOf(e.instance);
            auto fb = ctx.project->blockOutputs.find(stdlib::upperAscii(type));
            if (fb != ctx.project->blockOutputs.end() && fb->second.count(p)) return fb->second.at(p);
            return standardBlockOutputType(type.empty() ? e.text : type, pin);
        }
        auto user = ctx.project->functionResults.find(t);
        if (user != ctx.project->functionResults.end()) return user->second;
        static const std::set<std::string> booleans = {"GT", "GE", "EQ", "LE", "LT", "NE"};
        if (booleans.count(t)) return "BOOL";
        size_t to = t.find("_TO_");
        if (to != std::string::npos) return t.substr(to + 4);
        if (t.rfind("TO_", 0) == 0) return t.substr(3);
        if (t == "TRUNC") return "DINT";
        if (t == "LEN" || t == "FIND") return "INT";
        if (t == "CONCAT" || t == "LEFT" || t == "RIGHT" || t == "MID" || t == "INSERT" || t == "DELETE" || t == "REPLACE") return "STRING";
        if (t == "SUB") {
            // The difference of two dates or times of day is a duration (IEC 61131-3
            // table 30: SUB_DT_DT, SUB_DATE_DATE, SUB_TOD_TOD): not the type of IN1 (C21).
            // Each name of a date type -> (its one spelling, the type of a difference of two).
            static const std::map<std::string, std::pair<std::string, std::string>> dates = {
                {"DT", {"DT", "TIME"}},     {"DATE_AND_TIME", {"DT", "TIME"}},     {"DATE", {"DATE", "TIME"}},   {"TOD", {"TOD", "TIME"}},
                {"TIME_OF_DAY", {"TOD", "TIME"}}, {"LDT", {"LDT", "LTIME"}},       {"LDATE_AND_TIME", {"LDT", "LTIME"}},
                {"LDATE", {"LDATE", "LTIME"}},    {"LTOD", {"LTOD", "LTIME"}},     {"LTIME_OF_DAY", {"LTOD", "LTIME"}}};
            auto in1 = dates.find(typeOfInput(e, 0, depth)), in2 = dates.find(typeOfInput(e, 1, depth));
            if (in1 != dates.end() && in2 != dates.end() && in1->second.first == in2->second.first) return in1->second.second;
        }
        // The type of the first typed input (SEL, MUX and LIMIT: of the values, not the selector).
        size_t first = (t == "SEL" || t == "MUX" || t == "LIMIT") ? 1 : 0;
        size_t n = 0;
        for (const PinIn& in : e.ins) {
            if (stdlib::upperAscii(in.name) == "EN") continue;
            if (n++ < first || in.conns.empty()) continue;
            std::string type = connectionType(in.conns[0], depth + 1);
            if (!type.empty()) return type;
        }
        return "";
    }

    // The type of the n-th input of block e (EN left out, upper case), "" when not known.
    std::string typeOfInput(const Element& e, size_t n, int depth) {
        size_t k = 0;
        for (const PinIn& in : e.ins) {
            if (stdlib::upperAscii(in.name) == "EN") continue;
            if (k++ != n) continue;
            return in.conns.empty() ? "" : stdlib::upperAscii(connectionType(in.conns[0], depth + 1));
        }
        return "";
    }

    // The type a function's result gets from what reads it (an output variable).
    std::string readerType(int i) const {
        for (const Element& r : els)
            if (r.kind == Kind::OutVar || r.kind == Kind::InOutVar)
                for (const Conn& c : r.ins[0].conns)
                    if (find(c.ref) == i) {
                        std::string t = expressionType(r.text);
                        if (!t.empty()) return t;
                    }
        return "";
    }

    // --- statements -----------------------------------------------------------

    void write(int i, std::string text) {
        for (std::string& trig : pendingTriggers) text = trig + " " + text;
        pendingTriggers.clear();
        // Split at the origin switches: every piece its own line, at its element.
        int owner = i;
        size_t pos = 0;
        std::string piece;
        auto flush = [&] {
            size_t b = piece.find_first_not_of(' ');
            if (b != std::string::npos) {
                auto [line, col] = conv.where(els[owner].node);
                lines.push_back({piece.substr(b), line, col, els[owner].label, false});
            }
            piece.clear();
        };
        while (pos < text.size()) {
            if (text[pos] == '\x1f') {
                flush();
                size_t end = text.find('\x1e', pos);
                owner = std::stoi(text.substr(pos + 1, end - pos - 1));
                pos = end + 1;
                continue;
            }
            piece.push_back(text[pos++]);
        }
        flush();
    }

    void emit(int i) {
        Element& e = els[i];
        e.state = 1;
        const int saved = currentRoot;
        if (currentRoot < 0 || !explicitOrder) currentRoot = i;
        std::string s = statement(i);
        currentRoot = saved;
        e.state = 2;
        if (!s.empty()) write(i, s);
    }

    std::string statement(int i) {
        Element& e = els[i];
        switch (e.kind) {
            case Kind::OutVar:
            case Kind::InOutVar: {
                bool connected = false;
                std::string v = inputValue(e.ins[0], connected);
                if (!connected) return "";
                if (e.ins[0].negated || (e.kind == Kind::OutVar && e.negated)) v = negate(v);
                if (e.storage == "set") return "IF " + v + " THEN " + e.text + " := TRUE; END_IF;";
                if (e.storage == "reset") return "IF " + v + " THEN " + e.text + " := FALSE; END_IF;";
                return e.text + " := " + v + ";";
            }
            case Kind::Coil: {
                std::string in = powerIn(e);
                std::string s;
                if (e.materialized) {
                    declare(i, hidden(i, ""), "BOOL");
                    s = hidden(i, "") + " := " + in + "; ";
                    in = hidden(i, "");
                }
                if (e.edge == "rising" || e.edge == "falling") {
                    std::string trig = hidden(i, "trig");
                    declare(i, trig, e.edge == "rising" ? "R_TRIG" : "F_TRIG");
                    s += trig + "(CLK := " + in + "); ";
                    in = trig + ".Q";
                }
                if (e.storage == "set") return s + "IF " + in + " THEN " + e.text + " := TRUE; END_IF;";
                if (e.storage == "reset") return s + "IF " + in + " THEN " + e.text + " := FALSE; END_IF;";
                return s + e.text + " := " + (e.negated ? negate(in) : in) + ";";
            }
            case Kind::Contact: {
                std::string s;
                if (e.trigger) {
                    std::string trig = hidden(i, "trig");
                    declare(i, trig, e.edge == "falling" ? "F_TRIG" : "R_TRIG");
                    s = trig + "(CLK := " + e.text + "); ";
                    // The detector sees the variable every evaluation, whatever the power flow (IEC 61131-3 Table 57).
                }
                if (e.materialized) {
                    declare(i, hidden(i, ""), "BOOL");
                    std::string flow = powerFlowAfterTrigger(i);
                    s += hidden(i, "") + " := " + flow + ";";
                }
                return s;
            }
            case Kind::Jump:
            case Kind::Return: {
                bool connected = false;
                std::string v = inputValue(e.ins[0], connected);
                std::string act = e.kind == Kind::Jump ? "JMP " + e.text + ";" : "RETURN;";
                if (!connected) return e.kind == Kind::Jump ? "" : act;
                return v == "TRUE" ? act : "IF " + v + " THEN " + act + " END_IF;";
            }
            case Kind::Label: return e.text + ": ;";
            case Kind::Block: return blockStatement(i);
            case Kind::ActionBlock: {
                // The activity in a hidden BOOL, then the actions' control, calls and final scans.
                declare(i, hidden(i, ""), "BOOL");
                write(i, hidden(i, "") + " := " + powerIn(e) + ";");
                Translation actions;
                translateActionBlock(conv, e.node, hidden(i, ""), hidden(i, "a"), where(), ctx, actions);
                for (StLine& l : actions.body) {
                    if (!l.verbatim) l.element = e.label;  // the control and calls name the block
                    lines.push_back(std::move(l));
                }
                out.declarations.insert(out.declarations.end(), actions.declarations.begin(), actions.declarations.end());
                return "";
            }
            default: return "";
        }
    }

    std::string powerFlowAfterTrigger(int i) {
        Element& e = els[i];
        std::string in = powerIn(e);
        std::string term = e.edge.empty() ? e.text : hidden(i, "trig") + ".Q";
        if (e.negated) term = "NOT " + term;
        term = at(i) + term;
        return in == "TRUE" ? term : "(" + in + " AND " + term + ")";
    }

    std::string blockStatement(int i) {
        Element& e = els[i];
        bool hasEn = false;
        std::string en = enValue(i, hasEn);
        std::string call;
        if (e.fb) {
            if (e.instance.empty()) declare(i, hidden(i, "fb"), e.text);
            std::string s;
            for (size_t k = 0; k < e.ins.size(); ++k) {
                const PinIn& p = e.ins[k];
                if (stdlib::upperAscii(p.name) == "EN") continue;
                bool connected = false;
                std::string v = argument(i, p, k, connected);
                if (connected) s += (s.empty() ? "" : ", ") + p.name + " := " + v;
            }
            for (const PinIn& p : e.inouts) {
                bool connected = false;
                std::string v = inputValue(p, connected);
                if (connected) s += (s.empty() ? "" : ", ") + p.name + " := " + v;
            }
            call = instanceName(i) + "(" + s + ");";
        } else if (e.materialized) {
            std::string type = blockType(i, "", 0);
            if (type.empty()) type = readerType(i);
            if (type.empty()) {
                conv.error(e.node, where() + "cannot tell the type of the result of " + e.label +
                                       "; connect it to a variable or give an input a typed variable or literal");
                failed = true;
                return "";
            }
            declare(i, hidden(i, "OUT"), type);
            call = hidden(i, "OUT") + " := " + callText(i) + ";";
        } else if (totalReaders(i) == 0 && e.stdFunction) {
            return "";  // a standard function (no side effect) whose output is connected to nothing: a dangling drawing
        } else if (totalReaders(i) == 0) {
            call = callText(i) + ";";  // a user function whose result nobody reads: called for its effect
        } else {
            return "";  // written inline where it is read
        }
        return hasEn ? "IF " + en + " THEN " + call + " END_IF;" : call;
    }

    // --- order ------------------------------------------------------------------

    void run(const pugi::xml_node& lang, const std::vector<ChartCondition>* conditions = nullptr) {
        read(lang);
        if (conditions)
            for (const ChartCondition& c : *conditions) {
                // A transition whose condition is drawn as a network: an output variable of the network.
                Element e;
                e.kind = Kind::OutVar;
                e.node = c.transition;
                e.id = c.transition.attribute("localId").as_int();
                readPosition(e);
                e.text = c.variable;
                e.label = c.label;
                e.ins.push_back({"", false, "", connectionsOf(c.pointIn)});
                byId[e.id] = static_cast<int>(els.size());
                els.push_back(std::move(e));
            }
        if (failed) return;
        link();
        if (failed) return;
        classify();
        if (failed) return;
        std::vector<int> roots;
        for (size_t i = 0; i < els.size(); ++i) {
            Kind k = els[i].kind;
            if (k == Kind::OutVar || k == Kind::InOutVar || k == Kind::Coil || k == Kind::Block || k == Kind::Jump || k == Kind::Return ||
                k == Kind::Label || k == Kind::ActionBlock)
                roots.push_back(static_cast<int>(i));
        }
        explicitOrder = !roots.empty() && std::all_of(roots.begin(), roots.end(), [&](int i) { return els[i].order > 0; });
        std::stable_sort(roots.begin(), roots.end(), [&](int a, int b) {
            const Element &x = els[a], &y = els[b];
            if (explicitOrder) return x.order < y.order;
            return std::make_tuple(x.network, x.y, x.x) < std::make_tuple(y.network, y.y, y.x);
        });
        for (int r : roots) {
            if (els[r].state != 0) continue;
            currentRoot = -1;
            emit(r);
        }
        if (failed) return;
        out.body.insert(out.body.end(), lines.begin(), lines.end());
    }
};

}  // namespace

void translateNetwork(XmlConversion& conv, const pugi::xml_node& lang, bool ld, PouContext& ctx, Translation& out) {
    Network n(conv, ctx, out, ld);
    n.run(lang);
}

void copyStText(XmlConversion& conv, const pugi::xml_node& n, const std::string& element, std::vector<StLine>& out, int depth) {
    if (depth > 64) return;
    for (pugi::xml_node c : n.children()) {
        if (c.type() == pugi::node_cdata || c.type() == pugi::node_pcdata) {
            auto [line, col] = conv.where(c);
            out.push_back({c.value(), line, col, element, true});
        } else if (c.type() == pugi::node_element) {
            copyStText(conv, c, element, out, depth + 1);
        }
    }
}

void translateChartConditions(XmlConversion& conv, const pugi::xml_node& sfc, PouContext& ctx, const std::vector<ChartCondition>& conditions,
                              Translation& out) {
    Network n(conv, ctx, out, false);
    n.inChart = true;
    n.run(sfc, &conditions);
}

std::string PouContext::typeOf(const std::string& name) const {
    const std::string u = stdlib::upperAscii(name);
    auto it = variables.find(u);
    if (it != variables.end()) return it->second;
    auto g = project->globals.find(u);
    return g == project->globals.end() ? "" : g->second;
}

bool PouContext::isBlockInstance(const std::string& name) const {
    const std::string type = stdlib::upperAscii(typeOf(name));
    return !type.empty() && (standardBlocks().count(type) || project->blockOutputs.count(type));
}

}  // namespace strun::source::plcopen
