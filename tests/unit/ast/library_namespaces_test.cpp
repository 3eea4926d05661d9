// A .plcproj's project information and its references' namespaces, and which
// given project folders become libraries with a namespace (decision 0454).
#include <catch2/catch.hpp>

#include "interpreter/source/twincat_library_namespaces.h"
#include "interpreter/source/twincat_plc_project.h"

using namespace strun;
using namespace strun::source;

namespace {

PlcProject read(const std::string& xml) {
    PlcProject p;
    std::string error;
    REQUIRE(readPlcProject(xml, p, error));
    return p;
}

const char* const kApp = R"xml(<?xml version="1.0"?>
<Project xmlns="http://schemas.microsoft.com/developer/msbuild/2003">
  <PropertyGroup><Name>App</Name><DefaultNamespace>App</DefaultNamespace></PropertyGroup>
  <ItemGroup>
    <PlaceholderReference Include="LCLS General"><Namespace>LCLS_General</Namespace></PlaceholderReference>
    <PlaceholderReference Include="Units"/>
    <LibraryReference Include="Tc2_MC2, 3.3.12.0 (Beckhoff Automation GmbH)"><Namespace>MC</Namespace></LibraryReference>
  </ItemGroup>
</Project>)xml";

}  // namespace

TEST_CASE("a .plcproj: its name, title, default namespace and each reference's namespace", "[source][twincat]") {
    const PlcProject app = read(kApp);
    CHECK(app.name == "App");
    CHECK(app.defaultNamespace == "App");
    CHECK(app.libraries == std::vector<std::string>{"LCLS General", "Units", "Tc2_MC2"});
    CHECK(app.libraryNamespaces == std::vector<std::string>{"LCLS_General", "", "MC"});
    const PlcProject lib = read(R"(<Project><PropertyGroup><Title> LCLS General </Title><DefaultNamespace/></PropertyGroup></Project>)");
    CHECK(lib.title == "LCLS General");
    CHECK(lib.defaultNamespace.empty());
}

TEST_CASE("a referenced project folder is a library in the reference's namespace, else its default one", "[source][twincat]") {
    SourceSet sources;
    std::vector<int> files = {sources.add("app/MAIN.TcPOU", ""), sources.add("general/POUs/F_A.TcPOU", ""),
                              sources.add("units/F_B.TcPOU", ""), sources.add("other/F_C.TcPOU", ""),
                              sources.add("general/notes.st", "")};
    sources.addReferencedLibrary("LCLS General");
    sources.addReferencedLibrary("Units");
    sources.addReferencedLibrary("Tc2_MC2");
    std::vector<GivenPlcProject> given = {
        {"app", read(kApp)},
        {"general", read(R"(<Project><PropertyGroup><Title>LCLS General</Title></PropertyGroup></Project>)")},
        {"units", read(R"(<Project><PropertyGroup><Name>Units</Name><DefaultNamespace>UnitsLib</DefaultNamespace></PropertyGroup></Project>)")},
        {"other", read(R"(<Project><PropertyGroup><Name>Other</Name><DefaultNamespace>Other</DefaultNamespace></PropertyGroup></Project>)")},
    };
    assignLibraryNamespaces(given, files, sources);
    CHECK(sources.libraryNamespace(files[0]).empty());             // the application: top level
    CHECK(sources.libraryNamespace(files[1]) == "LCLS_General");   // the reference's namespace
    CHECK(sources.libraryNamespace(files[2]) == "UnitsLib");       // none given: the library's default
    CHECK(sources.libraryNamespace(files[3]).empty());             // no one references it
    CHECK(sources.libraryNamespace(files[4]).empty());             // not a TwinCAT object
    // The given libraries are not missing; Tc2_MC2 still is.
    CHECK(sources.referencedLibraries() == std::vector<std::string>{"Tc2_MC2"});
}
