// Finding the test suites of a compiled project: the FUNCTION_BLOCKs that
// extend FB_TestSuite, and their instances in the program instances and
// global lists (members, nested instances and array elements included), in
// declaration order. These are what RUN() calls.
#pragma once

#include <string>
#include <vector>

#include "interpreter/sema/program_model.h"

namespace strun::testing {

class TestRegistry;

// True for a FUNCTION_BLOCK derived (at any depth) from FB_TestSuite.
bool isTestSuite(const sema::PouInfo* pou);

// Records, while the checker's AST is still alive (compile pipeline), what the
// test run needs of it later: the source file of every POU (fault locations)
// and the suite blocks that can be instantiated (not ABSTRACT).
void recordProject(const sema::ProgramModel& model, TestRegistry& registry);

// ST source of the program strun adds to a project that never calls RUN():
// one instance of every suite block, named after the block, and RUN().
std::string syntheticTestProgram(const std::vector<std::string>& blocks);
extern const char* const kSyntheticProgramName;

// Fills registry.suites with every suite instance.
void collectSuites(sema::ProgramModel& model, TestRegistry& registry);

}  // namespace strun::testing
