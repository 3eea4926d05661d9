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

// The suite blocks that can be instantiated (not ABSTRACT), in declaration order.
std::vector<const sema::PouInfo*> suiteBlocks(const sema::ProgramModel& model);

// ST source of the program strun adds to a project that never calls RUN():
// one instance of every suite block, named after the block, and RUN().
std::string syntheticTestProgram(const std::vector<const sema::PouInfo*>& blocks);
extern const char* const kSyntheticProgramName;

// Fills registry.suites with every suite instance and registry.pouFiles.
void collectSuites(sema::ProgramModel& model, TestRegistry& registry);

}  // namespace strun::testing
