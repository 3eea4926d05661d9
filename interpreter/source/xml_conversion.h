// What both XML readers (TwinCAT, PLCopen) share while they convert one file
// to ST: the XML text and its line/column table, the ST being assembled, the
// result with its problems, each located at the XML node it concerns.
#pragma once

#include <string>
#include <utility>

#include <pugixml.hpp>

#include "interpreter/source/st_assembler.h"
#include "interpreter/source/xml_inputs.h"

namespace strun::source {

struct XmlConversion {
    const std::string& xml;
    TextPositions positions;
    StAssembler out;
    Converted result;

    explicit XmlConversion(const std::string& x) : xml(x), positions(x) {}

    std::pair<int, int> where(const pugi::xml_node& n) const { return positions.at(n.offset_debug()); }
    void error(const pugi::xml_node& n, std::string message) {
        auto [line, col] = where(n);
        result.errors.push_back({line, col, std::move(message)});
    }
    // Parses the text into `doc`; a malformed document is an error at the
    // line and column where pugixml stopped.
    bool load(pugi::xml_document& doc) {
        pugi::xml_parse_result parsed = doc.load_buffer(xml.data(), xml.size(), pugi::parse_default, pugi::encoding_utf8);
        if (parsed) return true;
        auto [line, col] = positions.at(parsed.offset);
        result.errors.push_back({line, col, std::string("not well-formed XML: ") + parsed.description()});
        return false;
    }
};

}  // namespace strun::source
