// TcUnit's library parameters (GVL_Param_TcUnit). TwinCAT keeps them in the
// PLC project's library references (the .plcproj), CODESYS in its library
// manager; strun takes them from a .plcproj under a project folder it reads
// and from `strun test --tcunit-param NAME=VALUE` (which wins). The values
// become the constants' initial values in the embedded library, so code that
// reads GVL_Param_TcUnit.X sees them, and the runner applies them
// (docs/testing.md, decision 0295).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace strun::sema { struct ProgramModel; }

namespace strun::testing {

class TestRegistry;

// Parameter name as TcUnit spells it -> the value's ST literal text.
using TcUnitParameters = std::map<std::string, std::string>;

// The parameters GVL_Param_TcUnit declares, spelled as TcUnit does.
const std::vector<std::string>& tcunitParameterNames();

// "NAME=VALUE" from the command line into `out`; false with `error` set
// (an unknown NAME names the closest parameter).
bool parseTcUnitParameter(const std::string& text, TcUnitParameters& out, std::string& error);

// The GVL_Param_TcUnit values of every .plcproj under `dir` that references
// TcUnit (or CfUnit) into `out` (names already in `out` are kept). False with
// `error` set when a .plcproj cannot be read as XML.
bool readPlcprojParameters(const std::string& dir, TcUnitParameters& out, std::string& error);

// `libraryText` (stdlib/st/tcunit.st) with the initial values of the given
// parameters replaced.
std::string withTcUnitParameters(std::string_view libraryText, const TcUnitParameters& params);

// After compiling: the values the runner applies, read from the compiled
// GVL_Param_TcUnit constants (TcUnit's defaults when the list is absent).
void readTcUnitLimits(const sema::ProgramModel& model, TestRegistry& reg);

}  // namespace strun::testing
