// Source files -> checked, runnable program model. Parses the embedded ST
// standard library together with the user's files, so both are checked as
// one project.
#pragma once

#include <memory>
#include <vector>

#include "interpreter/sema/compile_options.h"
#include "interpreter/sema/program_model.h"
#include "interpreter/source/source_set.h"

namespace strun::project {

// Returns null when the project does not compile (errors are in `log`).
std::unique_ptr<sema::ProgramModel> compileProject(SourceSet& sources, const std::vector<int>& userFiles, CompileLog& log,
                                                   const sema::CompileOptions& options = {});

}  // namespace strun::project
