// PLCopen TC6 XML (v2.01, as CODESYS, Beremiz/OpenPLC and others export it):
// data types, POUs with their interface and ST body, actions, CODESYS methods
// and global variable lists (addData), configurations with resources, tasks
// and program instances. Declarations are written as ST lines pointing at
// the XML element they come from; ST bodies are copied with their positions,
// LD, FBD and SFC bodies translated to ST (plcopen_network.cpp, plcopen_sfc.cpp),
// IL bodies too (il_body.cpp).
#include <cctype>
#include <cstdio>
#include <cstring>
#include <set>

#include <pugixml.hpp>

#include "interpreter/source/il_body.h"
#include "interpreter/source/plcopen_graphical.h"
#include "interpreter/source/plcopen_xml.h"
#include "interpreter/source/xml_conversion.h"
#include "stdlib/literals.h"

namespace strun::source {

namespace {

using namespace plcopen;

std::string upperCase(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// TC6 v2.01 and v2.00: CODESYS V3, TwinCAT and Machine Expert export 2.00, Beremiz 2.01;
// v1.0x (`tc6.xsd`): PLCOpenEditor and Beremiz before 2012 (decision 0349).
constexpr const char* kTc6Namespaces[] = {"http://www.plcopen.org/xml/tc6_0201", "http://www.plcopen.org/xml/tc6_0200",
                                          "http://www.plcopen.org/xml/tc6.xsd"};
constexpr int kMaxTypeDepth = 64;  // nested type elements: far beyond real projects

// An xsd:time `HH:MM:SS[.fraction]` (a task interval in TC6 v1.0x) -> T#..., or "" when it is not one.
std::string clockDurationLiteral(const std::string& text) {
    unsigned h = 0, m = 0, s = 0;
    int used = 0;
    if (std::sscanf(text.c_str(), "%2u:%2u:%2u%n", &h, &m, &s, &used) != 3 || m > 59 || s > 59) return "";
    std::string fraction = text.substr(static_cast<size_t>(used));
    if (!fraction.empty() && (fraction[0] != '.' || fraction.size() == 1 ||
                              fraction.find_first_not_of("0123456789", 1) != std::string::npos))
        return "";
    return "T#" + std::to_string(h) + "h" + std::to_string(m) + "m" + std::to_string(s) + fraction + "s";
}

// ISO 8601 duration (PT0.01S, PT1H2M), xsd:time (00:00:00.100000) or an IEC
// literal (T#10ms) -> an IEC literal.
std::string durationLiteral(std::string text) {
    if (std::string clock = clockDurationLiteral(text); !clock.empty()) return clock;
    if (text.size() > 2 && (text[0] == 'P' || text[0] == 'p')) {
        std::string out = "T#";
        bool inTime = false;
        std::string number;
        for (size_t i = 1; i < text.size(); ++i) {
            char c = static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
            if (c == 'T') { inTime = true; continue; }
            if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') { number.push_back(c); continue; }
            const char* unit = c == 'D' ? "d" : c == 'H' ? "h" : (c == 'M' && inTime) ? "m" : c == 'S' ? "s" : nullptr;
            if (!unit || number.empty()) return "T#0s";
            out += number + unit;
            number.clear();
        }
        return out.size() > 2 ? out : "T#0s";
    }
    return text;
}

struct PlcopenReader : XmlConversion {
    using XmlConversion::XmlConversion;

    void written(const pugi::xml_node& n, const std::string& st) {
        auto [line, col] = where(n);
        out.written(st, line, col);
    }

    // <type><INT/></type>, <derived name="T"/>, <array>, <string length>, <pointer>, <enum>, <struct>, subranges.
    std::string typeText(const pugi::xml_node& holder, int depth = 0) {
        pugi::xml_node t = firstElement(holder);
        if (!t || depth > kMaxTypeDepth) return "INT";
        std::string k = localName(t);
        if (k == "derived") return t.attribute("name").value();
        if (k == "string" || k == "wstring") {
            std::string s = k == "string" ? "STRING" : "WSTRING";
            if (t.attribute("length")) s += std::string("[") + t.attribute("length").value() + "]";
            return s;
        }
        if (k == "array") {
            std::string dims;
            for (pugi::xml_node d : children(t, "dimension"))
                dims += (dims.empty() ? "" : ", ") + std::string(d.attribute("lower").value()) + ".." + d.attribute("upper").value();
            return "ARRAY[" + dims + "] OF " + typeText(child(t, "baseType"), depth + 1);
        }
        if (k == "pointer") return "POINTER TO " + typeText(child(t, "baseType"), depth + 1);
        if (k == "subrangeSigned" || k == "subrangeUnsigned") {
            pugi::xml_node r = child(t, "range");
            return typeText(child(t, "baseType"), depth + 1) + "(" + r.attribute("lower").value() + ".." + r.attribute("upper").value() + ")";
        }
        if (k == "enum") {
            std::string values;
            for (pugi::xml_node v : children(child(t, "values"), "value")) {
                values += (values.empty() ? "" : ", ") + std::string(v.attribute("name").value());
                if (v.attribute("value")) values += std::string(" := ") + v.attribute("value").value();
            }
            std::string s = "(" + values + ")";
            if (pugi::xml_node b = child(t, "baseType")) s += " " + typeText(b, depth + 1);
            return s;
        }
        if (k == "struct") return "STRUCT";  // members follow on their own lines (dataType)
        // Elementary types are written as elements of their own name: <INT/>, <BOOL/>, <TIME/>...
        std::string upper;
        for (char c : k) upper.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
        return upper;
    }

    // <initialValue><simpleValue value="5"/></initialValue>, arrayValue, structValue.
    std::string valueText(const pugi::xml_node& v, int depth = 0) {
        if (!v || depth > kMaxTypeDepth) return "";
        std::string k = localName(v);
        if (k == "initialValue" || k == "value") return valueText(firstElement(v), depth + 1);
        if (k == "simpleValue") return v.attribute("value").value();
        if (k == "arrayValue") {
            std::string items;
            for (pugi::xml_node item : children(v, "value")) {
                std::string one = valueText(firstElement(item), depth + 1);
                if (item.attribute("repetitionValue")) one = std::string(item.attribute("repetitionValue").value()) + "(" + one + ")";
                items += (items.empty() ? "" : ", ") + one;
            }
            return "[" + items + "]";
        }
        if (k == "structValue") {
            std::string items;
            for (pugi::xml_node item : children(v, "value"))
                items += (items.empty() ? "" : ", ") + std::string(item.attribute("member").value()) + " := " + valueText(firstElement(item), depth + 1);
            return "(" + items + ")";
        }
        return "";
    }

    // TC6 v1.0x exports (PLCOpenEditor, early Beremiz) write a STRING's
    // initial value as the bare text (`<simpleValue value="str test name"/>`);
    // v2 exports write the ST literal ('...'). A bare one is quoted here.
    std::string stringValueQuoted(const pugi::xml_node& type, const pugi::xml_node& init, const std::string& v) {
        const std::string kind = localName(firstElement(type));
        const bool wide = kind == "wstring";
        if ((kind != "string" && !wide) || localName(firstElement(init)) != "simpleValue") return v;
        if (!v.empty() && v.front() == (wide ? '"' : '\'')) return v;
        return stdlib::quoteStringLiteral(v, wide);
    }

    void variable(const pugi::xml_node& var) {
        std::string line = std::string("    ") + var.attribute("name").value();
        if (var.attribute("address")) line += std::string(" AT ") + var.attribute("address").value();
        line += " : " + typeText(child(var, "type"));
        if (pugi::xml_node init = child(var, "initialValue")) {
            std::string v = valueText(init);
            if (!v.empty()) line += " := " + stringValueQuoted(child(var, "type"), init, v);
        }
        written(var, line + ";");
    }

    void varSection(const pugi::xml_node& section, const char* keyword) {
        std::string head = keyword;
        if (section.attribute("constant").as_bool()) head += " CONSTANT";
        if (section.attribute("retain").as_bool()) head += " RETAIN";
        if (section.attribute("persistent").as_bool()) head += " PERSISTENT";
        written(section, head);
        for (pugi::xml_node v : children(section, "variable")) variable(v);
        written(section, "END_VAR");
    }

    void interfaceOf(const pugi::xml_node& itf) {
        static const std::pair<const char*, const char*> sections[] = {
            {"inputVars", "VAR_INPUT"}, {"outputVars", "VAR_OUTPUT"}, {"inOutVars", "VAR_IN_OUT"},
            {"externalVars", "VAR_EXTERNAL"}, {"localVars", "VAR"}, {"tempVars", "VAR_TEMP"}, {"globalVars", "VAR_GLOBAL"}};
        for (pugi::xml_node s : itf.children()) {
            if (s.type() != pugi::node_element) continue;
            const std::string k = localName(s);
            for (const auto& [tag, keyword] : sections)
                if (k == tag) varSection(s, keyword);
        }
    }

    // The body of a POU, action, method or transition: ST copied with its
    // positions, LD/FBD/SFC translated (hidden variables into `tr.declarations`).
    void bodyOf(const pugi::xml_node& owner, const std::string& pouName, PouContext& ctx, Translation& tr) {
        pugi::xml_node body = child(owner, "body");
        if (!body) return;
        pugi::xml_node lang = firstElement(body);
        while (lang && (localName(lang) == "documentation" || localName(lang) == "addData")) lang = lang.next_sibling();
        if (!lang) return;
        const std::string k = localName(lang);
        if (k == "ST") {
            copyStText(*this, lang, "", tr.body);
        } else if (k == "LD" || k == "FBD") {
            translateNetwork(*this, lang, k == "LD", ctx, tr);
        } else if (k == "SFC") {
            translateChart(*this, lang, ctx, tr);
        } else if (k == "IL") {
            ilBody(lang, ctx, tr);
        } else {
            error(lang, "'" + pouName + "' has a body in " + k + ", which strun does not run (it runs ST, LD, FBD and SFC)");
        }
    }

    // An IL body (<IL><xhtml:p><![CDATA[...]]>, or the text itself) translated to ST (il_body.cpp).
    void ilBody(const pugi::xml_node& lang, PouContext& ctx, Translation& tr) {
        std::vector<StLine> texts;
        copyStText(*this, lang, "", texts);
        il::Surroundings around;
        around.prefix = "_il" + std::to_string(++ctx.bodies) + "_";
        around.isBlockInstance = [&ctx](const std::string& name) { return ctx.isBlockInstance(name); };
        around.fail = [this](int line, int col, const std::string& message) { result.errors.push_back({line, col, message}); };
        for (const StLine& t : texts)
            if (!il::translate(t.text, t.line, t.col, around, tr)) return;
    }

    void writeLines(const std::vector<StLine>& lines) {
        for (const StLine& l : lines) {
            if (l.verbatim) out.verbatim(l.text, l.line, l.col, l.element);
            else out.written(l.text, l.line, l.col, l.element);
        }
    }

    void dataType(const pugi::xml_node& dt) {
        pugi::xml_node base = child(dt, "baseType");
        pugi::xml_node t = firstElement(base);
        written(dt, "TYPE");
        if (t && localName(t) == "struct") {
            // CODESYS keeps a structure's EXTENDS in <addData><data name=".../datatypeinheritance"> (decision 0371).
            written(dt, std::string(dt.attribute("name").value()) + inheritanceClause(dt) + " :");
            written(t, "STRUCT");
            for (pugi::xml_node v : children(t, "variable")) variable(v);
            written(t, "END_STRUCT");
            written(dt, "END_TYPE");
            return;
        }
        std::string line = std::string(dt.attribute("name").value()) + " : " + typeText(base);
        if (pugi::xml_node init = child(dt, "initialValue")) {
            std::string v = valueText(init);
            if (!v.empty()) line += " := " + v;
        }
        written(dt, line + ";");
        written(dt, "END_TYPE");
    }

    // A CODESYS interface: <addData><data name=".../interface"><Interface
    // name="I"><Methods><Method name="M"><interface>..., kept in the project's
    // own addData, outside <types> (decision 0371).
    void codesysInterface(const pugi::xml_node& i) {
        written(i, std::string("INTERFACE ") + i.attribute("name").value() + inheritanceClause(i));
        for (pugi::xml_node method : children(child(i, "Methods"), "Method")) {
            pugi::xml_node mitf = child(method, "interface");
            std::string mhead = std::string("METHOD ") + method.attribute("name").value();
            if (pugi::xml_node r = child(mitf, "returnType")) mhead += " : " + typeText(r);
            written(method, mhead);
            interfaceOf(mitf);
            written(method, "END_METHOD");
        }
        // <Properties><Property name="P"><interface><returnType>..., with an
        // empty <GetAccessor /> / <SetAccessor /> for each accessor it
        // declares (decision 0391): `PROPERTY P : T` with those accessors.
        for (pugi::xml_node prop : children(child(i, "Properties"), "Property")) {
            written(prop, propertyHead(prop));
            for (const char* acc : {"GetAccessor", "SetAccessor"})
                if (pugi::xml_node a = child(prop, acc)) {
                    const bool get = std::string(acc) == "GetAccessor";
                    written(a, get ? "GET" : "SET");
                    written(a, get ? "END_GET" : "END_SET");
                }
            written(prop, "END_PROPERTY");
        }
        written(i, "END_INTERFACE");
    }

    // CODESYS writes a method's or property's access in its <interface>'s
    // <addData><data name=".../accessmodifiers"><AccessModifiers Private="true" />
    // (an empty element for PUBLIC): " PRIVATE" etc. for its ST header (decision 0430).
    std::string accessModifier(const pugi::xml_node& itf) {
        for (pugi::xml_node d : children(child(itf, "addData"), "data")) {
            const std::string dataName = d.attribute("name").value();
            if (dataName.size() < 15 || dataName.compare(dataName.size() - 15, 15, "accessmodifiers") != 0) continue;
            pugi::xml_node m = child(d, "AccessModifiers");
            for (const char* access : {"Private", "Protected", "Internal", "Public"})
                if (m.attribute(access).as_bool()) return " " + upperCase(access);
        }
        return "";
    }

    std::string propertyHead(const pugi::xml_node& prop) {
        std::string head = std::string("PROPERTY") + accessModifier(child(prop, "interface")) + " " + prop.attribute("name").value();
        if (pugi::xml_node r = child(child(prop, "interface"), "returnType")) head += " : " + typeText(r);
        return head;
    }

    void codesysInterfaces(const pugi::xml_node& n, int depth, std::set<std::string>& declared) {
        if (depth > kMaxTypeDepth) return;
        for (pugi::xml_node c : n.children()) {
            if (c.type() != pugi::node_element) continue;
            if (localName(c) == "Interface" && localName(c.parent()) == "data") {
                if (declared.insert(upperCase(c.attribute("name").value())).second) codesysInterface(c);
            } else if (localName(c) != "pou" && localName(c) != "dataType" && localName(c) != "body") {
                codesysInterfaces(c, depth + 1, declared);
            }
        }
    }

    void pou(const pugi::xml_node& p) {
        const std::string name = p.attribute("name").value();
        const std::string kind = p.attribute("pouType").value();
        pugi::xml_node itf = child(p, "interface");
        const char* keyword = kind == "program" ? "PROGRAM" : kind == "functionBlock" ? "FUNCTION_BLOCK" : kind == "function" ? "FUNCTION" : nullptr;
        if (!keyword) {
            error(p, "POU '" + name + "' has an unknown pouType '" + kind + "'");
            return;
        }
        // Bodies first: graphical ones declare hidden variables, written with the POU's.
        PouContext ctx;
        ctx.project = &projectTypes;
        ctx.pouName = name;
        collectVariables(itf, ctx.variables);
        for (pugi::xml_node a : children(child(p, "actions"), "action")) ctx.actions.insert(upperCase(a.attribute("name").value()));
        for (pugi::xml_node t : children(child(p, "transitions"), "transition")) ctx.transitions[upperCase(t.attribute("name").value())] = t;
        Translation main;
        bodyOf(p, name, ctx, main);
        std::vector<std::pair<pugi::xml_node, Translation>> methods, actions, accessors;
        for (pugi::xml_node method : codesysMethods(p)) {
            Translation t;
            bodyOf(method, name + "." + method.attribute("name").value(), ctx, t);
            methods.push_back({method, std::move(t)});
        }
        const std::vector<pugi::xml_node> properties = codesysProperties(p);
        for (pugi::xml_node prop : properties)
            for (const char* acc : {"GetAccessor", "SetAccessor"})
                if (pugi::xml_node a = child(prop, acc)) {
                    Translation t;
                    bodyOf(a, name + "." + prop.attribute("name").value() + (std::string(acc) == "GetAccessor" ? ".GET" : ".SET"), ctx, t);
                    accessors.push_back({a, std::move(t)});
                }
        for (pugi::xml_node a : children(child(p, "actions"), "action")) {
            Translation t;
            bodyOf(a, name + "." + a.attribute("name").value(), ctx, t);
            actions.push_back({a, std::move(t)});
        }
        std::vector<StLine> hidden = main.declarations;
        for (auto* group : {&methods, &actions, &accessors})
            for (auto& [node, t] : *group) hidden.insert(hidden.end(), t.declarations.begin(), t.declarations.end());

        std::string head = std::string(keyword) + " " + name;
        if (kind == "function") head += " : " + (child(itf, "returnType") ? typeText(child(itf, "returnType")) : std::string("INT"));
        if (kind == "functionBlock") head += inheritanceClause(itf);
        written(p, head);
        interfaceOf(itf);
        if (!hidden.empty()) {
            written(p, "VAR");
            writeLines(hidden);
            written(p, "END_VAR");
        }
        writeLines(main.body);
        for (auto& [method, t] : methods) {
            pugi::xml_node mitf = child(method, "interface");
            std::string mhead = std::string("METHOD") + accessModifier(mitf) + " " + method.attribute("name").value();
            if (pugi::xml_node r = child(mitf, "returnType")) mhead += " : " + typeText(r);
            written(method, mhead);
            interfaceOf(mitf);
            writeLines(t.body);
            written(method, "END_METHOD");
        }
        // CODESYS keeps a property in <addData><data name=".../property"><Property
        // name="P"><interface><returnType>, with <GetAccessor> / <SetAccessor>
        // (in either order), each with its own <interface> and <body> (decision 0391).
        auto accessor = accessors.begin();
        for (pugi::xml_node prop : properties) {
            written(prop, propertyHead(prop));
            for (const char* acc : {"GetAccessor", "SetAccessor"})
                if (pugi::xml_node a = child(prop, acc)) {
                    const bool get = std::string(acc) == "GetAccessor";
                    written(a, get ? "GET" : "SET");
                    interfaceOf(child(a, "interface"));
                    writeLines(accessor->second.body);
                    ++accessor;
                    written(a, get ? "END_GET" : "END_SET");
                }
            written(prop, "END_PROPERTY");
        }
        for (auto& [a, t] : actions) {
            written(a, std::string("ACTION ") + a.attribute("name").value() + ":");
            writeLines(t.body);
            written(a, "END_ACTION");
        }
        written(p, std::string("END_") + keyword);
    }

    // --- what graphical bodies need to know about the project ----------------

    ProjectTypes projectTypes;

    void collectVariables(const pugi::xml_node& itf, std::map<std::string, std::string>& into) {
        for (pugi::xml_node section : itf.children())
            if (section.type() == pugi::node_element)
                for (pugi::xml_node v : children(section, "variable")) into[upperCase(v.attribute("name").value())] = typeText(child(v, "type"));
    }

    void collectPou(const pugi::xml_node& p) {
        const std::string name = upperCase(p.attribute("name").value());
        const std::string kind = p.attribute("pouType").value();
        pugi::xml_node itf = child(p, "interface");
        if (kind == "function") {
            projectTypes.functionResults[name] = child(itf, "returnType") ? typeText(child(itf, "returnType")) : "INT";
            for (pugi::xml_node v : children(child(itf, "inputVars"), "variable")) projectTypes.functionInputs[name].push_back(v.attribute("name").value());
        } else if (kind == "functionBlock") {
            auto& outs = projectTypes.blockOutputs[name];
            for (pugi::xml_node v : children(child(itf, "outputVars"), "variable")) outs[upperCase(v.attribute("name").value())] = typeText(child(v, "type"));
        }
    }

    void collectProject(const pugi::xml_node& n, int depth) {
        if (depth > kMaxTypeDepth) return;
        for (pugi::xml_node c : n.children()) {
            if (c.type() != pugi::node_element) continue;
            const std::string k = localName(c);
            if (k == "pou") {
                collectPou(c);
            } else if (k == "globalVars") {
                for (pugi::xml_node v : children(c, "variable")) projectTypes.globals[upperCase(v.attribute("name").value())] = typeText(child(v, "type"));
            } else if (k != "body" && k != "interface") {
                collectProject(c, depth + 1);
            }
        }
    }

    // CODESYS keeps a block's EXTENDS and IMPLEMENTS in <interface><addData>
    // <data name=".../pouinheritance"><Inheritance><Extends>B</Extends>
    // <Implements>I</Implements>: " EXTENDS B IMPLEMENTS I, J" (decision 0327).
    static std::string inheritanceClause(const pugi::xml_node& itf) {
        std::string extends, implements;
        for (pugi::xml_node data : children(child(itf, "addData"), "data"))
            for (pugi::xml_node inh : children(data, "Inheritance")) {
                for (pugi::xml_node e : children(inh, "Extends"))
                    if (extends.empty()) extends = e.text().get();
                for (pugi::xml_node i : children(inh, "Implements")) {
                    const std::string names = i.text().get();
                    if (!names.empty()) implements += (implements.empty() ? "" : ", ") + names;
                }
            }
        std::string out;
        if (!extends.empty()) out += " EXTENDS " + extends;
        if (!implements.empty()) out += " IMPLEMENTS " + implements;
        return out;
    }

    // CODESYS keeps methods in <addData><data name=".../method"><Method>.
    static std::vector<pugi::xml_node> codesysMethods(const pugi::xml_node& p) {
        std::vector<pugi::xml_node> out;
        for (pugi::xml_node data : children(child(p, "addData"), "data"))
            for (pugi::xml_node m : children(data, "Method")) out.push_back(m);
        return out;
    }

    // CODESYS keeps properties in <addData><data name=".../property"><Property>.
    static std::vector<pugi::xml_node> codesysProperties(const pugi::xml_node& p) {
        std::vector<pugi::xml_node> out;
        for (pugi::xml_node data : children(child(p, "addData"), "data"))
            for (pugi::xml_node m : children(data, "Property")) out.push_back(m);
        return out;
    }

    // CODESYS writes a task's program call as <pouInstance name="PLC_PRG" typeName="">:
    // the program of that name. TC6 v1.0x names the type in `type`.
    static std::string instanceType(const pugi::xml_node& inst) {
        std::string type = inst.attribute("typeName").value();
        if (type.empty()) type = inst.attribute("type").value();  // TC6 v1.0x
        return type.empty() ? inst.attribute("name").value() : type;
    }

    void configuration(const pugi::xml_node& c) {
        written(c, std::string("CONFIGURATION ") + c.attribute("name").value());
        for (pugi::xml_node g : children(c, "globalVars")) varSection(g, "VAR_GLOBAL");
        for (pugi::xml_node r : children(c, "resource")) {
            written(r, std::string("RESOURCE ") + r.attribute("name").value() + " ON PLC");
            for (pugi::xml_node g : children(r, "globalVars"))
                if (!g.attribute("name")) varSection(g, "VAR_GLOBAL");  // a named one is a list of its own (run())
            for (pugi::xml_node t : children(r, "task")) {
                std::string params;
                if (t.attribute("interval")) params += "INTERVAL := " + durationLiteral(t.attribute("interval").value());
                if (t.attribute("single")) params += (params.empty() ? "" : ", ") + std::string("SINGLE := ") + t.attribute("single").value();
                if (t.attribute("priority")) params += (params.empty() ? "" : ", ") + std::string("PRIORITY := ") + t.attribute("priority").value();
                written(t, std::string("TASK ") + t.attribute("name").value() + " (" + params + ");");
                for (pugi::xml_node inst : children(t, "pouInstance"))
                    written(inst, std::string("PROGRAM ") + inst.attribute("name").value() + " WITH " + t.attribute("name").value() + " : " +
                                      instanceType(inst) + ";");
            }
            for (pugi::xml_node inst : children(r, "pouInstance"))
                written(inst, std::string("PROGRAM ") + inst.attribute("name").value() + " : " + instanceType(inst) + ";");
            written(r, "END_RESOURCE");
        }
        written(c, "END_CONFIGURATION");
    }

    // One named global variable list: NAMESPACE name + VAR_GLOBAL (decision 0094).
    // A list that mixes CONSTANT and other variables is exported with the
    // first section's attributes on the whole list and the real sections in
    // <addData><data name=".../mixedattrsvarlist"><MixedAttrsVarList>: those
    // are taken instead (decision 0337).
    void namedList(const pugi::xml_node& g) {
        written(g, std::string("NAMESPACE ") + g.attribute("name").value());
        std::vector<pugi::xml_node> sections;
        for (pugi::xml_node data : children(child(g, "addData"), "data"))
            for (pugi::xml_node mixed : children(data, "MixedAttrsVarList"))
                for (pugi::xml_node part : children(mixed, "globalVars")) sections.push_back(part);
        if (sections.empty()) sections.push_back(g);
        for (pugi::xml_node part : sections) varSection(part, "VAR_GLOBAL");
        written(g, "END_NAMESPACE");
    }

    // Named global variable lists CODESYS exports in addData (decision 0094).
    void namedGlobalLists(const pugi::xml_node& n, int depth) {
        if (depth > kMaxTypeDepth) return;
        for (pugi::xml_node c : n.children()) {
            if (c.type() != pugi::node_element) continue;
            if (localName(c) == "globalVars" && c.attribute("name") && localName(c.parent()) == "data") {
                namedList(c);
            } else {
                namedGlobalLists(c, depth + 1);
            }
        }
    }

    // CODESYS exports the POUs and data types of an application inside its
    // resource: <addData><data name=".../pou"><pou> (and ".../datatype"),
    // with <types><pous/> left empty. Taken unless types/ declares the name too.
    void addDataDeclarations(const pugi::xml_node& n, int depth, const std::set<std::string>& declared) {
        if (depth > kMaxTypeDepth) return;
        for (pugi::xml_node c : n.children()) {
            if (c.type() != pugi::node_element) continue;
            const bool inData = localName(c.parent()) == "data";
            if (inData && localName(c) == "pou" && !declared.count(c.attribute("name").value())) {
                pou(c);
            } else if (inData && localName(c) == "dataType" && !declared.count(c.attribute("name").value())) {
                dataType(c);
            } else if (localName(c) != "pou" && localName(c) != "types") {
                addDataDeclarations(c, depth + 1, declared);
            }
        }
    }

    void run() {
        pugi::xml_document doc;
        if (!load(doc)) return;
        pugi::xml_node project = firstElement(doc);
        pugi::xml_node types = child(project, "types");
        collectProject(project, 0);
        std::set<std::string> declared;
        for (pugi::xml_node dt : children(child(types, "dataTypes"), "dataType")) {
            dataType(dt);
            declared.insert(dt.attribute("name").value());
        }
        for (pugi::xml_node p : children(child(types, "pous"), "pou")) {
            pou(p);
            declared.insert(p.attribute("name").value());
        }
        addDataDeclarations(child(project, "instances"), 0, declared);
        std::set<std::string> interfaces;
        codesysInterfaces(project, 0, interfaces);
        namedGlobalLists(project, 0);
        // A CODESYS project with several devices exports one configuration per
        // device's application; strun runs one PLC: the first (decision 0337).
        bool first = true;
        for (pugi::xml_node c : children(child(child(project, "instances"), "configurations"), "configuration")) {
            if (!first) {
                const auto [line, col] = where(c);
                result.warnings.push_back({line, col, std::string("configuration '") + c.attribute("name").value() +
                                                             "' is skipped: strun runs one PLC, the export's first configuration"});
                continue;
            }
            first = false;
            // A resource's named global lists (GVL_MQTT of an application) are
            // lists of their own, read as GVL_MQTT.x everywhere.
            for (pugi::xml_node r : children(c, "resource"))
                for (pugi::xml_node g : children(r, "globalVars"))
                    if (g.attribute("name")) namedList(g);
            configuration(c);
        }
        result.text = std::move(out.text());
        result.origins = std::move(out.origins());
    }
};

}  // namespace

bool isPlcOpenProject(const std::string& xml) {
    pugi::xml_document doc;
    if (!doc.load_buffer(xml.data(), xml.size(), pugi::parse_default, pugi::encoding_utf8)) return false;
    pugi::xml_node root = firstElement(doc);
    if (!root || localName(root) != "project") return false;
    for (pugi::xml_attribute a : root.attributes()) {
        std::string n = a.name();
        if (n == "xmlns" || n.rfind("xmlns:", 0) == 0)
            for (const char* ns : kTc6Namespaces)
                if (std::strcmp(a.value(), ns) == 0) return true;
    }
    return false;
}

Converted readPlcOpen(const std::string& xml) {
    PlcopenReader r(xml);
    r.run();
    return std::move(r.result);
}

}  // namespace strun::source
