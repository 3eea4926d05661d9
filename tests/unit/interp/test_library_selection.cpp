// The embedded library files a project gets: only those it mentions
// (interpreter/project/library_selection.h, decision 0150).
#include <algorithm>
#include <cctype>
#include <string>

#include <catch2/catch.hpp>

#include "interpreter/project/library_selection.h"
#include "stdlib/embedded_sources.h"
#include "stdlib/library_mentions.h"
#include "stdlib/library_registry.h"

namespace {

std::vector<std::string> selectedPaths(const std::vector<std::string_view>& texts) {
    std::vector<std::string> paths;
    for (const auto* src : strun::project::embeddedSourcesFor(texts)) paths.emplace_back(src->path);
    return paths;
}

bool has(const std::vector<std::string>& paths, const std::string& path) {
    return std::find(paths.begin(), paths.end(), path) != paths.end();
}

}  // namespace

TEST_CASE("a project that uses no library block gets no library file", "[library]") {
    CHECK(selectedPaths({"PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM"}).empty());
}

TEST_CASE("a library block named in any case selects the file that declares it", "[library]") {
    auto paths = selectedPaths({"PROGRAM Main VAR t : ton; END_VAR t(IN := TRUE, PT := T#1s); END_PROGRAM"});
    CHECK(has(paths, "stdlib/timers.st"));
    CHECK_FALSE(has(paths, "stdlib/counters.st"));
}

TEST_CASE("names are whole words: a longer identifier does not select a block", "[library]") {
    CHECK(selectedPaths({"PROGRAM Main VAR TONx : INT; myCTU : INT; END_VAR END_PROGRAM"}).empty());
}

TEST_CASE("selection is over all files of the project together", "[library]") {
    auto paths = selectedPaths({"PROGRAM Main VAR c : CTU; END_VAR END_PROGRAM", "FUNCTION_BLOCK F VAR e : R_TRIG; END_VAR END_FUNCTION_BLOCK"});
    CHECK(has(paths, "stdlib/counters.st"));
    CHECK(has(paths, "stdlib/edges.st"));
}

TEST_CASE("selected files come in the order of the embedded library", "[library]") {
    auto paths = selectedPaths({"R_TRIG CTU TON"});
    CHECK(has(paths, "stdlib/edges.st"));
    CHECK(has(paths, "stdlib/counters.st"));
    CHECK(has(paths, "stdlib/timers.st"));
    // In the order of the embedded library: stdlib/st first, sorted.
    CHECK(std::is_sorted(paths.begin(), paths.end()));
}

TEST_CASE("a type a library file declares selects it (T_MaxString, T_DCTIME64)", "[library]") {
    auto paths = selectedPaths({"PROGRAM Main VAR s : T_MaxString; t : t_dctime64; END_VAR END_PROGRAM"});
    CHECK(has(paths, "stdlib/Tc2_System/Tc2_System.st"));
    CHECK(has(paths, "stdlib/Tc2_EtherCAT/Tc2_EtherCAT.st"));
    CHECK_FALSE(has(paths, "stdlib/Tc2_Utilities/string_helpers.st"));
    CHECK_FALSE(has(paths, "stdlib/tcunit.st"));
}

TEST_CASE("a Tc2_Utilities helper pulls in the type file it uses", "[library]") {
    auto paths = selectedPaths({"PROGRAM Main VAR s : STRING; END_VAR s := DWORD_TO_HEXSTR(16#AB, 2, FALSE); END_PROGRAM"});
    CHECK(has(paths, "stdlib/Tc2_Utilities/string_helpers.st"));
    CHECK(has(paths, "stdlib/Tc2_System/Tc2_System.st"));
}

TEST_CASE("every library block and function is a 'did you mean' candidate, as declared", "[library]") {
    const auto& names = strun::project::embeddedLibraryNames();
    auto in = [](const std::vector<std::string>& list, const std::string& n) { return std::find(list.begin(), list.end(), n) != list.end(); };
    CHECK(in(names.types, "TON"));
    CHECK(in(names.types, "CTU"));
    CHECK(in(names.types, "R_TRIG"));
    CHECK(in(names.functions, "WRITE_PROTECTED_INT"));
    CHECK_FALSE(in(names.types, "WRITE_PROTECTED_INT"));  // a FUNCTION is no type
    CHECK_FALSE(in(names.functions, "TON"));
}

// Decision 0220: the vendor libraries and their native functions.

namespace {
strun::project::LibrarySelection select(std::string_view text) { return strun::project::selectLibraries({text}); }
bool hasLibrary(const strun::project::LibrarySelection& s, std::string_view lib) {
    return std::find(s.nativeLibraries.begin(), s.nativeLibraries.end(), lib) != s.nativeLibraries.end();
}
}  // namespace

TEST_CASE("a project naming no vendor library gets no file and no native function", "[library]") {
    auto s = select("PROGRAM Main VAR t : TON; x : INT; END_VAR t(IN := TRUE, PT := T#1s); x := x + 1; END_PROGRAM");
    CHECK(s.nativeLibraries.empty());
    for (const auto* f : s.files) CHECK(f->library.empty());
}

TEST_CASE("a native function selects its library's natives, a constant its file", "[library]") {
    auto s = select("PROGRAM Main ADSLOGSTR(ADSLOG_MSGTYPE_ERROR, 'x %s', 'y'); END_PROGRAM");
    CHECK(hasLibrary(s, "Tc2_System"));
    bool systemFile = false;
    for (const auto* f : s.files) systemFile |= f->path == "stdlib/Tc2_System/Tc2_System.st";
    CHECK(systemFile);
}

TEST_CASE("a global constant, an enumeration value and a block select their files", "[library]") {
    auto paths = selectedPaths({"x := S_OK;"});
    CHECK(has(paths, "stdlib/Tc3_Module/Tc3_Module.st"));
    paths = selectedPaths({"d := MC_Negative_Direction;"});
    CHECK(has(paths, "stdlib/Tc2_MC2/types.st"));
    CHECK_FALSE(has(paths, "stdlib/Tc2_MC2/axis_ref.st"));
    paths = selectedPaths({"a : AXIS_REF; p : MC_Power;"});
    CHECK(has(paths, "stdlib/Tc2_MC2/axis_ref.st"));
    CHECK(has(paths, "stdlib/Tc2_MC2/motion_blocks.st"));
    CHECK(has(paths, "stdlib/Tc2_MC2/types.st"));
    CHECK(hasLibrary(strun::project::selectLibraries({"a : AXIS_REF;"}), "Tc2_MC2"));  // the axis' clock
}

TEST_CASE("the registry knows names of libraries strun does not provide", "[library]") {
    CHECK(strun::stdlib::libraryHint("modbusrtumasterv2_pccom").find("comes from library Tc2_ModbusRTU, which strun does not provide") != std::string::npos);
    CHECK(strun::stdlib::libraryHint("MC_Power") == "'MC_Power' comes from library Tc2_MC2");
    CHECK(strun::stdlib::libraryHint("NoSuchName").empty());
    CHECK(strun::stdlib::findLibrary("tc2_system") != nullptr);
    // Names of absent libraries select nothing.
    CHECK(selectedPaths({"s : ModbusRtuMasterV2_PcCOM;"}).empty());
}

TEST_CASE("values of a qualified_only enumeration select nothing by themselves", "[library]") {
    // TcEventSeverity.Error: a project's own `Error` must not load Tc3_EventLogger.
    for (const auto& p : selectedPaths({"Error := TRUE; Info := 1; Warning := 2;"})) CHECK(p.find("Tc3_EventLogger") == std::string::npos);
    CHECK(has(selectedPaths({"s : TcEventSeverity;"}), "stdlib/Tc3_EventLogger/Tc3_EventLogger.st"));
}

// Decision 0421: what a word selects depends on what it names.

namespace {
bool hasLibraryFile(const std::vector<std::string>& paths, std::string_view library) {
    return std::any_of(paths.begin(), paths.end(), [&](const std::string& p) { return p.find("/" + std::string(library) + "/") != std::string::npos; });
}
}  // namespace

TEST_CASE("a library function selects its file only where it is called", "[library]") {
    // Tc3_Module's FAILED: a state, a variable or an enumeration value named Failed loads nothing.
    CHECK(selectedPaths({"TYPE S : (Idle, Failed); END_TYPE PROGRAM Main VAR Failed : BOOL; END_VAR Failed := TRUE; END_PROGRAM"}).empty());
    CHECK(has(selectedPaths({"b := FAILED(hr);"}), "stdlib/Tc3_Module/Tc3_Module.st"));
    CHECK(has(selectedPaths({"b := failed (hr);"}), "stdlib/Tc3_Module/Tc3_Module.st"));
    CHECK(has(selectedPaths({"b := FAILED\n   (hr);"}), "stdlib/Tc3_Module/Tc3_Module.st"));
    CHECK(has(selectedPaths({"r := Tc3_Module.SUCCEEDED(hr);"}), "stdlib/Tc3_Module/Tc3_Module.st"));
}

TEST_CASE("a library namespace selects its file only qualified or in a USING list", "[library]") {
    // CmpErrors' namespace Errors: a counter named errors loads nothing.
    CHECK(selectedPaths({"PROGRAM Main VAR errors : DINT; END_VAR errors := errors + 1; END_PROGRAM"}).empty());
    CHECK(has(selectedPaths({"r := Errors.ERR_TIMEOUT;"}), "stdlib/CmpErrors/CmpErrors.st"));
    CHECK(has(selectedPaths({"r := Errors . ERR_TIMEOUT;"}), "stdlib/CmpErrors/CmpErrors.st"));
    CHECK(hasLibraryFile(selectedPaths({"USING AxUnit;"}), "AxUnit"));
    CHECK(hasLibraryFile(selectedPaths({"USING Foo, AxUnit;"}), "AxUnit"));
    CHECK_FALSE(hasLibraryFile(selectedPaths({"(* AxUnit *) USING Foo; x := AxUnit;"}), "AxUnit"));
}

TEST_CASE("a dotted namespace selects its file only where its whole path is written", "[library]") {
    CHECK(selectedPaths({"PROGRAM Main VAR system : INT; END_VAR system := 1; END_PROGRAM"}).empty());
    auto paths = selectedPaths({"USING System.Strings;"});
    CHECK(hasLibraryFile(paths, "System_Strings"));
    CHECK_FALSE(hasLibraryFile(paths, "System_DateTime"));
    CHECK_FALSE(hasLibraryFile(paths, "System_Timer"));
    paths = selectedPaths({"System.DateTime.SplitDateAndTime(value := d, year => y);"});
    CHECK(hasLibraryFile(paths, "System_DateTime"));
    CHECK_FALSE(hasLibraryFile(paths, "System_Strings"));
    CHECK(hasLibraryFile(selectedPaths({"USING system . timer;"}), "System_Timer"));
    CHECK_FALSE(hasLibraryFile(selectedPaths({"x := System.Timers;"}), "System_Timer"));
}

TEST_CASE("a library file needs what its code names, not what its comments say", "[library]") {
    // Tc2_System.st's comments speak of "the system time" and of
    // TwinCAT_SystemInfoVarList; its code uses neither AX's System namespaces nor system_info.st.
    auto paths = selectedPaths({"PROGRAM Main VAR s : T_MaxString; END_VAR END_PROGRAM"});
    CHECK(has(paths, "stdlib/Tc2_System/Tc2_System.st"));
    CHECK_FALSE(has(paths, "stdlib/Tc2_System/system_info.st"));
    CHECK_FALSE(hasLibraryFile(paths, "System_Strings"));
    CHECK_FALSE(has(paths, "stdlib/timers.st"));
    // What its code does use still comes along: Tc3_Module's constants are OTCIDs of Tc2_System.
    paths = selectedPaths({"x := S_OK;"});
    CHECK(has(paths, "stdlib/Tc3_Module/Tc3_Module.st"));
    CHECK(has(paths, "stdlib/Tc2_System/Tc2_System.st"));
    for (size_t f = 0; f < strun::stdlib::embeddedSources().size(); ++f)
        for (int used : strun::stdlib::libraryFileUses(f)) CHECK(used != static_cast<int>(f));
}

TEST_CASE("an enumeration value still selects its file, as does its block", "[library]") {
    // Kept (decision 0421): TwinCAT reaches a value of an unqualified library
    // enumeration without its type.
    CHECK(has(selectedPaths({"d := MC_Negative_Direction;"}), "stdlib/Tc2_MC2/types.st"));
    CHECK(has(selectedPaths({"m : MC_MoveVelocity; m(Direction := d);"}), "stdlib/Tc2_MC2/types.st"));
}

// Decision 0493: the word scan's hash filter never drops a selecting name.
TEST_CASE("every name that selects a file or natives passes the word filter, in any case", "[library]") {
    const auto hashSet = strun::stdlib::libraryNameHashSet();
    auto inSet = [&](std::string_view w) { return strun::stdlib::mentions::mayBeInNameHashSet(hashSet, w); };
    const auto& sources = strun::stdlib::embeddedSources();
    size_t checkedFiles = 0;
    for (const strun::stdlib::LibraryName& n : strun::stdlib::libraryNames()) {
        if (n.kind == 'U') continue;
        std::string lower(n.upper);
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        INFO(n.upper);
        CHECK(inSet(n.upper));
        CHECK(inSet(lower));
        if (n.written.find('.') == std::string_view::npos) CHECK(inSet(n.written));  // a dotted namespace's path is no word
        // Written in lower case where a project uses it, the name still selects its file.
        if (n.file >= 0 && (n.kind == 'B' || n.kind == 'T' || n.kind == 'E' || n.kind == 'G' || n.kind == 'F')) {
            const std::string text = "x := " + lower + (n.kind == 'F' ? "(1);" : ";");
            const auto s = strun::project::selectLibraries({text});
            const auto* want = &sources[static_cast<size_t>(n.file)];
            CHECK(std::find(s.files.begin(), s.files.end(), want) != s.files.end());
            ++checkedFiles;
        }
    }
    CHECK(checkedFiles > 500);
    // The words a program is full of are let through by neither test.
    for (std::string_view w : {"END_VAR", "enable", "setpoint", "timer", "END_FUNCTION_BLOCK"}) CHECK_FALSE(inSet(w));
}
