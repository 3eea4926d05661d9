// Beremiz / OpenPLC Editor project folders in a directory argument
// (decision 0356). Such a folder holds `beremiz.xml` (the project settings)
// and `plc.xml` (the whole program, PLCopen TC6); Beremiz compiles plc.xml
// alone. Its build/ folder holds ST generated from plc.xml (plc.st with the
// C code of Beremiz' own blocks in `{{ }}`, generated_plc.st), and users
// often keep the ST their editor exported for the OpenPLC runtime beside it:
// read together with plc.xml, every POU would be declared twice.
#pragma once

#include <string>
#include <vector>

#include "interpreter/source/xml_inputs.h"

namespace strun::source {

// One Beremiz project folder found under a directory argument.
struct BeremizFolder {
    std::string settings;              // its beremiz.xml
    std::string program;               // its plc.xml
    std::vector<std::string> skipped;  // the other source files under it, left out
};

// Finds the Beremiz project folders among `found` (the source files of one
// directory argument, `.xml` included): every folder with a beremiz.xml and a
// plc.xml. Removes from `found` each such folder's beremiz.xml and every
// source under it except its plc.xml, and returns the folders with what was
// removed, for the warning that says so.
std::vector<BeremizFolder> takeBeremizFolders(std::vector<std::string>& found);

// Why a skipped file is not part of the project, for the note naming it.
std::string beremizSkipReason(const BeremizFolder& folder, const std::string& skipped);

// The global variables a Beremiz extension of the project declares (a C or
// Python file's `<variables>`: cfile.xml, pyfile.xml), which Beremiz adds to
// every configuration of plc.xml: `VAR_GLOBAL name : TYPE := initial; END_VAR`,
// each line at its XML element; and the status variable of an MQTT client
// extension (`baseconfnode.xml` of a folder `name@mqtt`, at `path`).
// Empty text when `xml` is no such file.
Converted readBeremizExtensionGlobals(const std::string& xml, const std::string& path);

}  // namespace strun::source
