// The checked program, ready to run: storage blocks with their initial
// values, program instances, tasks with what they call, and the resolved
// tree of every POU. Produced by the checker, run by project/, dumped by
// exec/dump.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "interpreter/exec/call_nodes.h"
#include "interpreter/sema/symbols.h"
#include "interpreter/sema/types.h"
#include "runtime/machine.h"
#include "runtime/task_spec.h"

namespace strun::testing { class TestRegistry; }

namespace strun::sema {

struct ProgramInstance {
    std::string name;        // instance name as declared (the program's own name by default)
    PouInfo* pou = nullptr;
    uint8_t* memory = nullptr;
    ast::Loc loc;
    // PROGRAM p WITH t : T (In := gX, Out => gY): parameter connections,
    // evaluated before / after each call in the task.
    std::vector<exec::Stmt*> before;
    std::vector<exec::Stmt*> after;
};

// One thing a task calls each activation: a program instance or an FB instance.
struct Invocation {
    ProgramInstance* program = nullptr;
    exec::PouCode* code = nullptr;
    uint8_t* instance = nullptr;
    std::string name;
};

struct ConfiguredTask {
    rt::TaskSpec spec;
    std::vector<Invocation> calls;
};

struct ProgramModel {
    std::unique_ptr<TypeTable> types = std::make_unique<TypeTable>();
    exec::NodePool pool;
    std::deque<exec::PouCode> codes;
    std::deque<exec::ClassDesc> classes;
    std::vector<std::unique_ptr<uint8_t[]>> blocks;  // every storage block, zero-initialised then initial values
    std::deque<ProgramInstance> programs;
    std::vector<VarSym*> globals;                   // in declaration order (for --dump)
    std::vector<ConfiguredTask> tasks;
    // CODESYS FB_init of every instance that has one, run once before the
    // first activation of any task (innermost instances first).
    std::vector<exec::Stmt*> initCalls;
    bool initDone = false;
    // Run at the start of every activation of every task, before its
    // programs: library work tied to the task cycle (Tc2_System's _TaskInfo[]).
    // Empty unless the project uses such a library.
    std::vector<exec::Stmt*> activationPrologue;
    uint32_t maxFrameSize = 0;                      // largest frame of any POU (sizes the frame stacks)
    uint32_t largestType = 0;                       // largest element type (sizes the fault sink)
    rt::Machine machine;                            // the process image lives here; addresses point into it
    std::deque<std::string> names;                  // stable strings referenced by nodes (POU names)
    // Owners of what the checker declared: the dump and the run refer to them.
    std::vector<std::unique_ptr<PouInfo>> pouStore;
    std::vector<std::unique_ptr<VarSym>> globalStore;
    // The TcUnit API's state (interpreter/testing): created by the compile
    // pipeline before checking, referenced by the test nodes.
    std::shared_ptr<testing::TestRegistry> tests;

    uint8_t* allocate(size_t size) {
        blocks.push_back(std::make_unique<uint8_t[]>(size ? size : 1));
        machine.memory.add(blocks.back().get(), size ? size : 1);
        return blocks.back().get();
    }
};

}  // namespace strun::sema
