#include "interpreter/testing/tcunit_parameters.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <pugixml.hpp>

#include "interpreter/sema/program_model.h"
#include "interpreter/source/closest_name.h"
#include "interpreter/testing/test_registry.h"

namespace strun::testing {

namespace fs = std::filesystem;

namespace {

std::string upperText(std::string_view s) {
    std::string u(s);
    for (char& ch : u) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return u;
}

std::string trimText(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return std::string(s);
}

// The name as TcUnit spells it, or "" when GVL_Param_TcUnit has none such (any case).
std::string canonical(std::string_view name) {
    for (const auto& n : tcunitParameterNames())
        if (upperText(n) == upperText(name)) return n;
    return {};
}

// An element's name without its namespace prefix.
std::string localName(const pugi::xml_node& node) {
    std::string name = node.name();
    size_t colon = name.find(':');
    return colon == std::string::npos ? name : name.substr(colon + 1);
}

}  // namespace

const std::vector<std::string>& tcunitParameterNames() {
    static const std::vector<std::string> names = {
        "MaxNumberOfTestSuites",   "MaxNumberOfTestsForEachTestSuite", "MaxNumberOfAssertsForEachTestSuite",
        "LogExtendedResults",      "xUnitEnablePublish",               "xUnitBufferSize",
        "xUnitFilePath",           "AdsLogMessageFifoRingBufferSize",  "TimeBetweenTestSuitesExecution"};
    return names;
}

bool parseTcUnitParameter(const std::string& text, TcUnitParameters& out, std::string& error) {
    size_t eq = text.find('=');
    std::string name = trimText(text.substr(0, eq));
    const std::string prefix = "GVL_PARAM_TCUNIT.";
    if (upperText(name).rfind(prefix, 0) == 0) name = name.substr(prefix.size());
    if (eq == std::string::npos || name.empty() || trimText(text.substr(eq + 1)).empty()) {
        error = "--tcunit-param: '" + text + "' is not NAME=VALUE (e.g. MaxNumberOfTestsForEachTestSuite=200)";
        return false;
    }
    std::string known = canonical(name);
    if (known.empty()) {
        error = "--tcunit-param: GVL_Param_TcUnit has no parameter '" + name + "'";
        std::string close = closestName(name, tcunitParameterNames());
        error += close.empty() ? " (docs/testing.md lists them)" : "; did you mean '" + close + "'?";
        return false;
    }
    out[known] = trimText(text.substr(eq + 1));
    return true;
}

bool readPlcprojParameters(const std::string& dir, TcUnitParameters& out, std::string& error) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return true;
    std::vector<std::string> projects;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        std::string ext = upperText(it->path().extension().string());
        if (ext == ".PLCPROJ" && it->is_regular_file(ec)) projects.push_back(it->path().string());
    }
    std::sort(projects.begin(), projects.end());
    for (const auto& path : projects) {
        pugi::xml_document doc;
        pugi::xml_parse_result parsed = doc.load_file(path.c_str());
        if (!parsed) {
            error = "'" + path + "': not a readable project file (" + parsed.description() + ")";
            return false;
        }
        // <PlaceholderReference Include="TcUnit"> (or a LibraryReference) <Parameters>
        //   <Parameter ListName="GVL_Param_TcUnit"><Key>NAME</Key><Value>VALUE</Value></Parameter>
        std::vector<pugi::xml_node> pending{doc.document_element()};
        while (!pending.empty()) {
            pugi::xml_node node = pending.back();
            pending.pop_back();
            const std::string kind = localName(node);
            const std::string library = upperText(node.attribute("Include").value());
            const bool tcunit = (kind == "PlaceholderReference" || kind == "LibraryReference") &&
                                (library.find("TCUNIT") != std::string::npos || library.find("CFUNIT") != std::string::npos);
            if (!tcunit) {
                for (pugi::xml_node child : node.children())
                    if (child.type() == pugi::node_element) pending.push_back(child);
                continue;
            }
            for (pugi::xml_node group : node.children()) {
                if (localName(group) != "Parameters") continue;
                for (pugi::xml_node p : group.children()) {
                    if (localName(p) != "Parameter" || upperText(p.attribute("ListName").value()) != "GVL_PARAM_TCUNIT") continue;
                    std::string name, value;
                    for (pugi::xml_node field : p.children()) {
                        if (localName(field) == "Key") name = canonical(trimText(field.text().get()));
                        if (localName(field) == "Value") value = trimText(field.text().get());
                    }
                    if (!name.empty() && !value.empty()) out.emplace(name, value);
                }
            }
        }
    }
    return true;
}

std::string withTcUnitParameters(std::string_view libraryText, const TcUnitParameters& params) {
    std::string text(libraryText);
    const size_t list = text.find("NAMESPACE GVL_Param_TcUnit");
    if (list == std::string::npos) return text;
    const size_t listEnd = text.find("END_NAMESPACE", list);
    for (const auto& [name, value] : params) {
        // "  Name : TYPE := default;" on its own line inside the list.
        size_t at = text.find("\n  " + name + " :", list);
        if (at == std::string::npos || at > listEnd) continue;
        size_t assign = text.find(":=", at);
        size_t semicolon = text.find(";\n", assign);
        if (assign == std::string::npos || semicolon == std::string::npos) continue;
        text.replace(assign + 2, semicolon - assign - 2, " " + value);
    }
    return text;
}

void readTcUnitLimits(const sema::ProgramModel& model, TestRegistry& reg) {
    for (const auto& g : model.globalStore) {
        if (!g || !g->hasConstValue || upperText(g->listName) != "GVL_PARAM_TCUNIT") continue;
        const std::string name = upperText(g->name);
        if (name == "MAXNUMBEROFTESTSFOREACHTESTSUITE") reg.maxTests = g->constInt;
        else if (name == "MAXNUMBEROFASSERTSFOREACHTESTSUITE") reg.maxAsserts = g->constInt;
        else if (name == "MAXNUMBEROFTESTSUITES") reg.maxSuites = g->constInt;
        else if (name == "LOGEXTENDEDRESULTS") reg.logExtendedResults = g->constInt != 0;
        else if (name == "TIMEBETWEENTESTSUITESEXECUTION") reg.timeBetweenSuites = g->constInt * sema::nanosPerUnit(g->type->kind);  // TIME: ms
    }
}

}  // namespace strun::testing
