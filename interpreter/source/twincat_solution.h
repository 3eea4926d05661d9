#pragma once
// The TwinCAT solution around a PLC project folder given on its own
// (decision 0474). TwinCAT keeps the global data types and event classes a
// PLC project uses in the System's type system: the .tsproj one or two
// folders above the .plcproj, and the .tmc files beside it. Repositories
// and users commonly name the PLC project folder (`strun run Solution/Plc`),
// so strun looks for the solution that names the project there.

#include <string>
#include <vector>

namespace strun::source {

// The type systems (.tsproj first, then the .tmc files beside it) of the
// solutions, one or two folders above each of `plcProjects`, whose .tsproj
// or independent project file (`_Config/PLC/*.xti`) names that .plcproj in
// a `PrjFilePath` attribute.
// Empty when none does.
std::vector<std::string> enclosingTwinCatTypeSystems(const std::vector<std::string>& plcProjects);

}  // namespace strun::source
