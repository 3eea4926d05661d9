// The global data types of a TwinCAT solution (decision 0447). TwinCAT keeps
// data types shared between projects in the System's type system: the
// <DataTypes> of the .tsproj and of the type-system .tmc files it adds
// (<AdditionalTmcFile>), and makes them available to every PLC project
// (Beckhoff: "Global data types are managed in the type system of the System
// Manager and automatically made available to the PLC project"). A PLC
// project may pin such a type (`<PinnedGlobalDataType Include="ST_X"/>` in
// its .plcproj); its own .tmc, the compiler's description of the project,
// then records the pinned type too. PLC code names these types, but no
// .TcDUT declares them. strun writes them as ST TYPE declarations.
#pragma once

#include <string>
#include <vector>

namespace strun::source {

struct TwinCatDataType {
    std::string name;                 // <Name>ST_X</Name>
    std::string guid;                 // its GUID attribute, as written ("" when none)
    std::vector<std::string> hides;   // <Hides><Hide GUID=...>: older versions this one replaces
    std::vector<std::string> uses;    // the type names its members, base and EXTENDS name
    std::string st;                   // TYPE ... END_TYPE
};

// The structures, enumerations and aliases of one .tsproj or .tmc text,
// appended to `out`. `onlyPinned` non-null: a PLC project's own .tmc (it
// has <Modules>), of which only the types named there are taken; null: a
// type system (.tsproj, or a .tmc of data types only), all of it. Types
// TwinCAT itself provides (TcBaseType), event classes (decision 0372),
// function blocks and interfaces are left out, as is any type strun cannot
// write back as ST.
void readTwinCatDataTypes(const std::string& xml, const std::vector<std::string>* onlyPinned, std::vector<TwinCatDataType>& out);

// The ST of the types the `texts` name (a lexical test, any case) and,
// transitively, of those types' own uses among `types`. A version another
// one hides is left out; of two of the same name the first is taken (the
// .tsproj comes first). Empty when the texts name none.
std::string twinCatGlobalTypesSource(const std::vector<TwinCatDataType>& types, const std::vector<const std::string*>& texts);

// Whether `text` holds `name` as a whole word, in any case (`name` lower-case).
bool mentionsWord(const std::string& text, const std::string& lowerName);

}  // namespace strun::source
