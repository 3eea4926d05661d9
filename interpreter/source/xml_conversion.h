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
};

}  // namespace strun::source
