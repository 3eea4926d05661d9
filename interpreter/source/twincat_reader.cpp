// TwinCAT 3 PLC objects: <TcPlcObject> holding one POU (with Method,
// Property/Get/Set, Action, Transition children), DUT, GVL, Itf or Task. The ST
// lives in CDATA sections of <Declaration> and <Implementation><ST>; strun
// adds the END_xxx lines TwinCAT leaves out.
#include <cctype>
#include <cstring>
#include <map>

#include <pugixml.hpp>

#include "interpreter/source/il_body.h"
#include "interpreter/source/st_tokens.h"
#include "interpreter/source/twincat_tasks.h"
#include "interpreter/source/xml_conversion.h"

namespace strun::source {

namespace {

struct TwincatReader : XmlConversion {
    using XmlConversion::XmlConversion;

    // The text of an element (its CDATA or plain text child), copied with its position.
    void copyText(const pugi::xml_node& element) {
        for (pugi::xml_node c : element.children()) {
            if (c.type() != pugi::node_cdata && c.type() != pugi::node_pcdata) continue;
            auto [line, col] = where(c);
            out.verbatim(c.value(), line, col);
        }
    }

    void written(const pugi::xml_node& n, const std::string& st) {
        auto [line, col] = where(n);
        out.written(st, line, col);
    }

    // IL bodies translated to ST before their POU is written (decision 0466):
    // the temporaries of the POU's own body and of its actions go into a VAR
    // section after the POU's declaration, a method's or accessor's after its own.
    std::map<const void*, plcopen::Translation> ilBodies;
    plcopen::ProjectTypes ilProject;  // no project-wide knowledge: the standard blocks are the instances `S fb` knows
    int ilCount = 0;

    // The <IL> text of `owner`'s implementation translated; its hidden temporaries into `decls`.
    std::string pouDeclaration;  // the text of the POU's <Declaration>: its variables are the IL's too

    void translateIl(const pugi::xml_node& owner, std::vector<plcopen::StLine>& decls) {
        pugi::xml_node il = owner.child("Implementation").child("IL");
        if (!il) return;
        std::string declText = pouDeclaration;
        for (pugi::xml_node c : owner.child("Declaration").children()) declText += std::string("\n") + c.value();
        plcopen::PouContext ctx;
        ctx.project = &ilProject;
        const std::vector<StToken> toks = tokenizeSt(declText);
        declaredVariables(toks, 0, toks.size(), false, ctx.variables);
        il::Surroundings around;
        around.prefix = "_il" + std::to_string(++ilCount) + "_";
        around.isBlockInstance = [&ctx](const std::string& name) { return ctx.isBlockInstance(name); };
        around.fail = [this](int line, int col, const std::string& message) { result.errors.push_back({line, col, message}); };
        plcopen::Translation& tr = ilBodies[il.internal_object()];
        for (pugi::xml_node c : il.children()) {
            if (c.type() != pugi::node_cdata && c.type() != pugi::node_pcdata) continue;
            auto [line, col] = where(c);
            if (!il::translate(c.value(), line, col, around, tr)) return;
        }
        decls.insert(decls.end(), tr.declarations.begin(), tr.declarations.end());
    }

    void writeLines(const std::vector<plcopen::StLine>& lines) {
        for (const plcopen::StLine& l : lines) out.written(l.text, l.line, l.col, l.element);
    }

    void declarationsOfIl(const std::vector<plcopen::StLine>& decls) {
        if (decls.empty()) return;
        out.written("VAR", decls.front().line, decls.front().col);
        writeLines(decls);
        out.written("END_VAR", decls.front().line, decls.front().col);
    }

    // <Implementation><ST>...</ST></Implementation> (or <IL>, translated
    // before); another language is an error naming the POU.
    void implementation(const pugi::xml_node& owner, const std::string& pouName) {
        pugi::xml_node impl = owner.child("Implementation");
        if (!impl) return;
        for (pugi::xml_node lang : impl.children()) {
            if (lang.type() != pugi::node_element) continue;
            if (std::strcmp(lang.name(), "ST") == 0) {
                copyText(lang);
            } else if (std::strcmp(lang.name(), "IL") == 0) {
                auto it = ilBodies.find(lang.internal_object());
                if (it != ilBodies.end()) writeLines(it->second.body);
            } else if (std::strcmp(lang.name(), "NWL") == 0 && hasActiveIl(lang)) {
                error(lang, "'" + pouName + "' has a body in IL, kept by TwinCAT's FBD/LD/IL editor as networks (<NWL>), " +
                                "which strun does not read; strun runs ST bodies and IL written as text (<IL>)");
            } else {
                error(lang, "'" + pouName + "' has a body in " + languageName(lang.name()) +
                                "; strun runs Structured Text (ST) bodies only");
            }
        }
    }

    // TwinCAT's FBD/LD/IL editor marks a network shown as IL with <v n="ILActive">true</v>.
    static bool hasActiveIl(const pugi::xml_node& nwl) {
        for (pugi::xpath_node v : nwl.select_nodes(".//v[@n='ILActive']"))
            if (std::strcmp(v.node().child_value(), "true") == 0) return true;
        return false;
    }

    static std::string languageName(const char* tag) {
        std::string t = tag;
        if (t == "NWL" || t == "FBD") return "FBD";
        if (t == "LD") return "LD";
        if (t == "SFC") return "SFC";
        if (t == "IL") return "IL";
        if (t == "CFC") return "CFC";
        return t;
    }

    // The first keyword of a declaration (comments and pragmas skipped).
    static std::string firstKeyword(const pugi::xml_node& decl) {
        std::string text;
        for (pugi::xml_node c : decl.children()) text += c.value();
        size_t i = 0;
        while (i < text.size()) {
            if (std::isspace(static_cast<unsigned char>(text[i]))) { ++i; continue; }
            if (text.compare(i, 2, "(*") == 0) { size_t e = text.find("*)", i + 2); i = e == std::string::npos ? text.size() : e + 2; continue; }
            if (text.compare(i, 2, "//") == 0) { size_t e = text.find('\n', i); i = e == std::string::npos ? text.size() : e + 1; continue; }
            if (text[i] == '{') { size_t e = text.find('}', i); i = e == std::string::npos ? text.size() : e + 1; continue; }
            break;
        }
        std::string word;
        while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_'))
            word.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(text[i++]))));
        return word;
    }

    void methods(const pugi::xml_node& pou, bool prototypes) {
        for (pugi::xml_node m : pou.children("Method")) {
            std::vector<plcopen::StLine> ilDecls;
            if (!prototypes) translateIl(m, ilDecls);
            copyText(m.child("Declaration"));
            declarationsOfIl(ilDecls);
            if (!prototypes) implementation(m, m.attribute("Name").value());
            written(m, "END_METHOD");
        }
        for (pugi::xml_node p : pou.children("Property")) {
            copyText(p.child("Declaration"));
            for (const char* accessor : {"Get", "Set"}) {
                pugi::xml_node a = p.child(accessor);
                if (!a) continue;
                written(a, std::strcmp(accessor, "Get") == 0 ? "GET" : "SET");
                std::vector<plcopen::StLine> ilDecls;
                if (!prototypes) translateIl(a, ilDecls);
                copyText(a.child("Declaration"));
                declarationsOfIl(ilDecls);
                if (!prototypes) implementation(a, std::string(p.attribute("Name").value()) + "." + accessor);
                written(a, std::strcmp(accessor, "Get") == 0 ? "END_GET" : "END_SET");
            }
            written(p, "END_PROPERTY");
        }
    }

    void pou(const pugi::xml_node& pou) {
        const std::string name = pou.attribute("Name").value();
        pugi::xml_node decl = pou.child("Declaration");
        const std::string kind = firstKeyword(decl);
        const char* end = kind == "PROGRAM" ? "END_PROGRAM" : kind == "FUNCTION_BLOCK" ? "END_FUNCTION_BLOCK"
                          : kind == "FUNCTION" ? "END_FUNCTION" : nullptr;
        if (!end) {
            error(decl ? decl : pou, "'" + name + "': the declaration does not start with PROGRAM, FUNCTION_BLOCK or FUNCTION");
            return;
        }
        std::vector<plcopen::StLine> ilDecls;  // of the POU's body and its actions
        pouDeclaration.clear();
        for (pugi::xml_node c : decl.children()) pouDeclaration += c.value();
        translateIl(pou, ilDecls);
        for (pugi::xml_node a : pou.children("Action")) translateIl(a, ilDecls);
        copyText(decl);
        declarationsOfIl(ilDecls);
        implementation(pou, name);
        methods(pou, false);
        for (pugi::xml_node a : pou.children("Action")) {
            written(a, std::string("ACTION ") + a.attribute("Name").value() + ":");
            implementation(a, name + "." + a.attribute("Name").value());
            written(a, "END_ACTION");
        }
        // <Transition>s belong to SFC bodies, which are reported above.
        written(pou, end);
    }

    void run() {
        pugi::xml_document doc;
        if (!load(doc)) return;
        pugi::xml_node root = doc.child("TcPlcObject");
        if (!root) {
            result.errors.push_back({1, 1, "not a TwinCAT PLC object (no <TcPlcObject> root)"});
            return;
        }
        for (pugi::xml_node n : root.children()) {
            if (n.type() != pugi::node_element) continue;
            const std::string tag = n.name();
            if (tag == "POU") {
                pou(n);
            } else if (tag == "DUT" || tag == "EnumerationTextList") {
                // An enumeration with a text list (.TcTLEO) declares its TYPE like a DUT;
                // the texts (its XmlArchive) are for the HMI and not read.
                copyText(n.child("Declaration"));
            } else if (tag == "GVL") {
                // A named global variable list: GVL.var (decision 0094).
                written(n, std::string("NAMESPACE ") + n.attribute("Name").value());
                copyText(n.child("Declaration"));
                written(n, "END_NAMESPACE");
            } else if (tag == "Task") {
                convertTwinCatTask(*this, n);  // a .TcTTO (decision 0144)
            } else if (tag == "Itf") {
                copyText(n.child("Declaration"));
                methods(n, true);
                written(n, "END_INTERFACE");
            }
        }
        result.text = std::move(out.text());
        result.origins = std::move(out.origins());
    }
};

}  // namespace

Converted readTwinCat(const std::string& xml) {
    TwincatReader r(xml);
    r.run();
    return std::move(r.result);
}

}  // namespace strun::source
