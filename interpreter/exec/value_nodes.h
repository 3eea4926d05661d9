// Leaves of the resolved tree: constants and variable places. A place node
// both yields its address (for stores, members, aggregates) and loads its
// value in the representation of its storage type T, so reading a variable
// is one virtual call. Struct members of a variable are folded into the
// variable's offset by the checker; only subscripts, dereferences and
// VAR_IN_OUT references are computed at run time.
#pragma once

#include <cmath>
#include <type_traits>

#include "interpreter/exec/node.h"

namespace strun::exec {

template <class T>
inline int64_t toI(T v) {
    if constexpr (std::is_floating_point_v<T>) return static_cast<int64_t>(v);
    else return static_cast<int64_t>(v);
}
template <class T>
inline double toF(T v) { return static_cast<double>(v); }

struct ConstInt final : Expr {
    int64_t v;
    explicit ConstInt(int64_t value) : v(value) {}
    int64_t i(Ctx&) override { return v; }
    double f(Ctx&) override { return static_cast<double>(v); }
};

struct ConstReal final : Expr {
    double v;
    explicit ConstReal(double value) : v(value) {}
    double f(Ctx&) override { return v; }
};

// Constant aggregate (string literal, folded string): its bytes laid out as the type's storage.
struct ConstBytes final : Expr {
    std::vector<uint8_t> bytes;
    explicit ConstBytes(std::vector<uint8_t> b) : bytes(std::move(b)) {}
    uint8_t* addr(Ctx&) override { return bytes.data(); }
};

// Where a variable's storage is: its address is a base plus a fixed offset.
//   Self    the current PROGRAM / FB instance (bodies and methods)
//   Frame   the current call frame (function/method locals, VAR_TEMP)
//   Abs     a fixed address (globals, program instances, the process image)
//   Pending the frame of a call whose arguments are being bound
enum class BaseKind : uint8_t { Self, Frame, Abs, Pending };

template <BaseKind B>
inline uint8_t* baseOf(Ctx& c, uint8_t* abs) {
    if constexpr (B == BaseKind::Self) return c.self;
    else if constexpr (B == BaseKind::Frame) return c.frame;
    else if constexpr (B == BaseKind::Pending) return c.pending;
    else return abs;
}

// A variable: one virtual call yields its address or its value as T.
template <class T, BaseKind B>
struct VarNode final : Expr {
    uint32_t off = 0;
    uint8_t* abs = nullptr;
    explicit VarNode(uint32_t o) : off(o) {}
    explicit VarNode(uint8_t* p) : abs(p) {}
    uint8_t* addr(Ctx& c) override { return baseOf<B>(c, abs) + off; }
    int64_t i(Ctx& c) override {
        if constexpr (std::is_void_v<T>) return 0;
        else return toI(loadAs<T>(baseOf<B>(c, abs) + off));
    }
    double f(Ctx& c) override {
        if constexpr (std::is_void_v<T>) return 0;
        else return toF(loadAs<T>(baseOf<B>(c, abs) + off));
    }
};

template <class T>
using SelfVar = VarNode<T, BaseKind::Self>;
template <class T>
using FrameVar = VarNode<T, BaseKind::Frame>;
template <class T>
using AbsVar = VarNode<T, BaseKind::Abs>;
template <class T>
using PendingVar = VarNode<T, BaseKind::Pending>;

// Storage reached through a computed address (subscript, dereference, member of those).
template <class T>
struct PlaceLoad final : Expr {
    Expr* place;
    explicit PlaceLoad(Expr* p) : place(p) {}
    uint8_t* addr(Ctx& c) override { return place->addr(c); }
    int64_t i(Ctx& c) override {
        if constexpr (std::is_void_v<T>) return 0;
        else return toI(loadAs<T>(place->addr(c)));
    }
    double f(Ctx& c) override {
        if constexpr (std::is_void_v<T>) return 0;
        else return toF(loadAs<T>(place->addr(c)));
    }
};

// A member at a fixed offset from a computed address.
struct OffsetPlace final : Expr {
    Expr* base;
    uint32_t off;
    OffsetPlace(Expr* b, uint32_t o) : base(b), off(o) {}
    uint8_t* addr(Ctx& c) override { return base->addr(c) + off; }
};

// VAR_IN_OUT, REFERENCE TO: the slot holds the address of the referenced storage.
// A slot forged through a UNION, a pointer or a memory copy may hold any
// address: like a pointer dereference, it must lead into project memory.
struct RefSlotPlace final : Expr {
    Expr* slot;  // place of the 8-byte address
    Site site;
    uint32_t targetSize;  // bytes of the referenced storage (1 for ARRAY[*])
    RefSlotPlace(Expr* s, Site st, uint32_t size) : slot(s), site(st), targetSize(size) {}
    uint8_t* addr(Ctx& c) override {
        uint8_t* p = loadAs<uint8_t*>(slot->addr(c));
        if (__builtin_expect(p == nullptr || !c.m->memory.contains(p, targetSize), 0)) return badTarget(c, p);
        return p;
    }
    uint8_t* badTarget(Ctx& c, const uint8_t* p);
};

// p^ : the pointer value (an address) as storage.
// A pointer that is null or does not lead into the project's memory (moved by
// arithmetic, forged) faults with NULL_POINTER and yields the fault sink.
struct DerefPlace final : Expr {
    Expr* pointer;
    Site site;
    uint32_t targetSize;  // bytes the dereference reads or writes
    DerefPlace(Expr* p, Site st, uint32_t size) : pointer(p), site(st), targetSize(size) {}
    uint8_t* addr(Ctx& c) override {
        auto p = reinterpret_cast<uint8_t*>(static_cast<intptr_t>(pointer->i(c)));
        if (__builtin_expect(p == nullptr || !c.m->memory.contains(p, targetSize), 0)) return badTarget(c, p);
        return p;
    }
    uint8_t* badTarget(Ctx& c, const uint8_t* p);
};

// An element of an array reached through a pointer (`PT^[i]` with PT : POINTER
// TO ARRAY[0..32767] OF BYTE, as OSCAT writes buffer code): the pointer only
// has to lead into project memory, and each element access is checked itself,
// because the declared array is usually larger than the buffer pointed at.
struct MemoryCheckedPlace final : Expr {
    Expr* place;
    DerefPlace* deref;  // reports the fault like the dereference would
    uint32_t size;
    MemoryCheckedPlace(Expr* p, DerefPlace* d, uint32_t n) : place(p), deref(d), size(n) {}
    uint8_t* addr(Ctx& c) override {
        uint8_t* p = place->addr(c);
        if (__builtin_expect(!c.m->memory.contains(p, size), 0)) return deref->badTarget(c, p);
        return p;
    }
};

// ADR(x) / REF(x): the address of a place as a pointer value.
struct AddressOf final : Expr {
    Expr* place;
    explicit AddressOf(Expr* p) : place(p) {}
    int64_t i(Ctx& c) override { return static_cast<int64_t>(reinterpret_cast<intptr_t>(place->addr(c))); }
};

// a[i, j, ...]: bounds-checked element address. Out of range: ARRAY_BOUNDS
// goes to the runtime, and the access is redirected to a zeroed sink so the
// read yields 0 and the write is dropped.
struct IndexPlace final : Expr {
    struct Dim { Expr* index; int64_t lo; int64_t count; uint64_t stride; };
    Expr* base;
    std::vector<Dim> dims;
    Site site;
    uint8_t* addr(Ctx& c) override {
        uint64_t offset = 0;
        for (const Dim& d : dims) {
            int64_t k = static_cast<int64_t>(static_cast<uint64_t>(d.index->i(c)) - static_cast<uint64_t>(d.lo));
            if (__builtin_expect(static_cast<uint64_t>(k) >= static_cast<uint64_t>(d.count), 0)) return outOfRange(c, d, static_cast<int64_t>(static_cast<uint64_t>(k) + static_cast<uint64_t>(d.lo)));
            offset += static_cast<uint64_t>(k) * d.stride;
        }
        return base->addr(c) + offset;
    }
    uint8_t* outOfRange(Ctx& c, const Dim& d, int64_t value);
};

// One-dimensional fast path.
struct Index1Place final : Expr {
    Expr* base;
    Expr* index;
    int64_t lo, count;
    uint64_t stride;
    Site site;
    uint8_t* addr(Ctx& c) override {
        int64_t k = static_cast<int64_t>(static_cast<uint64_t>(index->i(c)) - static_cast<uint64_t>(lo));
        if (__builtin_expect(static_cast<uint64_t>(k) >= static_cast<uint64_t>(count), 0)) return outOfRange(c, static_cast<int64_t>(static_cast<uint64_t>(k) + static_cast<uint64_t>(lo)));
        return base->addr(c) + static_cast<uint64_t>(k) * stride;
    }
    uint8_t* outOfRange(Ctx& c, int64_t value);
};

// Reports ARRAY_BOUNDS and returns the zeroed fault sink (faults.cpp).
uint8_t* indexFault(Ctx& c, const Site& site, int64_t value, int64_t lo, int64_t count);
// A memory function (MEMCPY, ...) given a range outside the project's memory: NULL_POINTER.
void reportMemoryFault(Ctx& c, const Site& site, std::string message);
// A message the program logs (Tc2_System ADSLOGSTR ...): LOG in the diagnostic buffer.
void reportLog(Ctx& c, const Site& site, std::string message);

// a[i] on an array variable at a known place (instance, frame or absolute):
// the element address and its load in one node, the hot path of array code.
// The subscript is read inside the node when it is a DINT or INT variable of
// the instance or frame, plus a constant (a[i], a[j + 1]): computed in DINT
// with wrap-around, exactly as the index expression would be (decision 0151).
enum class IndexFrom : uint8_t { Node, Self32, Frame32, Self16, Frame16 };
struct Index1Fields {
    uint32_t off = 0;
    uint8_t* abs = nullptr;
    Expr* index = nullptr;
    int64_t lo = 0, count = 0;
    uint64_t stride = 0;
    Site site;
    uint32_t indexOff = 0;  // IndexFrom other than Node: the index variable
    int32_t indexAdd = 0;   // and the constant added to it
};
template <IndexFrom IX>
inline int64_t readIndex(Ctx& c, const Index1Fields& f) {
    if constexpr (IX == IndexFrom::Node) return f.index->i(c);
    else {
        constexpr bool self = IX == IndexFrom::Self32 || IX == IndexFrom::Self16;
        const uint8_t* p = (self ? c.self : c.frame) + f.indexOff;
        int32_t v = (IX == IndexFrom::Self32 || IX == IndexFrom::Frame32) ? loadAs<int32_t>(p) : loadAs<int16_t>(p);
        return static_cast<int32_t>(static_cast<uint32_t>(v) + static_cast<uint32_t>(f.indexAdd));
    }
}
// The address of element readIndex() of a one-dimensional array variable:
// an index outside the bounds reports ARRAY_BOUNDS and yields the fault sink.
template <BaseKind B, IndexFrom IX>
inline uint8_t* index1Address(Ctx& c, const Index1Fields& f) {
    int64_t k = static_cast<int64_t>(static_cast<uint64_t>(readIndex<IX>(c, f)) - static_cast<uint64_t>(f.lo));
    if (__builtin_expect(static_cast<uint64_t>(k) >= static_cast<uint64_t>(f.count), 0))
        return indexFault(c, f.site, static_cast<int64_t>(static_cast<uint64_t>(k) + static_cast<uint64_t>(f.lo)), f.lo, f.count);
    uint8_t* base = B == BaseKind::Abs ? f.abs : baseOf<B>(c, nullptr) + f.off;
    return base + static_cast<uint64_t>(k) * f.stride;
}

// a[i] as the target of an assignment: the store can compute the element's
// address itself (fused_nodes.h, decision 0154).
struct Index1Target : Expr, Index1Fields {
    // place := value, for the element's scalar representation (`boolean`: BOOL,
    // stored as 0/1); a constant value is stored as its bytes. Null for
    // elements that are not scalars.
    virtual Stmt* makeStore(NodePool& pool, Expr* value, bool boolean) = 0;
};

template <class T, BaseKind B, IndexFrom IX = IndexFrom::Node>
struct Index1Var final : Index1Target {
    uint8_t* addr(Ctx& c) override { return index1Address<B, IX>(c, *this); }
    int64_t i(Ctx& c) override {
        if constexpr (std::is_void_v<T>) return 0;
        else return toI(loadAs<T>(addr(c)));
    }
    double f(Ctx& c) override {
        if constexpr (std::is_void_v<T>) return 0;
        else return toF(loadAs<T>(addr(c)));
    }
    Stmt* makeStore(NodePool& pool, Expr* value, bool boolean) override;  // fused_nodes.h
};

// x.3 — one bit of an integer / bit-string place; also BOOL AT %IX0.3.
template <class T>
struct BitPlace final : Expr {
    Expr* base;
    int bit;
    BitPlace(Expr* b, int n) : base(b), bit(n) {}
    int bitIndex() const override { return bit; }
    uint8_t* addr(Ctx& c) override { return base->addr(c); }
    int64_t i(Ctx& c) override { return (loadAs<T>(base->addr(c)) >> bit) & 1; }
};

// A standard function's input named twice (`LIMIT(MN := F(), MN := 2, ...)`,
// decision 0426): the replaced argument is still evaluated, for its calls'
// effects, before the function, whose value this is.
struct ThenValue final : Expr {
    enum class Kind : uint8_t { Int, Real, Addr };
    Expr* first;
    Kind firstKind;
    Expr* value;
    ThenValue(Expr* f, Kind k, Expr* v) : first(f), firstKind(k), value(v) {}
    void discardFirst(Ctx& c) {
        if (firstKind == Kind::Int) first->i(c);
        else if (firstKind == Kind::Real) first->f(c);
        else first->addr(c);
    }
    int64_t i(Ctx& c) override { discardFirst(c); return value->i(c); }
    double f(Ctx& c) override { discardFirst(c); return value->f(c); }
    uint8_t* addr(Ctx& c) override { discardFirst(c); return value->addr(c); }
};

}  // namespace strun::exec
