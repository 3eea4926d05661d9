// A TwinCAT PLC project file (`.plcproj`, MSBuild XML): the objects it
// compiles and the libraries it references (decision 0279). strun reads a
// TwinCAT project folder by its objects (.TcPOU, .TcDUT, .TcGVL, .TcIO,
// .TcTTO); the .plcproj says which of them TwinCAT builds and which
// libraries the code may name.
#pragma once

#include <string>
#include <vector>

namespace strun::source {

struct PlcProject {
    // `<Compile Include="POUs\MAIN.TcPOU">`: the paths, '/'-separated and
    // relative to the folder of the .plcproj.
    std::vector<std::string> compiled;
    // `<PlaceholderReference Include="Tc2_MC2">`, `<LibraryReference
    // Include="Tc2_MC2, 3.3.12.0 (Beckhoff Automation GmbH)">`: the names.
    std::vector<std::string> libraries;
    // The `<Namespace>` each reference gives its library's names in this
    // project (`<PlaceholderReference Include="lcls-twincat-math">` ...
    // `<Namespace>lcls_twincat_math</Namespace>`), parallel to `libraries`;
    // "" when the reference names none (decision 0454).
    std::vector<std::string> libraryNamespaces;
    // `<PropertyGroup>`: the project's `<Name>`, `<Title>` (what a consumer's
    // reference names it by) and `<DefaultNamespace>` (the qualifier of its
    // names when the reference gives none).
    std::string name, title, defaultNamespace;
    // `<PinnedGlobalDataType Include="ST_X"/>`: global data types of the
    // solution's type system the project pins (decision 0447).
    std::vector<std::string> pinnedTypes;
};

// False (with `error` set) when `text` is not well-formed XML with a
// <Project> root.
bool readPlcProject(const std::string& text, PlcProject& out, std::string& error);

}  // namespace strun::source
