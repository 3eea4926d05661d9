// The command-line choices that change how a project compiles. The CLI
// (`run`, `check`, `test`) fills one and hands it to project::compileProject,
// which passes it to the checker.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace strun::sema {

struct CompileOptions {
    // --target: the PLC family whose task model, limits and system variables
    // apply (an id of rt::allProfiles(); the CLI validates it).
    std::string target = "generic";
    // --strict: IEC 61131-3 typing; implicit conversions the default accepts
    // with a warning are errors.
    bool strict = false;
    // `strun test` on a project that never calls RUN(): the PROGRAM the test
    // runner added. Under a CONFIGURATION (which only runs the programs it
    // names) it runs in the project's first cyclic or freewheeling task, or
    // else in the target's task for programs without a task (decision 0141).
    std::string testProgram;
    // `strun test`: TcUnit's library parameters (GVL_Param_TcUnit, name as
    // TcUnit spells it -> ST literal), from --tcunit-param and a .plcproj;
    // they replace the defaults in the embedded stdlib/st/tcunit.st.
    std::map<std::string, std::string> tcunitParameters;
    // Small leaf FUNCTIONs run inlined in their callers (decision 0317). The
    // debugger turns it off: it follows calls by their frames and depth.
    bool inlineCalls = true;
    // The project comes (at least partly) from TwinCAT object files (.TcPOU,
    // .TcDUT, .TcGVL, .TcIO): REAL_TO_STRING and friends write a whole
    // number as TwinCAT does, with '.0' (decision 0336). Set by compileProject.
    bool twincatRealText = false;
    // The same projects keep TIME and LTIME as TwinCAT does: unsigned 32-bit
    // milliseconds up to T#49d17h2m47s295ms and unsigned 64-bit nanoseconds
    // up to LTIME#213503d23h34m33s709ms551us615ns (decision 0367).
    bool twincatDurations = false;
    // A SIMATIC AX project (an apax.yml in the folder of a source file or
    // above it): `s[i]` on a STRING is its i-th CHAR, counted from 1, as AX
    // and IEC 61131-3 Ed.3 read it, not TwinCAT's byte from 0 (decision 0394).
    // Set by compileProject.
    bool axStrings = false;
    // The path of every source file, by SourceSet index: the value of an
    // input marked {CallerFilePath} (SIMATIC AX, decision 0363). Set by compileProject.
    std::vector<std::string> sourcePaths;
};

}  // namespace strun::sema
