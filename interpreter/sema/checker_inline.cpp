// Small leaf FUNCTIONs inlined at their calls (decision 0317). A call costs
// a frame push, register saves and restores and a depth count; for a FUNCTION
// of a few statements that calls nothing that is most of what the call does.
// Such a call instead runs a second copy of the callee's body, checked with
// the callee's variables in an area of the caller's frame: the arguments are
// stored there, the body runs on the caller's frame, and only the POU name
// (for watchdog positions and test failures) changes for its duration.
#include <algorithm>

#include "interpreter/sema/checker.h"

namespace strun::sema {

namespace {
constexpr size_t kMaxInlineStatements = 12;        // statements of an inlined body, nested ones counted
constexpr uint32_t kMaxInlineFrame = 256;           // bytes of an inlined FUNCTION's frame
constexpr uint32_t kMaxInlineBytesPerCaller = 16384;  // a caller's frame grows by at most this much
constexpr size_t kMaxInlinedCalls = 20000;          // in a project: bounds the extra checking and nodes

uint32_t alignInlineBase(uint32_t v, uint32_t a) { return (v + a - 1) / a * a; }

// Writes a constant argument into the call's frame image, as bindArgs would
// store it; false for the other kinds of argument.
bool storeConstantArgument(std::vector<uint8_t>& image, const exec::ArgBind& b) {
    using H = exec::ArgBind::How;
    const size_t bytes = b.how == H::Const1 ? 1 : b.how == H::Const2 ? 2 : b.how == H::Const4 ? 4 : b.how == H::Const8 ? 8 : 0;
    if (bytes == 0 || b.dst + bytes > image.size()) return false;
    uint8_t* p = image.data() + b.dst;
    switch (bytes) {
        case 1: exec::storeAs<uint8_t>(p, static_cast<uint8_t>(b.bits)); break;
        case 2: exec::storeAs<uint16_t>(p, static_cast<uint16_t>(b.bits)); break;
        case 4: exec::storeAs<uint32_t>(p, static_cast<uint32_t>(b.bits)); break;
        default: exec::storeAs<uint64_t>(p, b.bits); break;
    }
    return true;
}

// Statements of `list`, nested ones included; stops counting past `limit`.
size_t countStatements(const ast::StmtList& list, size_t limit);
size_t countStatement(const ast::Stmt& s, size_t limit) {
    size_t n = 1;
    for (const ast::StmtList& b : s.blocks) n += countStatements(b, limit);
    if (s.elseBlock) n += countStatements(*s.elseBlock, limit);
    for (const ast::CaseBranch& c : s.cases) n += countStatements(c.body, limit);
    n += countStatements(s.body, limit);
    return n;
}
size_t countStatements(const ast::StmtList& list, size_t limit) {
    size_t n = 0;
    for (const ast::StmtPtr& s : list) {
        if (!s) continue;
        if (s->kind == ast::StmtKind::Label || s->kind == ast::StmtKind::Jmp) return limit + 1;  // JMP needs the Block's labels
        n += countStatement(*s, limit);
        if (n > limit) return n;
    }
    return n;
}
// The inputs of an inlined block call as QuickArgs (decision 0472), when
// every one is bound directly as a 1- or 4-byte constant, a 4-byte integer
// value or a BOOL value; else none (the call keeps its ArgBind list).
std::vector<exec::QuickArg> quickInputs(const exec::CallFbStmt& call) {
    using H = exec::ArgBind::How;
    std::vector<exec::QuickArg> out;
    if (!call.directInputs || call.binds.empty()) return out;
    for (const exec::ArgBind& b : call.binds) {
        exec::QuickArg q;
        q.dst = b.dst;
        switch (b.how) {
            case H::Const1: exec::storeAs<uint8_t>(reinterpret_cast<uint8_t*>(&q.bits), static_cast<uint8_t>(b.bits)); q.oneByte = true; break;
            case H::Const4: q.bits = static_cast<uint32_t>(b.bits); break;
            case H::Int4: q.value = b.value; break;
            case H::Bool: q.value = b.value; q.oneByte = true; break;
            default: return {};
        }
        out.push_back(q);
    }
    out.back().last = true;
    return out;
}
}  // namespace

void Checker::noteInlinable(PouInfo* pou, size_t messagesBefore, uint64_t callsBefore) {
    const bool kind = pou->kind == ast::PouKind::Function || pou->kind == ast::PouKind::FunctionBlock ||
                      (pou->kind == ast::PouKind::Method && !pou->property && pou->ast && !pou->ast->abstract);
    pou->inlinable = options_.inlineCalls && kind && !pou->code->library && pou->ast &&
                     userCallsMade_ == callsBefore &&                       // a leaf: calls no POU
                     log_.messages().size() == messagesBefore &&            // checked without any diagnostic
                     messagesBefore < CompileLog::kMaxMessages &&
                     pou->frameAddressInits.empty() && pou->code->frameSize <= kMaxInlineFrame &&
                     countStatements(pou->ast->body, kMaxInlineStatements) <= kMaxInlineStatements;  // no label or JMP either
}

void Checker::noteInlineSite(exec::CallPou* call, PouInfo* fn, bool onInstance, const ast::Expr& e) {
    // Only a call in a body proper (its frame is the caller's), with every
    // input bound directly and no output, with a scalar result.
    if (!options_.inlineCalls || !inlineCaller_ || fn->code->library) return;
    if (fn->kind != (onInstance ? ast::PouKind::Method : ast::PouKind::Function)) return;
    if (!call->directInputs || !call->outputs.empty() || call->resultSize != 0) return;
    inlineSites_.push_back({call, nullptr, fn, inlineCaller_, onInstance, &e});
}

void Checker::noteInlineSite(exec::CallFbStmt* call, PouInfo* fb) {
    if (!options_.inlineCalls || !inlineCaller_ || fb->code->library || fb->kind != ast::PouKind::FunctionBlock) return;
    inlineSites_.push_back({nullptr, call, fb, inlineCaller_, true});
}

void Checker::inlineLeafCalls() {
    size_t inlined = 0;
    for (const InlineSite& site : inlineSites_) {
        PouInfo* fn = site.callee;
        exec::PouCode* caller = site.caller->code;
        if (!fn->inlinable || inlined >= kMaxInlinedCalls) continue;
        const uint32_t area = static_cast<uint32_t>(exec::frameImageSize(fn->code->frameSize));
        const uint32_t base = alignInlineBase(caller->frameSize, 16);
        if (base + area - caller->initSize > kMaxInlineBytesPerCaller) continue;
        // The callee's body once more, as if it were being checked for the
        // first time, with its frame at `base` and new temporaries above it;
        // first with the parameters that read as their arguments (decision
        // 0403), and without them if that check fails (a parameter written).
        auto checkInlined = [&](std::vector<ArgSubstitute> substitutes) -> exec::Block* {
            pou_ = fn;
            currentPouName_ = fn->bodyName;
            frameTop_ = base + area;
            frameBias_ = base;
            loopDepth_ = 0;
            assignedResult_ = false;
            argSubstitutes_ = std::move(substitutes);
            ExprObserver* observer = observer_;
            observer_ = nullptr;
            silent_ = true;
            const uint64_t silencedBefore = silencedCount_;
            exec::Block* checked = checkBlock(fn->ast->body);
            const bool clean = silencedCount_ == silencedBefore;
            silent_ = false;
            observer_ = observer;
            argSubstitutes_.clear();
            frameBias_ = 0;
            pou_ = nullptr;
            currentPouName_ = nullptr;
            return clean ? checked : nullptr;
        };
        std::vector<ArgSubstitute> substitutes = argumentSubstitutes(site);
        exec::Block* body = checkInlined(substitutes);
        if (!body && !substitutes.empty()) {
            substitutes.clear();
            body = checkInlined({});
        }
        if (!body) continue;
        auto* in = pool().make<exec::InlinedCall>();
        in->body = exec::Body(body);
        if (site.call && body->stmts.size() == 1 && body->labels.empty()) in->single = body->stmts[0];
        if (in->body.block) {
            in->list = body->stmts;  // no labels here: countStatements refused them
            in->list.push_back(nullptr);
        }
        in->base = base;
        in->onInstance = site.onInstance;
        in->size = fn->code->initSize;
        in->image = fn->code->frameInit;
        in->resultOffset = fn->code->resultOffset;
        if (site.call) {
            // Constant arguments are part of the image: stored once, here (a
            // substituted one too, so that the area holds what a call stores).
            // A substituted variable of the caller is not copied at all.
            auto& binds = site.call->binds;
            std::erase_if(binds, [&](const exec::ArgBind& b) {
                if (storeConstantArgument(in->image, b)) return true;
                for (const ArgSubstitute& sub : substitutes)
                    if (sub.bind.dst == b.dst) return true;
                return false;
            });
            in->binds = binds;
            in->binds.push_back(exec::ArgBind{});
            in->binds.back().how = exec::ArgBind::How::End;
            chooseInlinedArgs(*in, *fn, substitutes);
            site.call->inlined = in;
            site.call->inlinedOnCaller = !site.onInstance;
        } else {
            site.fbCall->inlined = in;  // its inputs are stored into the instance, not the frame
            site.fbCall->quick = quickInputs(*site.fbCall);
            // A block instance that is a variable of the caller's instance: its address read inline.
            if (auto* var = exec::nodeCast<exec::VarNode<void, exec::BaseKind::Self>>(site.fbCall->instance)) {
                in->instanceOnSelf = true;
                in->instanceOffset = var->off;
            }
        }
        caller->frameSize = alignInlineBase(frameTop_, 16);
        model_.maxFrameSize = std::max(model_.maxFrameSize, caller->frameSize);
        ++inlined;
    }
}

}  // namespace strun::sema
