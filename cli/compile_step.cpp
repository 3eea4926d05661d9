#include "cli/compile_step.h"

#include <iostream>

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
    out.model = project::compileProject(out.sources, files, log, line.compile);
    log.print(std::cerr, out.sources);
    out.exitCode = out.model ? kExitOk : kExitCompile;
}

}  // namespace strun::cli
