#include "interpreter/source/twincat_global_types.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <pugixml.hpp>
#include <set>

#include "interpreter/source/identifier_text.h"
#include "stdlib/literals.h"
#include "stdlib/number_scan.h"

namespace strun::source {

namespace {

std::string gtTrimmed(const std::string& s) { return std::string(stdlib::trimBlanks(s)); }

std::string gtUpper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
}

std::string gtLower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// The written type of a <Type>/<BaseType> element: its text, under the
// POINTER TO / REFERENCE TO its attributes give. The Namespace attribute
// (a library's, `Tc2_System`) is left out: strun finds library types by
// their simple names. Empty when the text is no type name strun can read.
std::string gtTypeText(pugi::xml_node type) {
    std::string text = gtTrimmed(type.text().as_string());
    const bool simple = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return isIdentifierChar(c) || c == '(' || c == ')' || c == ' ' || c == '.'; });
    if (!simple) return {};
    std::string prefix;
    for (int k = type.attribute("PointerTo").as_int(0); k > 0 && k < 4; --k) prefix += "POINTER TO ";
    if (type.attribute("ReferenceTo").as_bool(false)) prefix += "REFERENCE TO ";
    return prefix + text;
}

// The leading identifier of a type text ("STRING(80)" -> STRING), for the uses.
std::string gtTypeName(const pugi::xml_node type) {
    const std::string text = gtTrimmed(type.text().as_string());
    size_t end = 0;
    while (end < text.size() && isIdentifierChar(text[end])) ++end;
    return text.substr(0, end);
}

// "ARRAY[0..9, 1..3] OF " from the <ArrayInfo> children (LBound, Elements), or "".
std::string gtArrayPrefix(pugi::xml_node node) {
    std::string dims;
    for (pugi::xml_node info : node.children("ArrayInfo")) {
        const long long lo = info.child("LBound").text().as_llong(0), n = info.child("Elements").text().as_llong(0);
        if (n <= 0) return "?";  // no array strun can declare
        dims += (dims.empty() ? "" : ", ") + std::to_string(lo) + ".." + std::to_string(lo + n - 1);
    }
    return dims.empty() ? std::string() : "ARRAY[" + dims + "] OF ";
}

// " := value" of a member's <Default>, or "" (no default, or a form strun
// does not write back: a structured default).
std::string gtDefault(pugi::xml_node item) {
    const pugi::xml_node d = item.child("Default");
    if (!d) return {};
    if (pugi::xml_node v = d.child("Value")) {
        const std::string text = gtTrimmed(v.text().as_string());
        const bool number = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
            return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == 'e' || c == 'E' || c == '+';
        });
        return number ? " := " + text : std::string();
    }
    if (pugi::xml_node s = d.child("String")) return " := " + stdlib::quoteStringLiteral(s.text().as_string());
    if (pugi::xml_node b = d.child("Bool")) return std::string(" := ") + (b.text().as_bool() ? "TRUE" : "FALSE");
    if (pugi::xml_node e = d.child("EnumText")) {
        const std::string text = gtTrimmed(e.text().as_string());
        return std::all_of(text.begin(), text.end(), [](char c) { return isIdentifierChar(c) || c == '.'; }) && !text.empty() ? " := " + text : std::string();
    }
    if (pugi::xml_node t = d.child("DateTime")) {
        const std::string text = gtTrimmed(t.text().as_string());
        return text.find('#') != std::string::npos && text.find_first_of(";()") == std::string::npos ? " := " + text : std::string();
    }
    return {};
}

// The pragmas TwinCAT keeps as plcAttribute_ properties that change how
// code names the type's values: {attribute 'qualified_only'}, 'strict'.
std::string gtAttributes(pugi::xml_node dataType) {
    std::string out;
    for (pugi::xml_node p : dataType.child("Properties").children("Property")) {
        const std::string name = gtTrimmed(p.child("Name").text().as_string());
        if (name == "plcAttribute_qualified_only") out += "{attribute 'qualified_only'}\n";
        else if (name == "plcAttribute_strict") out += "{attribute 'strict'}\n";
    }
    return out;
}

// A function block, interface or program described in a .tmc: not a data type.
bool gtIsPou(pugi::xml_node dataType) {
    if (dataType.child("Method")) return true;
    for (pugi::xml_node p : dataType.child("Properties").children("Property"))
        if (gtTrimmed(p.child("Name").text().as_string()) == "PouType") return true;
    return gtTypeName(dataType.child("ExtendsType")) == "PVOID";
}

// One <DataType> as ST, or false when strun cannot write it.
bool gtConvert(pugi::xml_node dataType, TwinCatDataType& t) {
    const std::string attributes = gtAttributes(dataType);
    if (dataType.child("EnumInfo")) {
        const std::string base = gtTypeText(dataType.child("BaseType"));
        std::string values;
        for (pugi::xml_node e : dataType.children("EnumInfo")) {
            const std::string text = gtTrimmed(e.child("Text").text().as_string());
            const std::string value = gtTrimmed(e.child("Enum").text().as_string());
            if (!isPlainIdentifier(text) || value.empty() || value.find_first_not_of("-0123456789") != std::string::npos) return false;
            values += (values.empty() ? "" : ", ") + text + " := " + value;
        }
        t.st = attributes + "TYPE " + t.name + " : (" + values + ")" + (base.empty() ? "" : " " + base) + ";\nEND_TYPE\n";
        return true;
    }
    if (dataType.child("SubItem")) {
        std::string head = "TYPE " + t.name;
        if (pugi::xml_node ext = dataType.child("ExtendsType")) {
            const std::string base = gtTypeName(ext);
            if (!isPlainIdentifier(base)) return false;
            head += " EXTENDS " + base;
            t.uses.push_back(base);
        }
        std::string members;
        for (pugi::xml_node item : dataType.children("SubItem")) {
            const std::string name = gtTrimmed(item.child("Name").text().as_string());
            const std::string type = gtTypeText(item.child("Type"));
            const std::string array = gtArrayPrefix(item);
            if (!isPlainIdentifier(name) || type.empty() || array == "?") return false;
            members += "    " + name + " : " + array + type + gtDefault(item) + ";\n";
            t.uses.push_back(gtTypeName(item.child("Type")));
        }
        t.st = attributes + head + " :\nSTRUCT\n" + members + "END_STRUCT\nEND_TYPE\n";
        return true;
    }
    if (pugi::xml_node base = dataType.child("BaseType")) {  // an alias, of an array when it has ArrayInfo
        const std::string type = gtTypeText(base);
        const std::string array = gtArrayPrefix(dataType);
        if (type.empty() || array == "?") return false;
        t.uses.push_back(gtTypeName(base));
        t.st = attributes + "TYPE " + t.name + " : " + array + type + ";\nEND_TYPE\n";
        return true;
    }
    return false;
}

}  // namespace

bool mentionsWord(const std::string& text, const std::string& lowerName) {
    if (lowerName.empty()) return false;
    const char first = lowerName[0];
    for (size_t i = 0; i + lowerName.size() <= text.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(text[i])) != first) continue;
        if (i > 0 && isIdentifierChar(text[i - 1])) continue;
        const size_t end = i + lowerName.size();
        if (end < text.size() && isIdentifierChar(text[end])) continue;
        bool same = true;
        for (size_t k = 1; k < lowerName.size() && same; ++k) same = std::tolower(static_cast<unsigned char>(text[i + k])) == lowerName[k];
        if (same) return true;
    }
    return false;
}

void readTwinCatDataTypes(const std::string& xml, const std::vector<std::string>* onlyPinned, std::vector<TwinCatDataType>& out) {
    pugi::xml_document doc;
    if (!doc.load_buffer(xml.data(), xml.size())) return;
    const pugi::xml_node root = doc.document_element();
    // A .tmc with modules describes a compiled project: only its pinned types are global.
    if (std::strcmp(root.name(), "TcModuleClass") == 0 && root.child("Modules") && !onlyPinned) return;
    const bool all = !(std::strcmp(root.name(), "TcModuleClass") == 0 && root.child("Modules"));
    for (pugi::xml_node dataType : root.child("DataTypes").children("DataType")) {
        const pugi::xml_node name = dataType.child("Name");
        if (dataType.child("EventId") || name.attribute("TcBaseType").as_bool(false) || gtIsPou(dataType)) continue;
        TwinCatDataType t;
        t.name = gtTrimmed(name.text().as_string());
        if (!isPlainIdentifier(t.name)) continue;
        if (!all && std::none_of(onlyPinned->begin(), onlyPinned->end(), [&](const std::string& p) { return gtUpper(p) == gtUpper(t.name); })) continue;
        t.guid = gtUpper(gtTrimmed(name.attribute("GUID").as_string()));
        for (pugi::xml_node hide : dataType.child("Hides").children("Hide")) t.hides.push_back(gtUpper(gtTrimmed(hide.attribute("GUID").as_string())));
        if (gtConvert(dataType, t)) out.push_back(std::move(t));
    }
}

std::string twinCatGlobalTypesSource(const std::vector<TwinCatDataType>& types, const std::vector<const std::string*>& texts) {
    // The versions: a GUID another type hides is an older one.
    std::set<std::string> hidden;
    for (const TwinCatDataType& t : types) hidden.insert(t.hides.begin(), t.hides.end());
    std::vector<const TwinCatDataType*> current;  // one per name, in order
    for (const TwinCatDataType& t : types) {
        if (!t.guid.empty() && hidden.count(t.guid)) continue;
        const bool known = std::any_of(current.begin(), current.end(), [&](const TwinCatDataType* c) { return gtUpper(c->name) == gtUpper(t.name); });
        if (!known) current.push_back(&t);
    }
    std::vector<bool> chosen(current.size(), false);
    std::vector<size_t> todo;
    for (size_t k = 0; k < current.size(); ++k) {
        const std::string lower = gtLower(current[k]->name);
        if (std::any_of(texts.begin(), texts.end(), [&](const std::string* text) { return mentionsWord(*text, lower); })) {
            chosen[k] = true;
            todo.push_back(k);
        }
    }
    while (!todo.empty()) {  // the types the chosen ones use
        const TwinCatDataType* t = current[todo.back()];
        todo.pop_back();
        for (const std::string& use : t->uses)
            for (size_t k = 0; k < current.size(); ++k)
                if (!chosen[k] && gtUpper(current[k]->name) == gtUpper(use)) {
                    chosen[k] = true;
                    todo.push_back(k);
                }
    }
    std::string st;
    for (size_t k = 0; k < current.size(); ++k)
        if (chosen[k]) st += current[k]->st;
    if (st.empty()) return {};
    return "(* The global data types of the TwinCAT type system the project names, written by strun from\n"
           "   the .tsproj / .tmc files (decision 0447). *)\n" +
           st;
}

}  // namespace strun::source
