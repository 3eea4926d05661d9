#include "interpreter/project/task_runner.h"

#include <algorithm>
#include <cstring>

#include "interpreter/project/retain_store.h"

namespace strun::project {

namespace {
// Deep enough for kMaxCallDepth nested frames of the largest POU, plus temporaries.
size_t frameStackBytes(const sema::ProgramModel& model) {
    return (static_cast<size_t>(model.maxFrameSize) + 64) * (exec::kMaxCallDepth + 2) + 4096;
}
}  // namespace

TaskRunner::TaskRunner(sema::ProgramModel& model, const sema::ConfiguredTask& task)
    : model_(model),
      calls_(task.calls),
      stack_(frameStackBytes(model)),
      sink_(std::max<size_t>(exec::kFaultSinkSize, model.largestType + 64)) {
    model.machine.memory.add(stack_.data(), stack_.size());
    model.machine.memory.add(sink_.data(), sink_.size());
    ctx_.m = &model.machine;
    ctx_.faultSink = sink_.data();
}

// CODESYS FB_init calls, once, on the first activation of any task.
void TaskRunner::runInitCalls() {
    model_.initDone = true;
    exec::Ctx& c = ctx_;
    for (exec::Stmt* s : model_.initCalls) {
        c.depth = 0;
        c.stackTop = stack_.data();
        c.stackEnd = stack_.data() + stack_.size();
        c.frame = c.stackTop;
        c.stackTop = c.frame + model_.maxFrameSize;
        c.self = nullptr;
        c.pouName = nullptr;
        s->exec(c);
        if (c.aborting) return;
    }
}

bool TaskRunner::runActivation() {
    exec::Ctx& c = ctx_;
    c.aborting = false;
    if (!model_.initDone) {
        runInitCalls();
        if (c.aborting) return false;
    }
    if (!model_.activationPrologue.empty())
        for (exec::Stmt* s : model_.activationPrologue) s->exec(c);
    for (const sema::Invocation& inv : calls_) {
        c.depth = 0;
        c.stackTop = stack_.data();
        c.stackEnd = stack_.data() + stack_.size();
        c.frame = c.stackTop;
        c.self = inv.instance;
        if (inv.program)
            for (exec::Stmt* s : inv.program->before) s->exec(c);
        const exec::PouCode& code = *inv.code;
        c.pouName = &code.name;
        c.stmt = nullptr;
        if (code.initSize) std::memcpy(c.frame, code.frameInit.data(), code.initSize);
        c.stackTop = c.frame + code.frameSize;
        // Every activation costs at least one statement of PLC time, so an
        // empty program cannot spin a freewheeling task at a standstill.
        if (exec::tickAborts(c)) return false;
        exec::Flow f = code.body->exec(c);
        if (f == exec::Flow::Abort || c.aborting) return false;
        if (inv.program)
            for (exec::Stmt* s : inv.program->after) s->exec(c);
    }
    if (retain_) retain_->saveIfDue();  // between activations: a consistent snapshot of this task
    return true;
}

bool TaskRunner::currentPosition(std::string& pou, int& line) const {
    // Inside the library: the user's statement that called it (Ctx::userStmt).
    const std::string* name = ctx_.userStmt ? ctx_.userPou : ctx_.pouName;
    const exec::Stmt* stmt = ctx_.userStmt ? ctx_.userStmt : ctx_.stmt;
    if (!name) return false;
    pou = *name;
    line = stmt ? stmt->line : 0;
    return true;
}

bool TaskRunner::currentFileAndColumn(int& file, int& col) const {
    const exec::Stmt* stmt = ctx_.userStmt ? ctx_.userStmt : ctx_.stmt;
    if (!stmt) return false;
    file = stmt->file;
    col = stmt->col;
    return true;
}

}  // namespace strun::project
