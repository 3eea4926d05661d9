// The slow paths of the evaluator: runtime faults reported to the scheduler
// with the contract's substitute behaviour, and REAL -> integer conversion.
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "interpreter/exec/call_nodes.h"
#include "interpreter/exec/flex_ref_nodes.h"
#include "interpreter/exec/heap_nodes.h"
#include "stdlib/conversions.h"

namespace strun::exec {

namespace {
const std::string kUnknownPou = "?";
const std::string& pouOf(const Site& s) { return s.pou ? *s.pou : kUnknownPou; }

// Where a fault is reported: the node's own site, or, inside library code,
// the user's statement that called the library (Ctx::userStmt).
Site at(const Ctx& c, const Site& s) {
    if (!c.userStmt) return s;
    return Site{c.userPou, c.userStmt->line, c.userStmt->file, c.userStmt->col};
}

uint8_t* sink(Ctx& c) {
    // Large enough for any element: the checker sizes it to the largest type in the project.
    std::memset(c.faultSink, 0, kFaultSinkSize);
    return c.faultSink;
}
}  // namespace

void reportDivByZero(Ctx& c, const Site& site) {
    c.m->handler->onFault(rt::DiagCode::DivByZero, pouOf(at(c, site)), at(c, site).line, "division by zero; divisor 1 used", at(c, site).file, at(c, site).col);
}

void reportCallDepth(Ctx& c, const Site& site, const std::string& callee) {
    // Set first: a handler may let the activation go on (strun test: the refused call gives 0, decision 0253).
    c.aborting = true;
    c.m->expireCountdown();  // the next tick unwinds (decision 0267)
    c.m->handler->onFault(rt::DiagCode::CallDepth, pouOf(at(c, site)), at(c, site).line,
                          fmt::format("call nesting deeper than {} (calling {}): the nesting limit of the PLCs strun emulates; "
                                      "turn the recursion into a loop (docs/limits.md)",
                                      kMaxCallDepth, callee), at(c, site).file, at(c, site).col);
}

uint8_t* IndexPlace::outOfRange(Ctx& c, const Dim& d, int64_t value) {
    c.m->handler->onFault(rt::DiagCode::ArrayBounds, pouOf(at(c, site)), at(c, site).line,
                          fmt::format("subscript {} outside {}..{}", value, d.lo, d.lo + d.count - 1), at(c, site).file, at(c, site).col);
    return sink(c);
}

uint8_t* indexFault(Ctx& c, const Site& site, int64_t value, int64_t lo, int64_t count) {
    c.m->handler->onFault(rt::DiagCode::ArrayBounds, pouOf(at(c, site)), at(c, site).line,
                          fmt::format("subscript {} outside {}..{}", value, lo, lo + count - 1), at(c, site).file, at(c, site).col);
    return sink(c);
}

uint8_t* Index1Place::outOfRange(Ctx& c, int64_t value) {
    c.m->handler->onFault(rt::DiagCode::ArrayBounds, pouOf(at(c, site)), at(c, site).line,
                          fmt::format("subscript {} outside {}..{}", value, lo, lo + count - 1), at(c, site).file, at(c, site).col);
    return sink(c);
}

uint8_t* FlexIndexPlace::outOfRange(Ctx& c, int64_t value, int64_t lo, int64_t hi) {
    c.m->handler->onFault(rt::DiagCode::ArrayBounds, pouOf(at(c, site)), at(c, site).line, fmt::format("subscript {} outside {}..{}", value, lo, hi), at(c, site).file, at(c, site).col);
    return sink(c);
}

namespace {
void reportNullFlexRef(Ctx& c, const Site& site) {
    c.m->handler->onFault(rt::DiagCode::NullPointer, pouOf(at(c, site)), at(c, site).line, "dereference of a NULL REF_TO ARRAY[*]",
                          at(c, site).file, at(c, site).col);
}
}  // namespace

uint8_t* FlexRefDesc::unbound(Ctx& c) {
    reportNullFlexRef(c, site);
    // An empty array (bounds 0..-1) whose address is the sink itself: a
    // FOR over its bounds does nothing, and no element is ever reached.
    uint8_t* d = sink(c);
    storeAs<uint8_t*>(d, d);
    for (size_t k = 0; k < dims; ++k) storeAs<int64_t>(d + 16 + 16 * k, -1);
    return d;
}

uint8_t* FlexRefIndexPlace::unbound(Ctx& c) {
    reportNullFlexRef(c, site);
    return sink(c);
}

uint8_t* FlexRefIndexPlace::outOfRange(Ctx& c, int64_t value, int64_t lo, int64_t hi) {
    c.m->handler->onFault(rt::DiagCode::ArrayBounds, pouOf(at(c, site)), at(c, site).line, fmt::format("subscript {} outside {}..{}", value, lo, hi), at(c, site).file, at(c, site).col);
    return sink(c);
}

uint8_t* RefSlotPlace::badTarget(Ctx& c, const uint8_t* p) {
    const std::string heap = p ? heapDescription(c.m->heap, p) : std::string();
    c.m->handler->onFault(rt::DiagCode::NullPointer, pouOf(at(c, site)), at(c, site).line,
                          !p ? std::string("reference is not bound")
                          : heap.empty() ? std::string("reference leads outside the project's memory") : "reference leads to " + heap,
                          at(c, site).file, at(c, site).col);
    return sink(c);
}

uint8_t* DerefPlace::badTarget(Ctx& c, const uint8_t* p) {
    // A pointer into __NEW memory says what went wrong: released, or read past the block's end.
    const std::string heap = p ? heapDescription(c.m->heap, p) : std::string();
    c.m->handler->onFault(rt::DiagCode::NullPointer, pouOf(at(c, site)), at(c, site).line,
                          !p ? std::string("dereference of a null pointer")
                          : heap.empty() ? std::string("dereference of a pointer outside the project's memory") : "dereference of a pointer to " + heap,
                          at(c, site).file, at(c, site).col);
    return sink(c);
}

void reportMemoryFault(Ctx& c, const Site& site, std::string message) {
    c.m->handler->onFault(rt::DiagCode::NullPointer, pouOf(at(c, site)), at(c, site).line, std::move(message), at(c, site).file, at(c, site).col);
}

void reportLog(Ctx& c, const Site& site, std::string message) {
    c.m->handler->onLog(pouOf(at(c, site)), at(c, site).line, std::move(message), at(c, site).file, at(c, site).col);
}

PouCode* CallPou::dispatch(Ctx& c, uint8_t* inst) {
    // The instance may come from a pointer or interface forged by arithmetic:
    // it must lie in project memory and start with a real class descriptor.
    if (inst && !(c.m->memory.contains(inst, sizeof(const ClassDesc*)) && c.m->memory.isObject(loadAs<const ClassDesc*>(inst)))) {
        c.m->handler->onFault(rt::DiagCode::NullPointer, pouOf(at(c, site)), at(c, site).line,
                              fmt::format("call of {} through a pointer that does not lead to an instance", callee->name), at(c, site).file, at(c, site).col);
        return nullptr;
    }
    const ClassDesc* desc = inst ? loadAs<const ClassDesc*>(inst) : nullptr;
    PouCode* code = desc && static_cast<size_t>(virtualSlot) < desc->methods.size() ? desc->methods[static_cast<size_t>(virtualSlot)] : nullptr;
    if (!code) {
        c.m->handler->onFault(rt::DiagCode::NullPointer, pouOf(at(c, site)), at(c, site).line,
                              inst ? fmt::format("method {} not implemented by the instance", callee->name)
                                   : fmt::format("call of {} through an unbound interface or pointer", callee->name), at(c, site).file, at(c, site).col);
    }
    return code;
}

// Rounding rule and out-of-range behaviour: docs/decisions/0031 (stdlib/conversions.h).
int64_t realToIntRounded(double v, int bits, bool isSigned) {
    return static_cast<int64_t>(stdlib::realToInteger(v, bits, isSigned));
}

int64_t realToIntTruncated(double v, int bits, bool isSigned) {
    return static_cast<int64_t>(stdlib::truncToInteger(v, bits, isSigned));
}

}  // namespace strun::exec
