// Small helpers over pugixml shared by the PLCopen readers (declarations and
// ST bodies in plcopen_reader.cpp, LD/FBD networks and SFC charts in
// plcopen_network.cpp and plcopen_sfc.cpp): element names without a namespace
// prefix, children by local name, and the text of an element.
#pragma once

#include <string>
#include <vector>

#include <pugixml.hpp>

namespace strun::source::plcopen {

// Element name without a namespace prefix (`xhtml:p` -> `p`).
inline std::string localName(const pugi::xml_node& n) {
    std::string s = n.name();
    size_t colon = s.find(':');
    return colon == std::string::npos ? s : s.substr(colon + 1);
}

inline pugi::xml_node child(const pugi::xml_node& n, const char* name) {
    for (pugi::xml_node c : n.children())
        if (c.type() == pugi::node_element && localName(c) == name) return c;
    return {};
}

inline std::vector<pugi::xml_node> children(const pugi::xml_node& n, const char* name) {
    std::vector<pugi::xml_node> out;
    for (pugi::xml_node c : n.children())
        if (c.type() == pugi::node_element && localName(c) == name) out.push_back(c);
    return out;
}

inline pugi::xml_node firstElement(const pugi::xml_node& n) {
    for (pugi::xml_node c : n.children())
        if (c.type() == pugi::node_element) return c;
    return {};
}

// The text of an element and its descendants (an <expression>, a <variable> of a contact), trimmed.
inline std::string textOf(const pugi::xml_node& n) {
    std::string s;
    for (pugi::xml_node c : n.children()) {
        if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) s += c.value();
        else if (c.type() == pugi::node_element) s += textOf(c);
    }
    size_t b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return "";
    size_t e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

}  // namespace strun::source::plcopen
