#include "cli/compile_step.h"

#include <iostream>

#include "cli/diagnostic_render.h"
#include "cli/exit_codes.h"
#include "interpreter/project/compile.h"
#include "interpreter/source/project_inputs.h"

namespace strun::cli {

void compileCommandLine(const CommandLine& line, Compiled& out) {
    std::vector<int> files;
    std::string error;
    CompileLog log;
    if (!source::readProjectInputs(line.files, out.sources, files, log, error)) {
        std::cerr << "strun: " << error << "\n";
        out.exitCode = kExitUsage;
        return;
    }
    out.model = project::compileProject(out.sources, files, log, line.compile, nullptr, out.keepAst ? &out.ast : nullptr);
    // -Werror / -W CODE=error can turn a compiled project into one that does not compile.
    const bool errors = printDiagnostics(log, out.sources, line.diagnostics, std::cerr, stderrWantsColor(line.diagnostics.color));
    if (errors) out.model.reset();
    out.exitCode = out.model ? kExitOk : kExitCompile;
}

}  // namespace strun::cli
