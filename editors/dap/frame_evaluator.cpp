#include "editors/dap/frame_evaluator.h"

#include <algorithm>
#include <cstring>

#include "interpreter/ast/parse.h"
#include "interpreter/exec/call_nodes.h"
#include "interpreter/sema/types.h"

namespace strun::editors::dap {

namespace {

// The file index the parsed expression's positions carry: no source of the
// project has it, so the messages about it are told apart (and removed from
// the project's log after reading them).
constexpr int kExpressionFile = -77;

void relocate(ast::Expr& e) {
    e.loc.file = kExpressionFile;
    e.nameLoc.file = kExpressionFile;
    for (auto& k : e.kids)
        if (k) relocate(*k);
    for (auto& a : e.args) {
        a.loc.file = kExpressionFile;
        if (a.value) relocate(*a.value);
    }
}

}  // namespace

// Faults during an evaluation: the first is the answer's error.
class FrameEvaluator::FaultCatcher final : public rt::AttentionHandler {
public:
    bool onAttention() override { return false; }
    void onFault(rt::DiagCode code, std::string_view, int, std::string message, int, int) override {
        if (fault.empty()) fault = std::string(rt::diagCodeName(code)) + ": " + message;
    }
    rt::PlcTime currentTime() override { return 0; }
    int64_t calendarNanos() override { return 0; }
    std::string fault;
};

FrameEvaluator::FrameEvaluator(sema::Checker& checker, sema::ProgramModel& model, CompileLog& log)
    : checker_(checker), model_(model), log_(log), faults_(std::make_unique<FaultCatcher>()),
      machine_(std::make_unique<rt::Machine>()), sink_(std::max<size_t>(exec::kFaultSinkSize, model.largestType + 64)) {
    machine_->handler = faults_.get();
    machine_->setStmtCost(0);
}

FrameEvaluator::~FrameEvaluator() = default;

std::shared_ptr<CompiledExpression> FrameEvaluator::compile(const std::string& text, sema::PouInfo* pou) {
    auto key = std::make_pair(text, static_cast<const sema::PouInfo*>(pou));
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    auto out = std::make_shared<CompiledExpression>();
    if (text.size() > 4096 || text.find_first_not_of(" \t\r\n") == std::string::npos) {
        out->error = text.size() > 4096 ? "expression too long" : "empty expression";
        return out;
    }
    // The expression as the value of an assignment in a program of its own:
    // parsed by the project's parser, so it accepts what a body accepts.
    SourceSet sources;
    const int file = sources.add("<expression>", "PROGRAM strun_expression\nstrun_value := (\n" + text + "\n);\nEND_PROGRAM\n");
    CompileLog parseLog;
    out->ast.push_back(ast::parseFile(sources, file, parseLog));
    const ast::CompilationUnit& unit = out->ast.back();
    if (parseLog.hasErrors() || unit.pous.size() != 1 || unit.pous[0]->body.size() != 1 ||
        unit.pous[0]->body[0]->kind != ast::StmtKind::Assign || !unit.pous[0]->body[0]->expr) {
        out->error = "not an ST expression";
        for (const Diagnostic& d : parseLog.messages())
            if (d.severity == Severity::Error) {
                out->error += ": " + d.message;
                break;
            }
        cache_[key] = out;
        return out;
    }
    ast::Expr& expr = *out->ast.back().pous[0]->body[0]->expr;
    relocate(expr);
    const size_t before = log_.messages().size();
    out->checked = checker_.checkInScope(expr, pou, out->frameBytes);
    for (size_t k = before; k < log_.messages().size(); ++k) {
        const Diagnostic& d = log_.messages()[k];
        if (d.severity == Severity::Error && out->error.empty()) out->error = d.message;
    }
    log_.eraseIf([](const Diagnostic& d) { return d.loc.file == kExpressionFile; });
    out->ok = out->checked.ok && out->error.empty() && out->checked.node && out->checked.type;
    if (!out->ok && out->error.empty()) out->error = "cannot evaluate this expression";
    cache_[key] = out;
    return out;
}

EvaluatedValue FrameEvaluator::evaluate(const CompiledExpression& e, uint8_t* self, const uint8_t* frame, uint32_t frameSize) {
    EvaluatedValue v;
    if (!e.ok) {
        v.error = e.error;
        return v;
    }
    const sema::Type* t = e.checked.type;
    if (t->kind == sema::TK::Void) {
        v.error = "the expression has no value";
        return v;
    }
    // The frame, copied, with room for the temporaries and for calls.
    const size_t frameBytes = std::max<size_t>(e.frameBytes, frameSize) + 64;
    const size_t stackBytes = (static_cast<size_t>(model_.maxFrameSize) + 64) * (exec::kMaxCallDepth + 2) + 4096;
    std::vector<uint8_t> scratch(frameBytes + stackBytes, 0);
    if (frame && frameSize) std::memcpy(scratch.data(), frame, frameSize);
    machine_->memory = model_.machine.memory;
    machine_->memory.add(scratch.data(), scratch.size());
    machine_->memory.add(sink_.data(), sink_.size());
    machine_->setDeadline(rt::kNever);
    faults_->fault.clear();
    exec::Ctx c;
    c.self = self;
    c.frame = scratch.data();
    c.stackTop = scratch.data() + ((frameBytes + 15) & ~size_t{15});
    c.stackEnd = scratch.data() + scratch.size();
    c.m = machine_.get();
    c.faultSink = sink_.data();
    v.type = t;
    v.bytes.assign(t->size ? t->size : 1, 0);
    exec::Expr* node = e.checked.node;
    if (sema::isIntRep(t)) {
        int64_t x = node->i(c);
        if (t->kind == sema::TK::Bool) x = x != 0;
        for (size_t k = 0; k < v.bytes.size() && k < 8; ++k) v.bytes[k] = static_cast<uint8_t>(static_cast<uint64_t>(x) >> (8 * k));
    } else if (sema::isRealRep(t)) {
        const double x = node->f(c);
        if (t->kind == sema::TK::Real) {
            const float f = static_cast<float>(x);
            std::memcpy(v.bytes.data(), &f, std::min<size_t>(4, v.bytes.size()));
        } else {
            std::memcpy(v.bytes.data(), &x, std::min<size_t>(8, v.bytes.size()));
        }
    } else if (const uint8_t* p = node->addr(c)) {
        if (t->size > (size_t{16} << 20)) {
            v.error = "the value is too large to show";
            return v;
        }
        std::memcpy(v.bytes.data(), p, t->size);
    } else {
        v.error = "the expression has no value";
        return v;
    }
    if (!faults_->fault.empty()) {
        v.error = faults_->fault;
        return v;
    }
    v.ok = true;
    return v;
}

}  // namespace strun::editors::dap
