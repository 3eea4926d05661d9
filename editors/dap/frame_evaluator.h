// ST expressions typed in an editor (watch, hover, the debug console, a
// breakpoint's condition, a log point's {EXPR}) compiled by the checker in
// the scope of a POU and evaluated on a live frame. A wrong expression gets
// the checker's own message; evaluation never runs on the PLC's machine
// (its ticks and faults go to a machine of its own), so it cannot move PLC
// time, trip a watchdog or stop the PLC.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "interpreter/ast/ast.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/program_model.h"
#include "runtime/machine.h"

namespace strun::editors::dap {

struct CompiledExpression {
    bool ok = false;
    std::string error;  // the checker's (or the parser's) message when !ok
    sema::Checked checked;
    uint32_t frameBytes = 0;  // frame the evaluation needs (POU frame + temporaries)
    std::vector<ast::CompilationUnit> ast;  // keeps the parsed expression alive
};

struct EvaluatedValue {
    bool ok = false;
    std::string error;
    const sema::Type* type = nullptr;
    std::vector<uint8_t> bytes;  // the value's storage image (type->size bytes)
};

class FrameEvaluator {
public:
    FrameEvaluator(sema::Checker& checker, sema::ProgramModel& model, CompileLog& log);
    ~FrameEvaluator();
    // Compiled once per (text, POU); `pou` null: globals only.
    std::shared_ptr<CompiledExpression> compile(const std::string& text, sema::PouInfo* pou);
    // Evaluates on the frame whose instance is `self` and frame `frame`
    // (`frameSize` bytes of it are the POU's; they are copied, so the
    // expression cannot change the frame).
    EvaluatedValue evaluate(const CompiledExpression& e, uint8_t* self, const uint8_t* frame, uint32_t frameSize);

private:
    class FaultCatcher;
    sema::Checker& checker_;
    sema::ProgramModel& model_;
    CompileLog& log_;
    std::map<std::pair<std::string, const sema::PouInfo*>, std::shared_ptr<CompiledExpression>> cache_;
    std::unique_ptr<FaultCatcher> faults_;
    std::unique_ptr<rt::Machine> machine_;
    std::vector<uint8_t> sink_;
};

}  // namespace strun::editors::dap
