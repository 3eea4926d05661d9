// Picks the node specialisation for a type's storage representation, so the
// checker can write makeByRep<exec::SelfVar>(pool, type, offset) instead of
// a switch over every width at each use.
#pragma once

#include <cstdint>

#include "interpreter/exec/call_nodes.h"
#include "interpreter/sema/types.h"

namespace strun::sema {

enum class Rep : uint8_t { I8, I16, I32, I64, U8, U16, U32, U64, F32, F64, Bool, Void };

inline Rep repOf(const Type* t) {
    if (!t) return Rep::Void;
    if (t->kind == TK::Enum) return repOf(t->base);
    switch (t->kind) {
        case TK::Bool: return Rep::Bool;
        case TK::SInt: return Rep::I8;
        case TK::Int: return Rep::I16;
        case TK::Time: return t->unsignedDuration ? Rep::U32 : Rep::I32;  // decision 0367
        case TK::DInt: return Rep::I32;
        case TK::LTime: return t->unsignedDuration ? Rep::U64 : Rep::I64;  // decision 0367
        case TK::LInt: case TK::LDate: case TK::LTod: case TK::LDt: return Rep::I64;
        case TK::USInt: case TK::Byte: case TK::Char: return Rep::U8;
        case TK::UInt: case TK::Word: case TK::WChar: return Rep::U16;
        case TK::UDInt: case TK::DWord: case TK::Date: case TK::Tod: case TK::Dt: return Rep::U32;
        case TK::ULInt: case TK::LWord: case TK::Pointer: case TK::Reference: case TK::Interface: return Rep::U64;
        case TK::Real: return Rep::F32;
        case TK::LReal: return Rep::F64;
        default: return Rep::Void;
    }
}

// The representation integer arithmetic and comparisons are computed in:
// operands narrower than 32 bits are promoted to DINT, as CODESYS and C do;
// a result wraps to its type's width only when it is stored (decision 0078).
inline Rep arithmeticRep(Rep r) {
    switch (r) {
        case Rep::I8: case Rep::I16: case Rep::U8: case Rep::U16: case Rep::Bool: return Rep::I32;
        default: return r;
    }
}

// Integer-only node templates (no float/void instantiation).
template <template <class> class N, class... A>
exec::Expr* makeIntByRep(exec::NodePool& pool, Rep rep, A&&... args) {
    switch (rep) {
        case Rep::I8: return pool.make<N<int8_t>>(std::forward<A>(args)...);
        case Rep::I16: return pool.make<N<int16_t>>(std::forward<A>(args)...);
        case Rep::I32: return pool.make<N<int32_t>>(std::forward<A>(args)...);
        case Rep::I64: return pool.make<N<int64_t>>(std::forward<A>(args)...);
        case Rep::U8: case Rep::Bool: return pool.make<N<uint8_t>>(std::forward<A>(args)...);
        case Rep::U16: return pool.make<N<uint16_t>>(std::forward<A>(args)...);
        case Rep::U32: return pool.make<N<uint32_t>>(std::forward<A>(args)...);
        default: return pool.make<N<uint64_t>>(std::forward<A>(args)...);
    }
}

// N<T> for the C++ storage type of `rep` (BOOL stored as uint8_t 0/1).
template <template <class> class N, class... A>
exec::Expr* makeByRep(exec::NodePool& pool, Rep rep, A&&... args) {
    switch (rep) {
        case Rep::F32: return pool.make<N<float>>(std::forward<A>(args)...);
        case Rep::F64: return pool.make<N<double>>(std::forward<A>(args)...);
        case Rep::Void: return pool.make<N<void>>(std::forward<A>(args)...);
        default: return makeIntByRep<N>(pool, rep, std::forward<A>(args)...);
    }
}

template <template <class> class N, class... A>
exec::Expr* makeRealByRep(exec::NodePool& pool, Rep rep, A&&... args) {
    if (rep == Rep::F32) return pool.make<N<float>>(std::forward<A>(args)...);
    return pool.make<N<double>>(std::forward<A>(args)...);
}

inline exec::ResultRep resultRepOf(const Type* t) {
    switch (repOf(t)) {
        case Rep::I8: return exec::ResultRep::I8;
        case Rep::I16: return exec::ResultRep::I16;
        case Rep::I32: return exec::ResultRep::I32;
        case Rep::I64: return exec::ResultRep::I64;
        case Rep::U8: case Rep::Bool: return exec::ResultRep::U8;
        case Rep::U16: return exec::ResultRep::U16;
        case Rep::U32: return exec::ResultRep::U32;
        case Rep::U64: return exec::ResultRep::U64;
        case Rep::F32: return exec::ResultRep::F32;
        case Rep::F64: return exec::ResultRep::F64;
        default: return exec::ResultRep::Addr;
    }
}

}  // namespace strun::sema
