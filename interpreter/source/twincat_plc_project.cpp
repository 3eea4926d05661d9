#include "interpreter/source/twincat_plc_project.h"

#include <algorithm>
#include <cstring>
#include <pugixml.hpp>

namespace strun::source {

namespace {

std::string trimmed(std::string s) {
    const auto blank = [](unsigned char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!s.empty() && blank(static_cast<unsigned char>(s.back()))) s.pop_back();
    size_t first = 0;
    while (first < s.size() && blank(static_cast<unsigned char>(s[first]))) ++first;
    return s.substr(first);
}

}  // namespace

bool readPlcProject(const std::string& text, PlcProject& out, std::string& error) {
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size());
    if (!parsed) {
        error = std::string("not well-formed XML: ") + parsed.description();
        return false;
    }
    const pugi::xml_node project = doc.document_element();
    if (std::strcmp(project.name(), "Project") != 0) {
        error = "not a TwinCAT PLC project (the root must be <Project>)";
        return false;
    }
    for (const pugi::xml_node group : project.children("PropertyGroup")) {
        if (const pugi::xml_node n = group.child("Name"); n && out.name.empty()) out.name = trimmed(n.text().as_string());
        if (const pugi::xml_node n = group.child("Title"); n && out.title.empty()) out.title = trimmed(n.text().as_string());
        if (const pugi::xml_node n = group.child("DefaultNamespace"); n && out.defaultNamespace.empty())
            out.defaultNamespace = trimmed(n.text().as_string());
    }
    for (const pugi::xml_node group : project.children("ItemGroup")) {
        for (const pugi::xml_node item : group.children()) {
            const std::string include = trimmed(item.attribute("Include").as_string());
            if (include.empty()) continue;
            const std::string kind = item.name();
            if (kind == "Compile") {
                std::string path = include;
                std::replace(path.begin(), path.end(), '\\', '/');
                out.compiled.push_back(path);
            } else if (kind == "PlaceholderReference" || kind == "LibraryReference") {
                // "Tc2_MC2, 3.3.12.0 (Beckhoff Automation GmbH)": the name is before the comma.
                std::string name = trimmed(include.substr(0, include.find(',')));
                if (!name.empty() && std::find(out.libraries.begin(), out.libraries.end(), name) == out.libraries.end()) {
                    out.libraries.push_back(name);
                    out.libraryNamespaces.push_back(trimmed(item.child("Namespace").text().as_string()));
                }
            } else if (kind == "PinnedGlobalDataType") {
                out.pinnedTypes.push_back(include);
            }
        }
    }
    return true;
}

}  // namespace strun::source
