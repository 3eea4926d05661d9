// The code a configured task runs each activation: its program (and FB)
// instances in order, each on the task's own evaluator context and frame
// stack, with the parameter connections of PROGRAM ... WITH ... (...).
#pragma once

#include <memory>
#include <vector>

#include "interpreter/exec/call_nodes.h"
#include "interpreter/sema/program_model.h"
#include "runtime/task_spec.h"

namespace strun::project {

class TaskRunner final : public rt::TaskBody {
public:
    TaskRunner(sema::ProgramModel& model, const sema::ConfiguredTask& task);
    bool runActivation() override;
    bool currentPosition(std::string& pou, int& line) const override;
    bool currentFileAndColumn(int& file, int& col) const override;

private:
    void runInitCalls();
    sema::ProgramModel& model_;
    std::vector<sema::Invocation> calls_;
    std::vector<uint8_t> stack_;
    std::vector<uint8_t> sink_;
    exec::Ctx ctx_;
};

}  // namespace strun::project
