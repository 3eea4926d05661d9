// The namespace of a TwinCAT library given as its project folder beside the
// project that references it (decision 0454): `strun check App MyLib` with
// App's .plcproj referencing MyLib. The library's POUs and types live in the
// namespace the reference gives (`<Namespace>`), else in the library's
// `<DefaultNamespace>`, so that `MyLib.F_Twice` names them and the same name
// in two libraries (each library's F_GetVersion) is no clash.
#pragma once

#include <string>
#include <vector>

#include "interpreter/source/source_set.h"
#include "interpreter/source/twincat_plc_project.h"

namespace strun::source {

struct GivenPlcProject {
    std::string folder;  // of the .plcproj
    PlcProject project;
};

// Sets the library namespace of each file of `userFiles` that belongs to a
// project of `projects` another of them references, and drops that library
// from the referenced ones strun would report as not available. Projects no
// one references (the application) keep their names at the top level. A
// library's task objects (.TcTTO) are dropped from `userFiles`: a library
// has no tasks, the application's run.
void assignLibraryNamespaces(const std::vector<GivenPlcProject>& projects, std::vector<int>& userFiles, SourceSet& sources);

}  // namespace strun::source
