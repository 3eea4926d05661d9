// Calls between POUs. A call reserves a frame on the task's frame stack
// (function/method locals, VAR_TEMP, temporaries), initialises it from the
// callee's frame image, binds the arguments, runs the body and unbinds the
// outputs. Nesting deeper than kMaxCallDepth reports CALL_DEPTH (the runtime
// then STOPs the PLC) and the call yields 0.
#pragma once

#include "interpreter/exec/stmt_nodes.h"

namespace strun::exec {

constexpr int kMaxCallDepth = 16;

struct PouCode;

// The run-time class of a FUNCTION_BLOCK instance: every FB instance starts
// with a pointer to its ClassDesc, so methods called through THIS, SUPER's
// callers, pointers, references and interfaces reach the override of the
// instance's actual type. `methods` is indexed by the project-wide method
// slot of a method name; `interfaces` lists the INTERFACEs the class implements.
struct ClassDesc {
    std::string name;
    PouCode* body = nullptr;  // the block's own body: `p^()` through a POINTER TO its base runs this one
    std::vector<PouCode*> methods;
    std::vector<const void*> interfaces;
    bool implements(const void* itf) const {
        for (const void* i : interfaces)
            if (i == itf) return true;
        return false;
    }
};

// The executable form of one POU (program, function, FB body, method).
// Frames up to this size are initialised by a fixed-size copy (two vector
// moves instead of a memcpy call): their images are padded to it, and the
// bytes above a small frame are free stack when it is pushed.
constexpr uint32_t kSmallFrame = 32;
inline size_t frameImageSize(uint32_t frameSize) { return std::max(frameSize, kSmallFrame); }

struct PouCode {
    std::string name;
    Block* body = nullptr;
    // `body` held inline when it has at most two statements and no labels
    // (decision 0266): set by the checker once the body is final; a POU
    // without it runs its Block.
    Body inlineBody;
    bool hasInlineBody = false;
    uint32_t frameSize = 0;
    // The part of the frame a call initialises from `frameInit` (the POU's
    // variables and its own temporaries). Above it, up to frameSize, lie the
    // areas of the small FUNCTIONs inlined into this body (decision 0317),
    // which each inlined call initialises itself.
    uint32_t initSize = 0;
    std::vector<uint8_t> frameInit;  // initial image of the frame (locals with their initial values), frameImageSize(initSize) bytes
    uint32_t resultOffset = 0;       // FUNCTION / METHOD result, in the frame
    bool library = false;            // declared in the embedded standard library
};

void reportCallDepth(Ctx& c, const Site& site, const std::string& callee);

// Pushes a frame for `code`; returns nullptr (after reporting) when nesting is too deep.
inline uint8_t* pushFrame(Ctx& c, const PouCode& code, const Site& site) {
    uint8_t* f = reinterpret_cast<uint8_t*>((reinterpret_cast<uintptr_t>(c.stackTop) + 15) & ~uintptr_t(15));
    if (__builtin_expect(c.depth >= kMaxCallDepth || f + frameImageSize(code.frameSize) > c.stackEnd, 0)) {
        reportCallDepth(c, site, code.name);
        return nullptr;
    }
    if (code.initSize <= kSmallFrame) std::memcpy(f, code.frameInit.data(), kSmallFrame);
    else std::memcpy(f, code.frameInit.data(), code.initSize);
    c.stackTop = f + code.frameSize;
    return f;
}

// Runs `code` on instance `inst` in the already pushed frame `f`, one call
// level deeper, and restores the caller's registers afterwards.
// Always inlined: out of line (as GCC chose once a call had two paths into
// it) a call costs about 10 % more instructions (decision 0267).
[[gnu::always_inline]] inline void runBody(Ctx& c, const PouCode& code, uint8_t* inst, uint8_t* f) {
    uint8_t* savedSelf = c.self;
    uint8_t* savedFrame = c.frame;
    const Stmt* savedStmt = c.stmt;
    const std::string* savedPou = c.pouName;
    c.self = inst;
    c.frame = f;
    c.pouName = &code.name;
    // Entering the library from user code: remember where (see Ctx::userStmt).
    const bool entersLibrary = code.library && !c.userStmt;
    if (entersLibrary) {
        c.userStmt = savedStmt;
        c.userPou = savedPou;
    }
    ++c.depth;
    if (code.hasInlineBody) code.inlineBody.run(c);
    else code.body->exec(c);
    --c.depth;
    if (entersLibrary) {
        c.userStmt = nullptr;
        c.userPou = nullptr;
    }
    c.self = savedSelf;
    c.frame = savedFrame;
    c.stmt = savedStmt;
    c.pouName = savedPou;
}

[[gnu::noinline]] void runBodyOutOfLine(Ctx& c, const PouCode& code, uint8_t* inst, uint8_t* f);

enum class ResultRep : uint8_t { None, I8, I16, I32, I64, U8, U16, U32, U64, F32, F64, Addr };

inline int64_t loadIntRep(const uint8_t* p, ResultRep r) {
    switch (r) {
        case ResultRep::I8: return loadAs<int8_t>(p);
        case ResultRep::I16: return loadAs<int16_t>(p);
        case ResultRep::I32: return loadAs<int32_t>(p);
        case ResultRep::I64: return loadAs<int64_t>(p);
        case ResultRep::U8: return loadAs<uint8_t>(p);
        case ResultRep::U16: return loadAs<uint16_t>(p);
        case ResultRep::U32: return loadAs<uint32_t>(p);
        case ResultRep::U64: return static_cast<int64_t>(loadAs<uint64_t>(p));
        default: return 0;
    }
}

// One argument of a FUNCTION or METHOD call stored straight into the callee
// frame, without a statement node and, for a constant or a variable of the
// caller, without a value node (decision 0154). What it stores is what
// AssignPending / AssignConstLocal would store: the low bytes of the integer
// value, 0/1 for BOOL, the value rounded to REAL or LREAL. The stored width
// is part of `how`, so that binding one argument takes a single dispatch.
struct ArgBind {
    enum class How : uint8_t {
        Const1, Const2, Const4, Const8,              // the stored bytes `bits`
        CopySelf1, CopySelf2, CopySelf4, CopySelf8,  // the caller's instance variable at `src`
        CopyFrame1, CopyFrame2, CopyFrame4, CopyFrame8,
        Int1, Int2, Int4, Int8,                      // value->i
        Bool, F32, F64,                              // value->i != 0, value->f
        End                                          // ends an inlined call's list (InlinedCall::binds)
    };
    How how = How::Int8;
    uint32_t dst = 0;    // offset in the callee frame
    uint32_t src = 0;    // CopySelf / CopyFrame: offset of the caller's variable
    uint64_t bits = 0;   // Const: the stored bytes
    Expr* value = nullptr;  // Int / Bool / F32 / F64
};

// Binds the arguments in order into the callee frame `f` (or, for a
// FUNCTION_BLOCK call, into the instance `f`).
[[gnu::always_inline]] inline void bindArgs(Ctx& c, uint8_t* f, const std::vector<ArgBind>& binds) {
    using H = ArgBind::How;
    for (const ArgBind& a : binds) {
        uint8_t* p = f + a.dst;
        switch (a.how) {
            case H::Const1: storeAs<uint8_t>(p, static_cast<uint8_t>(a.bits)); break;
            case H::Const2: storeAs<uint16_t>(p, static_cast<uint16_t>(a.bits)); break;
            case H::Const4: storeAs<uint32_t>(p, static_cast<uint32_t>(a.bits)); break;
            case H::Const8: storeAs<uint64_t>(p, a.bits); break;
            case H::CopySelf1: storeAs<uint8_t>(p, loadAs<uint8_t>(c.self + a.src)); break;
            case H::CopySelf2: storeAs<uint16_t>(p, loadAs<uint16_t>(c.self + a.src)); break;
            case H::CopySelf4: storeAs<uint32_t>(p, loadAs<uint32_t>(c.self + a.src)); break;
            case H::CopySelf8: storeAs<uint64_t>(p, loadAs<uint64_t>(c.self + a.src)); break;
            case H::CopyFrame1: storeAs<uint8_t>(p, loadAs<uint8_t>(c.frame + a.src)); break;
            case H::CopyFrame2: storeAs<uint16_t>(p, loadAs<uint16_t>(c.frame + a.src)); break;
            case H::CopyFrame4: storeAs<uint32_t>(p, loadAs<uint32_t>(c.frame + a.src)); break;
            case H::CopyFrame8: storeAs<uint64_t>(p, loadAs<uint64_t>(c.frame + a.src)); break;
            case H::Int1: storeAs<uint8_t>(p, static_cast<uint8_t>(a.value->i(c))); break;
            case H::Int2: storeAs<uint16_t>(p, static_cast<uint16_t>(a.value->i(c))); break;
            case H::Int4: storeAs<uint32_t>(p, static_cast<uint32_t>(a.value->i(c))); break;
            case H::Int8: storeAs<uint64_t>(p, static_cast<uint64_t>(a.value->i(c))); break;
            case H::Bool: storeAs<uint8_t>(p, a.value->i(c) != 0); break;
            case H::F32: storeAs<float>(p, static_cast<float>(a.value->f(c))); break;
            case H::F64: storeAs<double>(p, a.value->f(c)); break;
            default: __builtin_unreachable();  // every How is a case: no range check per argument
        }
    }
}

// bindArgs over a list ended by How::End (an inlined call's own list): no
// end pointer kept in a register and compared per argument.
[[gnu::always_inline]] inline void bindArgsUntilEnd(Ctx& c, uint8_t* f, const ArgBind* a) {
    using H = ArgBind::How;
    for (;; ++a) {
        uint8_t* p = f + a->dst;
        switch (a->how) {
            case H::Const1: storeAs<uint8_t>(p, static_cast<uint8_t>(a->bits)); break;
            case H::Const2: storeAs<uint16_t>(p, static_cast<uint16_t>(a->bits)); break;
            case H::Const4: storeAs<uint32_t>(p, static_cast<uint32_t>(a->bits)); break;
            case H::Const8: storeAs<uint64_t>(p, a->bits); break;
            case H::CopySelf1: storeAs<uint8_t>(p, loadAs<uint8_t>(c.self + a->src)); break;
            case H::CopySelf2: storeAs<uint16_t>(p, loadAs<uint16_t>(c.self + a->src)); break;
            case H::CopySelf4: storeAs<uint32_t>(p, loadAs<uint32_t>(c.self + a->src)); break;
            case H::CopySelf8: storeAs<uint64_t>(p, loadAs<uint64_t>(c.self + a->src)); break;
            case H::CopyFrame1: storeAs<uint8_t>(p, loadAs<uint8_t>(c.frame + a->src)); break;
            case H::CopyFrame2: storeAs<uint16_t>(p, loadAs<uint16_t>(c.frame + a->src)); break;
            case H::CopyFrame4: storeAs<uint32_t>(p, loadAs<uint32_t>(c.frame + a->src)); break;
            case H::CopyFrame8: storeAs<uint64_t>(p, loadAs<uint64_t>(c.frame + a->src)); break;
            case H::Int1: storeAs<uint8_t>(p, static_cast<uint8_t>(a->value->i(c))); break;
            case H::Int2: storeAs<uint16_t>(p, static_cast<uint16_t>(a->value->i(c))); break;
            case H::Int4: storeAs<uint32_t>(p, static_cast<uint32_t>(a->value->i(c))); break;
            case H::Int8: storeAs<uint64_t>(p, static_cast<uint64_t>(a->value->i(c))); break;
            case H::Bool: storeAs<uint8_t>(p, a->value->i(c) != 0); break;
            case H::F32: storeAs<float>(p, static_cast<float>(a->value->f(c))); break;
            case H::F64: storeAs<double>(p, a->value->f(c)); break;
            case H::End: return;
            default: __builtin_unreachable();
        }
    }
}

// One input of an inlined function-block call in the forms most inputs take
// (decision 0472): a constant of 1 or 4 bytes, or a node's value stored as
// 4 bytes (ArgBind Int4) or as a BOOL 0/1 (ArgBind Bool), told apart by two
// tests of data instead of ArgBind's jump table. The list's last entry has
// `last` set (the list is never empty). Copies of the caller's variables
// keep the ArgBind list: telling them apart here cost more than the jump
// table saved (fb_calls +1.0 %, fb_io +2.5 % instructions).
struct QuickArg {
    Expr* value = nullptr;  // null: store the constant `bits`
    uint32_t dst = 0;       // offset in the instance
    uint32_t bits = 0;      // the constant's bytes as stored (a 1-byte one in the first)
    bool oneByte = false;   // one byte: the constant's first byte, or the value as BOOL
    bool last = false;
};

// Stores the inputs of `a` (ending at the one marked last) into `inst`, in order.
[[gnu::always_inline]] inline void bindQuickArgs(Ctx& c, uint8_t* inst, const QuickArg* a) {
    for (;; ++a) {
        if (!a->value) {
            if (a->oneByte) storeAs<uint8_t>(inst + a->dst, loadAs<uint8_t>(reinterpret_cast<const uint8_t*>(&a->bits)));
            else storeAs<uint32_t>(inst + a->dst, a->bits);
        } else {
            const int64_t v = a->value->i(c);
            // The destination is computed after the value's call, so that only
            // the list, inst and c live across it.
            if (a->oneByte) storeAs<uint8_t>(inst + a->dst, v != 0);
            else storeAs<uint32_t>(inst + a->dst, static_cast<uint32_t>(v));
        }
        if (a->last) return;
    }
}

// A small leaf FUNCTION inlined at its call (decision 0317): its body was
// checked a second time with its variables at `base` in the caller's frame,
// so the call pushes no frame and switches no registers but the POU name.
// `image` is the callee's initial frame with this call's constant arguments
// already in place, so that only the other arguments are bound per call.
struct InlinedCall {
    Body body;
    // The body's one statement, when it has exactly one (and no label): run
    // with its tick directly, without Body::run's tests.
    Stmt* single = nullptr;
    // A body of more than two statements (body.block set; an inlined body has
    // no labels): its statements ended by a null entry, run by runInlinedList
    // without Block::exec's index, count and reloaded vector (decision 0481).
    std::vector<Stmt*> list;
    // The arguments bound per call (the constant ones are in `image`), ended
    // by How::End. Unused by a block call, which binds its inputs (into the
    // instance) from its own list.
    std::vector<ArgBind> binds;
    // How a FUNCTION's or METHOD's call binds them (decision 0404): none at
    // all, one 4-byte integer (`arg` stored at `argDst`, without the list's
    // dispatch), several 4-byte integers computed per call (`ints`, decision
    // 0471: no dispatch per argument), or the list.
    enum class Args : uint8_t { None, One4, Int4s, List };
    Args args = Args::List;
    Expr* arg = nullptr;
    uint32_t argDst = 0;
    // Args::Int4s: each argument's value node and its offset in the area,
    // in the call's order, ended by a null `value`.
    struct IntArg {
        Expr* value = nullptr;
        uint32_t dst = 0;
    };
    std::vector<IntArg> ints;
    // The area holds only the result and inputs that are bound per call or
    // read as their arguments (decision 0404): only the result is
    // initialised, from `resultInit` (its 8 bytes of the image).
    bool resultOnly = false;
    uint64_t resultInit = 0;
    uint32_t base = 0;
    bool onInstance = false;      // a METHOD: its body runs on the call's instance (self)
    uint32_t size = 0;            // bytes of `image` copied per call (0: nothing to initialise)
    std::vector<uint8_t> image;   // frameImageSize(size) bytes
    uint32_t resultOffset = 0;    // a FUNCTION's / METHOD's result, from the start of the area
    // A block call on a variable of the caller's instance: the instance is
    // c.self + instanceOffset, without the virtual call to its place node.
    bool instanceOnSelf = false;
    uint32_t instanceOffset = 0;
};

// The area of an inlined call in the caller's frame, initialised from its image.
[[gnu::always_inline]] inline uint8_t* initInlinedArea(Ctx& c, const InlinedCall& in) {
    uint8_t* f = c.frame + in.base;
    if (in.size <= kSmallFrame) std::memcpy(f, in.image.data(), kSmallFrame);
    else std::memcpy(f, in.image.data(), in.size);
    return f;
}

// The area of an inlined FUNCTION's or METHOD's call, initialised (only its
// result when nothing else is read before the call writes it), and its
// per-call arguments bound.
[[gnu::always_inline]] inline uint8_t* prepareInlinedCall(Ctx& c, const InlinedCall& in) {
    uint8_t* f = c.frame + in.base;
    if (in.resultOnly) storeAs<uint64_t>(f + in.resultOffset, in.resultInit);
    else if (in.size <= kSmallFrame) std::memcpy(f, in.image.data(), kSmallFrame);
    else std::memcpy(f, in.image.data(), in.size);
    if (in.args == InlinedCall::Args::One4) storeAs<uint32_t>(f + in.argDst, static_cast<uint32_t>(in.arg->i(c)));
    else if (in.args == InlinedCall::Args::Int4s) {
        // The destination is computed after the value's call, so that it
        // does not live across it (no spill per argument).
        for (const InlinedCall::IntArg* a = in.ints.data(); a->value; ++a) {
            const uint32_t v = static_cast<uint32_t>(a->value->i(c));
            storeAs<uint32_t>(f + a->dst, v);
        }
    } else if (in.args == InlinedCall::Args::List) bindArgsUntilEnd(c, f, in.binds.data());
    return f;
}

// The statements of InlinedCall::list, each ticked as Block::exec ticks it,
// until the null entry or the first one that does not continue (RETURN, an
// abort: an inlined body has no labels, so no Jump to resolve). Only the
// list pointer and c live across each statement's call.
[[gnu::always_inline]] inline void runInlinedList(Ctx& c, Stmt* const* p) {
    for (; *p; ++p) {
        c.stmt = *p;
        if (tickAborts(c)) return;
        if ((*p)->exec(c) != Flow::Next) return;
    }
}

// Runs an inlined body with the POU name (and with `OnInstance` the
// instance, self) switched for its duration, so that a watchdog or a test
// failure names the callee; restores them and the caller's statement.
// `TrySingle`: run InlinedCall::single directly when set (FUNCTION and
// METHOD calls; a block body, often of two statements, paid the extra test).
template <bool OnInstance, bool TrySingle = true>
[[gnu::always_inline]] inline void runInlinedBody(Ctx& c, const InlinedCall& in, const std::string& name, uint8_t* inst) {
    const Stmt* savedStmt = c.stmt;
    const std::string* savedPou = c.pouName;
    uint8_t* savedSelf = c.self;
    if constexpr (OnInstance) c.self = inst;
    c.pouName = &name;
    if (Stmt* s = TrySingle ? in.single : nullptr) {
        c.stmt = s;
        if (!tickAborts(c)) s->exec(c);
    } else if (in.body.block) {
        runInlinedList(c, in.list.data());
    } else {
        in.body.runPinned(c);  // always inlined here (decision 0410)
    }
    if constexpr (OnInstance) c.self = savedSelf;
    c.stmt = savedStmt;
    c.pouName = savedPou;
}

// FUNCTION call, or METHOD call (then `instance` gives the FB instance).
// Inputs are stores into the new frame (places relative to Ctx::pending);
// outputs are stores from the frame into the caller's places, evaluated
// while Ctx::pending still points at the callee frame.
struct CallPou final : Expr {
    PouCode* callee = nullptr;
    Expr* instance = nullptr;        // methods: the instance (self) the method runs on
    std::vector<Stmt*> inputs;
    std::vector<ArgBind> binds;      // the inputs in direct form, when every input has one
    bool directInputs = false;       // bind with `binds` instead of running `inputs`
    std::vector<Stmt*> outputs;
    Site site;
    ResultRep rep = ResultRep::None;
    uint32_t resultSize = 0;         // aggregates: bytes copied to the caller's temporary
    uint32_t tempOffset = 0;         // aggregates: caller-frame temporary receiving the result
    int virtualSlot = -1;            // >= 0: the method is looked up in the instance's ClassDesc
    InlinedCall* inlined = nullptr;  // set: the callee's body runs in the caller's frame
    // `inlined` is set and is not a METHOD's (its body runs on the caller's
    // instance): what AssignCallLocal tests to tail-call runInlinedInto.
    bool inlinedOnCaller = false;

    // Runs the call; returns the (already popped) callee frame, or nullptr if it did not run.
    // Both forms are functions of their own: sharing one, the inlined form
    // paid the general form's register saves (19 instructions a call).
    [[gnu::always_inline]] uint8_t* run(Ctx& c) {
        if (!inlined) return runFramed(c);
        return inlined->onInstance ? runInlined<true>(c) : runInlined<false>(c);
    }
    // Defined once, in call_nodes.cpp: inline here, every file that built a
    // CallPou compiled a copy, GCC inlined the callee's statements into some
    // copies and not others, and the linker kept whichever came first.
    [[gnu::noinline]] uint8_t* runFramed(Ctx& c);
    // The inlined form: the same depth rule as pushFrame (the callee is a leaf,
    // so nothing inside it looks at the depth), the callee's variables
    // initialised and its inputs bound in the caller's frame, then its body.
    template <bool OnInstance>
    [[gnu::noinline]] uint8_t* runInlined(Ctx& c);
    // An inlined FUNCTION call and the use of its integer result fused in one
    // function (call_nodes.cpp): the value (iInlined) or the result's Bytes
    // stored at `dst` (x := F(...) of the result's own type), so that the
    // node holding the call pays no second call and register saves.
    [[gnu::noinline]] int64_t iInlined(Ctx& c);
    template <unsigned Bytes>
    [[gnu::noinline]] Flow runInlinedInto(Ctx& c, uint8_t* dst);  // Flow::Next
    PouCode* dispatch(Ctx& c, uint8_t* inst);  // faults.cpp: NULL_POINTER when unbound
    int64_t i(Ctx& c) override {
        if (inlined && !inlined->onInstance) return iInlined(c);  // (not inlinedOnCaller: +4 % in CallPou::i of framed calls)
        uint8_t* f = run(c);
        return f ? loadIntRep(f + callee->resultOffset, rep) : 0;
    }
    double f(Ctx& c) override {
        uint8_t* fr = run(c);
        if (!fr) return 0;
        return rep == ResultRep::F32 ? static_cast<double>(loadAs<float>(fr + callee->resultOffset))
                                     : loadAs<double>(fr + callee->resultOffset);
    }
    uint8_t* addr(Ctx& c) override {
        uint8_t* fr = run(c);
        uint8_t* dst = c.frame + tempOffset;
        if (fr) std::memmove(dst, fr + callee->resultOffset, resultSize);
        else std::memset(dst, 0, resultSize);
        return dst;
    }
};

// x := F(...) with x a scalar of the instance or frame: AssignLocal with the
// call's value computed by a direct (non-virtual) call.
template <class T>
constexpr ResultRep resultRepFor() {
    if constexpr (std::is_same_v<T, int8_t>) return ResultRep::I8;
    else if constexpr (std::is_same_v<T, int16_t>) return ResultRep::I16;
    else if constexpr (std::is_same_v<T, int32_t>) return ResultRep::I32;
    else if constexpr (std::is_same_v<T, int64_t>) return ResultRep::I64;
    else if constexpr (std::is_same_v<T, uint8_t>) return ResultRep::U8;
    else if constexpr (std::is_same_v<T, uint16_t>) return ResultRep::U16;
    else if constexpr (std::is_same_v<T, uint32_t>) return ResultRep::U32;
    else if constexpr (std::is_same_v<T, uint64_t>) return ResultRep::U64;
    else return ResultRep::None;
}

template <class T, bool FRAME>
struct AssignCallLocal final : Stmt {
    uint32_t off;
    CallPou* call;
    bool sameType;  // the result is stored as T: copied without the ResultRep switch
    AssignCallLocal(uint32_t o, CallPou* k) : off(o), call(k), sameType(k->rep == resultRepFor<T>() && k->rep != ResultRep::None) {}
    Flow exec(Ctx& c) override {
        if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
            // An inlined FUNCTION whose result has T's own type: one function
            // does the call and the store, tail-called (c.self and c.frame are
            // the same after an inlined FUNCTION, so the target is too).
            if (sameType && call->inlinedOnCaller) return call->runInlinedInto<sizeof(T)>(c, (FRAME ? c.frame : c.self) + off);
            return storeOutOfLine(c);  // keeps this function free of register saves
        } else {
            return store(c);
        }
    }
    [[gnu::noinline]] Flow storeOutOfLine(Ctx& c) { return store(c); }
    [[gnu::always_inline]] Flow store(Ctx& c) {
        if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
            if (sameType) {
                uint8_t* f = call->run(c);
                T v = f ? loadAs<T>(f + call->callee->resultOffset) : T(0);
                storeAs<T>((FRAME ? c.frame : c.self) + off, v);
                return Flow::Next;
            }
        }
        if constexpr (std::is_floating_point_v<T>) {
            T v = static_cast<T>(call->CallPou::f(c));
            storeAs<T>((FRAME ? c.frame : c.self) + off, v);
        } else if constexpr (std::is_same_v<T, bool>) {
            uint8_t v = call->CallPou::i(c) != 0;
            storeAs<uint8_t>((FRAME ? c.frame : c.self) + off, v);
        } else {
            T v = static_cast<T>(call->CallPou::i(c));
            storeAs<T>((FRAME ? c.frame : c.self) + off, v);
        }
        return Flow::Next;
    }
};

// FUNCTION_BLOCK call statement: inputs and outputs are plain stores in the
// caller's context (into / out of the instance's members).
// `Dispatch`: the instance is reached through a pointer, reference or
// VAR_IN_OUT of a block that others extend, so it may be of a derived type:
// its class's body runs, as in CODESYS/TwinCAT (decision 0314; TcUnit calls
// its suites through POINTER TO FB_TestSuite). Direct calls do not pay for it.
template <bool Dispatch>
struct CallFbStmtOf final : Stmt {
    PouCode* body = nullptr;
    Expr* instance = nullptr;
    std::vector<Stmt*> inputs;
    // The inputs as direct stores into the instance (offsets in it), when
    // every input has one and the instance is a plain variable (decision 0267).
    std::vector<ArgBind> binds;
    bool directInputs = false;
    std::vector<Stmt*> outputs;
    Site site;
    InlinedCall* inlined = nullptr;  // a small leaf body run on the caller's frame (decision 0317)
    // The inlined form's inputs when every one is a QuickArg (decision 0472;
    // `binds` then holds the same inputs for the framed form).
    std::vector<QuickArg> quick;
    [[gnu::always_inline]] uint8_t* bindInputs(Ctx& c) {
        if (directInputs) {
            uint8_t* inst = instance->addr(c);
            bindArgs(c, inst, binds);
            return inst;
        }
        for (Stmt* s : inputs) s->exec(c);
        return instance->addr(c);
    }
    // bindInputs of the inlined form: the instance's address read inline
    // when it is a variable of the caller's instance.
    // One bindArgs in the function (with two, GCC checked the range of the
    // binding kind at every argument).
    [[gnu::always_inline]] uint8_t* bindInlinedInputs(Ctx& c, const InlinedCall& in) {
        uint8_t* inst = in.instanceOnSelf ? c.self + in.instanceOffset : nullptr;
        if (!quick.empty()) {
            if (!inst) inst = instance->addr(c);
            bindQuickArgs(c, inst, quick.data());
            return inst;
        }
        if (directInputs) {
            if (!inst) inst = instance->addr(c);
            bindArgs(c, inst, binds);
            return inst;
        }
        for (Stmt* s : inputs) s->exec(c);
        return inst ? inst : instance->addr(c);
    }
    // The inlined form, as CallPou::runInlined: the block's VAR_TEMP in an
    // area of the caller's frame, its body run on the instance.
    [[gnu::noinline]] Flow runInlined(Ctx& c) {
        const InlinedCall& in = *inlined;
        uint8_t* inst = bindInlinedInputs(c, in);
        if (__builtin_expect(c.depth >= kMaxCallDepth, 0)) {
            reportCallDepth(c, site, body->name);
            return Flow::Next;
        }
        if (in.size) initInlinedArea(c, in);  // a block without VAR_TEMP has nothing to initialise
        runInlinedBody<true, false>(c, in, body->name, inst);
        if (c.aborting) return Flow::Abort;
        for (Stmt* s : outputs) s->exec(c);
        return Flow::Next;
    }
    // Each form a function of its own, as CallPou::run (the inlined one
    // paid the framed one's register saves when they shared a function).
    Flow exec(Ctx& c) override {
        if constexpr (!Dispatch)
            if (inlined) return runInlined(c);
        return runFramed(c);
    }
    [[gnu::noinline]] Flow runFramed(Ctx& c) {
        uint8_t* inst = bindInputs(c);
        const PouCode* code = body;
        if constexpr (Dispatch) {
            const ClassDesc* cls = loadAs<const ClassDesc*>(inst);
            if (cls && cls->body) code = cls->body;
        }
        uint8_t* f = pushFrame(c, *code, site);
        if (!f) return Flow::Next;
        // Out of line in the dispatching form: inlined in both, the body's
        // Block::exec stopped being inlined into the plain call (+5 %
        // instructions on fb_calls).
        if constexpr (Dispatch) runBodyOutOfLine(c, *code, inst, f);
        else runBody(c, *code, inst, f);
        c.stackTop = f;
        if (c.aborting) return Flow::Abort;
        for (Stmt* s : outputs) s->exec(c);
        return Flow::Next;
    }
};
using CallFbStmt = CallFbStmtOf<false>;
using CallFbDispatchStmt = CallFbStmtOf<true>;
// Compiled once, in call_nodes.cpp: instantiated implicitly, the copy the
// linker kept came from whichever checker file made one, and GCC's inlining
// there (the body's Block::exec) changed with unrelated edits to that file.
extern template struct CallFbStmtOf<false>;
extern template struct CallFbStmtOf<true>;

// ARRAY[*] parameters (VAR_IN_OUT): the slot holds a descriptor
// { address, lo0, hi0, lo1, hi1, ... } filled in at the call.
struct BindArrayDesc final : Stmt {
    Expr* slot;        // place of the descriptor
    Expr* place;       // the caller's array
    Expr* sourceDesc;  // the caller's own ARRAY[*] descriptor, or null (then `bounds`)
    std::vector<int64_t> bounds;
    Flow exec(Ctx& c) override {
        uint8_t* d = slot->addr(c);
        if (sourceDesc) {
            std::memmove(d, sourceDesc->addr(c), 8 + 16 * (bounds.size() / 2));
            return Flow::Next;
        }
        storeAs<uint8_t*>(d, place->addr(c));
        for (size_t k = 0; k < bounds.size(); ++k) storeAs<int64_t>(d + 8 + 8 * k, bounds[k]);
        return Flow::Next;
    }
};

// a[i, j] on an ARRAY[*] parameter: bounds and strides from the descriptor.
// The element number (row-major, from 0) that the subscripts `index` name in
// the array described by `d` ({ address, lo0, hi0, lo1, hi1, ... }). False,
// with the subscript and the bounds it broke in v / lo / hi, when one is out
// of range. Shared by ARRAY[*] parameters and REF_TO ARRAY[*] (flex_ref_nodes.h).
[[gnu::always_inline]] inline bool flexElement(Ctx& c, const uint8_t* d, const std::vector<Expr*>& index, uint64_t& element,
                                               int64_t& v, int64_t& lo, int64_t& hi) {
    element = 0;
    for (size_t k = 0; k < index.size(); ++k) {
        lo = loadAs<int64_t>(d + 8 + 16 * k);
        hi = loadAs<int64_t>(d + 16 + 16 * k);
        v = index[k]->i(c);
        if (__builtin_expect(v < lo || v > hi, 0)) return false;
        element = element * (static_cast<uint64_t>(hi) - static_cast<uint64_t>(lo) + 1) + (static_cast<uint64_t>(v) - static_cast<uint64_t>(lo));
    }
    return true;
}

struct FlexIndexPlace final : Expr {
    Expr* desc;
    std::vector<Expr*> index;
    uint64_t elemSize = 0;
    Site site;
    uint8_t* addr(Ctx& c) override {
        uint8_t* d = desc->addr(c);
        uint64_t element;
        int64_t v, lo, hi;
        if (!flexElement(c, d, index, element, v, lo, hi)) return outOfRange(c, v, lo, hi);
        return loadAs<uint8_t*>(d) + element * elemSize;
    }
    uint8_t* outOfRange(Ctx& c, int64_t v, int64_t lo, int64_t hi);
};

// LOWER_BOUND / UPPER_BOUND of an ARRAY[*] parameter.
struct FlexBound final : Expr {
    Expr* desc;
    size_t offset;  // 8 + 16 * dim (+ 8 for the upper bound)
    FlexBound(Expr* d, size_t o) : desc(d), offset(o) {}
    int64_t i(Ctx& c) override { return loadAs<int64_t>(desc->addr(c) + offset); }
};

// THIS: the address of the current instance, as a pointer value.
struct SelfAddress final : Expr {
    int64_t i(Ctx& c) override { return static_cast<int64_t>(reinterpret_cast<intptr_t>(c.self)); }
};

// An interface or pointer value used as an instance: the address it holds.
// No null check here: the method dispatch that follows reports NULL_POINTER once.
struct AddressValuePlace final : Expr {
    Expr* value;
    explicit AddressValuePlace(Expr* v) : value(v) {}
    uint8_t* addr(Ctx& c) override { return reinterpret_cast<uint8_t*>(static_cast<intptr_t>(value->i(c))); }
};

// itf ?= instance-or-interface: the address when the instance's class
// implements the interface, else 0.
struct TryCastInterface final : Expr {
    Expr* source;  // yields an instance address (0 allowed)
    const void* itf;
    TryCastInterface(Expr* s, const void* i) : source(s), itf(i) {}
    int64_t i(Ctx& c) override {
        auto p = reinterpret_cast<uint8_t*>(static_cast<intptr_t>(source->i(c)));
        if (!p || !c.m->memory.contains(p, sizeof(const ClassDesc*))) return 0;
        auto* desc = loadAs<const ClassDesc*>(p);
        return desc && c.m->memory.isObject(desc) && desc->implements(itf) ? static_cast<int64_t>(reinterpret_cast<intptr_t>(p)) : 0;
    }
};

// CODESYS __QUERYINTERFACE(source, dest): dest := source ?= ..., TRUE when it held.
struct QueryInterface final : Expr {
    Expr* cast;  // a TryCastInterface
    Expr* dest;  // place of the interface variable
    QueryInterface(Expr* c, Expr* d) : cast(c), dest(d) {}
    int64_t i(Ctx& c) override {
        int64_t v = cast->i(c);
        storeAs<int64_t>(dest->addr(c), v);
        return v != 0;
    }
};


// Binds a VAR_IN_OUT: stores the address of the caller's place into the slot.
struct BindAddress final : Stmt {
    Expr* slot;   // place of the 8-byte slot
    Expr* place;  // the caller's storage
    BindAddress(Expr* s, Expr* p) : slot(s), place(p) {}
    Flow exec(Ctx& c) override {
        uint8_t* p = place->addr(c);
        storeAs<uint8_t*>(slot->addr(c), p);
        return Flow::Next;
    }
};

}  // namespace strun::exec

namespace strun::exec {

// A function call with EN/ENO (IEC 61131-3 6.6.1.7; Beremiz writes them for
// LD rungs): EN is evaluated once into a temporary, ENO receives it, and the
// function runs only when it is TRUE; otherwise the call's value is 0
// (decision 0333).
struct EnEnoCall final : Expr {
    Stmt* storeEn;   // temp := EN
    Expr* en;        // reads the temp
    Expr* call;
    Stmt* storeEno;  // ENO := temp; null without ENO
    EnEnoCall(Stmt* s, Expr* e, Expr* f, Stmt* o) : storeEn(s), en(e), call(f), storeEno(o) {}
    bool enabled(Ctx& c) {
        storeEn->exec(c);
        if (storeEno) storeEno->exec(c);
        return en->i(c) != 0;
    }
    int64_t i(Ctx& c) override { return enabled(c) ? call->i(c) : 0; }
    double f(Ctx& c) override { return enabled(c) ? call->f(c) : 0.0; }
};

// A function-block call with EN/ENO (IEC 61131-3; Beremiz writes
// `TON3(EN := x, IN := ...)` for LD rungs): EN is evaluated once into a
// temporary; the call (inputs, body, outputs) runs only when it is TRUE, so
// a block not enabled keeps its outputs; then every ENO place receives EN
// (`ENO => v`, the instance's ENO read as `inst.ENO`; decision 0358).
// Calls without EN/ENO never pass through here.
struct FbEnEnoStmt final : Stmt {
    Stmt* storeEn;  // temp := EN
    Expr* en;       // reads the temp
    Stmt* call;
    std::vector<Stmt*> storeEno;  // each: place := temp
    FbEnEnoStmt(Stmt* s, Expr* e, Stmt* f, std::vector<Stmt*> o) : storeEn(s), en(e), call(f), storeEno(std::move(o)) {}
    Flow exec(Ctx& c) override {
        storeEn->exec(c);
        if (en->i(c) != 0) {
            const Flow f = call->exec(c);
            if (f != Flow::Next) return f;
        }
        for (Stmt* s : storeEno) s->exec(c);
        return Flow::Next;
    }
};

}  // namespace strun::exec
