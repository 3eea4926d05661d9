#include "interpreter/exec/call_nodes.h"

namespace strun::exec {

// runBody for the rarer call forms (a body dispatched on the instance's
// class): kept out of line so that the plain FB call keeps the body's
// Block::exec inlined (call_nodes.h).
void runBodyOutOfLine(Ctx& c, const PouCode& code, uint8_t* inst, uint8_t* f) { runBody(c, code, inst, f); }

template struct CallFbStmtOf<false>;
template struct CallFbStmtOf<true>;

// The two forms of a FUNCTION / METHOD call, compiled here only (see
// call_nodes.h): this file is compiled alone (cmake/build_cost.cmake), so
// GCC's inlining limits are those of this small unit, and runBody's
// statement loop of the callee (Block::exec) is inlined.
uint8_t* CallPou::runFramed(Ctx& c) {
    uint8_t* inst = instance ? instance->addr(c) : c.self;
    PouCode* code = callee;
    if (virtualSlot >= 0) {
        code = dispatch(c, inst);
        if (!code) return nullptr;
    }
    uint8_t* f = pushFrame(c, *code, site);
    if (!f) return nullptr;
    if (directInputs && outputs.empty()) {
        // Lean call (decision 0267): nothing reads Ctx::pending.
        bindArgs(c, f, binds);
        runBody(c, *code, inst, f);
        c.stackTop = f;
        return f;
    }
    uint8_t* savedPending = c.pending;
    c.pending = f;
    if (directInputs) bindArgs(c, f, binds);
    else
        for (Stmt* s : inputs) s->exec(c);
    runBody(c, *code, inst, f);
    for (Stmt* s : outputs) s->exec(c);
    c.pending = savedPending;
    c.stackTop = f;
    return f;
}

namespace {
// The inlined form of a call (decision 0317): the same depth rule as
// pushFrame (the callee is a leaf, so nothing inside it looks at the depth),
// the callee's variables initialised and its inputs bound in the caller's
// frame, then its body. Returns the callee's area, or nullptr when the call
// is one too deep.
template <bool OnInstance>
[[gnu::always_inline]] inline uint8_t* runInlinedCall(Ctx& c, CallPou& call) {
    uint8_t* inst = nullptr;
    if constexpr (OnInstance) inst = call.instance->addr(c);  // before the arguments, as in runFramed
    if (__builtin_expect(c.depth >= kMaxCallDepth, 0)) {
        reportCallDepth(c, call.site, call.callee->name);
        return nullptr;
    }
    const InlinedCall& in = *call.inlined;
    uint8_t* f = prepareInlinedCall(c, in);
    runInlinedBody<OnInstance>(c, in, call.callee->name, inst);
    return f;
}
}  // namespace

template <bool OnInstance>
uint8_t* CallPou::runInlined(Ctx& c) {
    return runInlinedCall<OnInstance>(c, *this);
}
template uint8_t* CallPou::runInlined<false>(Ctx&);
template uint8_t* CallPou::runInlined<true>(Ctx&);

int64_t CallPou::iInlined(Ctx& c) {
    uint8_t* f = runInlinedCall<false>(c, *this);
    if (!f) return 0;
    const uint8_t* r = f + inlined->resultOffset;
    // DINT and BOOL results, the common ones, without loadIntRep's jump table.
    if (rep == ResultRep::I32) return loadAs<int32_t>(r);
    if (rep == ResultRep::U8) return loadAs<uint8_t>(r);
    return loadIntRep(r, rep);
}

// The result is stored with the caller's type, which is the result's own
// (AssignCallLocal::sameType): its bytes are copied. 0 after CALL_DEPTH.
template <unsigned Bytes>
Flow CallPou::runInlinedInto(Ctx& c, uint8_t* dst) {
    uint8_t* f = runInlinedCall<false>(c, *this);
    uint8_t v[Bytes] = {};
    if (f) std::memcpy(v, f + inlined->resultOffset, Bytes);
    std::memcpy(dst, v, Bytes);
    return Flow::Next;
}
template Flow CallPou::runInlinedInto<1>(Ctx&, uint8_t*);
template Flow CallPou::runInlinedInto<2>(Ctx&, uint8_t*);
template Flow CallPou::runInlinedInto<4>(Ctx&, uint8_t*);
template Flow CallPou::runInlinedInto<8>(Ctx&, uint8_t*);

}  // namespace strun::exec
