// The code a configured task runs each activation: its program (and FB)
// instances in order, each on the task's own evaluator context and frame
// stack, with the parameter connections of PROGRAM ... WITH ... (...).
#pragma once

#include <memory>
#include <vector>

#include "interpreter/exec/call_nodes.h"
#include "interpreter/sema/program_model.h"
#include "runtime/reserved_memory.h"
#include "runtime/task_spec.h"

namespace strun::project {

class TaskRunner final : public rt::TaskBody {
public:
    TaskRunner(sema::ProgramModel& model, const sema::ConfiguredTask& task);
    bool runActivation() override;
    bool currentPosition(std::string& pou, int& line) const override;
    bool currentFileAndColumn(int& file, int& col) const override;
    // --retain: the store saved periodically between activations.
    void setRetainStore(class RetainStore* store) { retain_ = store; }
    // strun debug: the evaluator's registers (current statement, POU, frame, depth).
    const exec::Ctx& context() const { return ctx_; }

private:
    void runInitCalls();
    sema::ProgramModel& model_;
    std::vector<sema::Invocation> calls_;
    rt::ReservedMemory stack_;
    rt::ReservedMemory sink_;
    exec::Ctx ctx_;
    RetainStore* retain_ = nullptr;
};

}  // namespace strun::project
