#include "cli/compile_step.h"

#include <iostream>

#include "cli/exit_codes.h"
#include "cli/source_files.h"
#include "interpreter/project/compile.h"

namespace strun::cli {

void compileCommandLine(const CommandLine& line, Compiled& out) {
    std::vector<int> files;
    std::string error;
    if (!readSourceFiles(line.files, out.sources, files, error)) {
        std::cerr << "strun: " << error << "\n";
        out.exitCode = kExitUsage;
        return;
    }
    CompileLog log;
    out.model = project::compileProject(out.sources, files, log, line.compile);
    log.print(std::cerr, out.sources);
    out.exitCode = out.model ? kExitOk : kExitCompile;
}

}  // namespace strun::cli
