// Tc2_System / CODESYS memory functions: MEMCPY, MEMMOVE, MEMSET (return the
// number of bytes handled, 0 for a null address or n = 0) and MEMCMP (-1, 0,
// 1; 16#FF for a null address or n = 0), as Beckhoff documents them.
// Unlike on a PLC, a range that does not lie inside the project's memory
// (runtime/memory_map.h, the check pointer dereferences use) is never
// touched: the call raises NULL_POINTER (docs/diagnostics.md) and returns 0.
#include <cstring>

#include <fmt/format.h>

#include "interpreter/builtins/bind_support.h"
#include "interpreter/builtins/register_groups.h"
#include "interpreter/exec/value_nodes.h"

namespace strun::stdlib::bind {

namespace {

using exec::Ctx;

enum class MemOp : uint8_t { Copy, Move, Set, Compare };

const char* opName(MemOp op) {
    switch (op) {
        case MemOp::Copy: return "MEMCPY";
        case MemOp::Move: return "MEMMOVE";
        case MemOp::Set: return "MEMSET";
        case MemOp::Compare: return "MEMCMP";
    }
    return "";
}

struct MemNode final : exec::Expr {
    Expr* first;   // destination (pBuf1 for MEMCMP)
    Expr* second;  // source (pBuf2), or the fill byte of MEMSET
    Expr* count;
    MemOp op;
    exec::Site site;
    MemNode(Expr* a, Expr* b, Expr* n, MemOp o, exec::Site s) : first(a), second(b), count(n), op(o), site(s) {}

    static uint8_t* address(int64_t v) { return reinterpret_cast<uint8_t*>(static_cast<intptr_t>(v)); }

    bool inside(Ctx& c, const uint8_t* p, uint64_t n, const char* role) {
        if (c.m->memory.contains(p, n)) return true;
        exec::reportMemoryFault(c, site, fmt::format("{}: the {} range of {} bytes lies outside the project's memory", opName(op), role, n));
        return false;
    }

    int64_t i(Ctx& c) override {
        uint8_t* a = address(first->i(c));
        int64_t b = second->i(c);
        auto n = static_cast<uint64_t>(count->i(c));
        const int64_t invalid = op == MemOp::Compare ? 0xFF : 0;
        if (a == nullptr || n == 0 || (op != MemOp::Set && b == 0)) return invalid;
        if (!inside(c, a, n, op == MemOp::Compare ? "first" : "destination")) return 0;
        if (op != MemOp::Set && !inside(c, address(b), n, op == MemOp::Compare ? "second" : "source")) return 0;
        switch (op) {
            case MemOp::Copy:
            case MemOp::Move: std::memmove(a, address(b), n); break;  // MEMCPY of overlapping ranges is undefined on the PLC; here it is MEMMOVE
            case MemOp::Set: std::memset(a, static_cast<int>(b & 0xFF), n); break;
            case MemOp::Compare: {
                int r = std::memcmp(a, address(b), n);
                return r < 0 ? -1 : r > 0 ? 1 : 0;
            }
        }
        return static_cast<int64_t>(n);
    }
};

// An address argument (PVOID): any POINTER or REFERENCE value as it is, or an
// unsigned integer of the pointer's width (ULINT, LWORD; the literal 0).
Checked addressArg(Checker& ck, const Checked& a, const std::string& fn, const char* what) {
    if (!a.ok) return a;
    if (a.type && a.type->kind == TK::Pointer) return a;
    if (isIntegerArg(a) || isBitArg(a)) return ck.coerce(a, ck.types().elementary(TK::ULInt), a.loc, fn.c_str());
    return argError(ck, a, fn, fmt::format("{} must be an address (ADR(...), a POINTER, or an LWORD/ULINT)", what));
}

void addMem(Checker& ck, MemOp op) {
    const bool set = op == MemOp::Set, cmp = op == MemOp::Compare;
    struct MemData { MemOp op; bool set; bool cmp; };
    ck.addBuiltin(opName(op), BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [op, set, cmp] = self.data<MemData>();
        std::vector<Checked> a;
        bool bound = cmp ? bindFixed(ck, call, {{"PBUF1"}, {"PBUF2"}, {"N"}}, a)
                   : set ? bindFixed(ck, call, {{"DESTADDR"}, {"FILLBYTE"}, {"N"}}, a)
                         : bindFixed(ck, call, {{"DESTADDR"}, {"SRCADDR"}, {"N"}}, a);
        if (!bound) return ck.bad(call.loc);
        Checked first = addressArg(ck, a[0], call.name, cmp ? "pBuf1" : "destAddr");
        if (!first.ok) return first;
        Checked second;
        if (set) {
            if (!isIntegerArg(a[1]) && !isBitArg(a[1])) return argError(ck, a[1], call.name, "fillByte must be a byte value");
            const Type* bt = a[1].type && a[1].type->kind == TK::Byte ? a[1].type : ck.types().elementary(TK::USInt);
            second = ck.coerce(a[1], bt, a[1].loc, call.name.c_str());
        } else {
            second = addressArg(ck, a[1], call.name, cmp ? "pBuf2" : "srcAddr");
        }
        if (!second.ok) return second;
        Checked n = ck.coerce(a[2], ck.types().elementary(TK::UDInt), a[2].loc, call.name.c_str());
        if (!n.ok) return n;
        auto* node = ck.pool().make<MemNode>(first.node, second.node, n.node, op, ck.site(call.loc));
        return makeResult(ck, node, ck.types().elementary(cmp ? TK::DInt : TK::UDInt), call, a, false);
    }, MemData{op, set, cmp}));
}

}  // namespace

void registerMemory(Checker& ck) {
    for (MemOp op : {MemOp::Copy, MemOp::Move, MemOp::Set, MemOp::Compare}) addMem(ck, op);
}

}  // namespace strun::stdlib::bind
