// One `strun test` run without the command line: compile the project for
// testing (adding a test program when nothing calls RUN()), find the suites,
// run the tasks on the virtual clock until every test finished or the
// timeout, and leave the verdicts in the project's TestRegistry.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "interpreter/sema/compile_options.h"
#include "interpreter/sema/program_model.h"
#include "interpreter/source/source_set.h"
#include "runtime/scheduler.h"

namespace strun::testing {

class TestRegistry;

// Compiles `userFiles` as one project for testing; null when it does not
// compile. When no POU calls RUN() / RUN_IN_SEQUENCE(), compiles again with
// one more PROGRAM that instantiates every suite block and calls RUN().
std::unique_ptr<sema::ProgramModel> compileForTests(SourceSet& sources, const std::vector<int>& userFiles, CompileLog& log,
                                                    const sema::CompileOptions& options = {});

struct TestRunResult {
    rt::PlcState state = rt::PlcState::Run;
    rt::PlcTime endTime = 0;
    std::vector<rt::DiagEntry> diagnostics;
};

// Runs the project's tasks with `options` (virtual clock, statement cost,
// profile; `duration` is the timeout) until every suite finished. Tests still
// running at the end fail with "timeout" (or the fault that stopped the PLC).
TestRunResult runTests(sema::ProgramModel& model, rt::RunOptions options, const std::string& filter);

}  // namespace strun::testing
