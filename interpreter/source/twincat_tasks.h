// TwinCAT 3 task objects (.TcTTO): <TcPlcObject><Task Name=...> with its
// <CycleTime> in microseconds, <Priority> and the programs it calls
// (<PouCall><Name>). Each becomes a CONFIGURATION of one TASK and its
// PROGRAM ... WITH lines; the checker joins the configurations of all task
// objects of a project into one (decision 0144).
#pragma once

#include <pugixml.hpp>

#include "interpreter/source/xml_conversion.h"

namespace strun::source {

// The name of the configuration written for a .TcTTO; the checker merges
// the configurations of this name.
inline constexpr const char* kTwinCatTasksConfiguration = "TwinCAT_Tasks";

// Appends the ST of one <Task> element to `c.out` (problems to `c.result`).
void convertTwinCatTask(XmlConversion& c, const pugi::xml_node& task);

}  // namespace strun::source
