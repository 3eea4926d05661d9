// Builds the fused statements and operands of fuse.h (decisions 0151, 0154);
// the fused binary operators are in fuse_binary_*.cpp.
#include "interpreter/sema/fuse.h"

#include <bit>
#include <optional>
#include <type_traits>

#include "interpreter/sema/fuse_binary.h"
#include "interpreter/sema/fuse_leaf.h"

namespace strun::sema {

using exec::BaseKind;
using exec::BinOp;
using fusion::Leaf;
using fusion::LeafKind;
using fusion::leafOf;

namespace {

template <class T, BaseKind B>
exec::Stmt* addConst(exec::NodePool& pool, uint32_t off, exec::Expr* value) {
    // The value as the checker builds it: x + k (AddIK / SubIK over the
    // variable node, in the computation type of T) or, for DINT/LINT
    // variables, the fused form of the same.
    using C = std::conditional_t<(sizeof(T) < 4), int32_t, T>;  // arithmeticRep
    using V = exec::VarNode<T, B>;
    auto same = [&](exec::Expr* e) {
        auto* v = exec::nodeCast<V>(e);
        return v && v->off == off;
    };
    if (auto* n = exec::nodeCast<exec::AddIK<C>>(value); n && same(n->l)) return pool.make<exec::AddConstLocal<T, B>>(off, static_cast<int64_t>(n->b));
    if (auto* n = exec::nodeCast<exec::SubIK<C>>(value); n && same(n->l))
        return pool.make<exec::AddConstLocal<T, B>>(off, static_cast<int64_t>(0 - static_cast<uint64_t>(static_cast<int64_t>(n->b))));
    if constexpr (std::is_same_v<C, T>) {
        using OV = exec::OpVar<T, B>;
        using K = exec::OpConst<T>;
        if (auto* n = exec::nodeCast<exec::FusedBin<T, BinOp::Add, OV, K>>(value); n && n->l.off == off)
            return pool.make<exec::AddConstLocal<T, B>>(off, static_cast<int64_t>(n->r.k));
        if (auto* n = exec::nodeCast<exec::FusedBin<T, BinOp::Sub, OV, K>>(value); n && n->l.off == off)
            return pool.make<exec::AddConstLocal<T, B>>(off, static_cast<int64_t>(0 - static_cast<uint64_t>(static_cast<int64_t>(n->r.k))));
    }
    return nullptr;
}

template <BaseKind B>
exec::Stmt* addConstByRep(exec::NodePool& pool, Rep rep, uint32_t off, exec::Expr* value) {
    switch (rep) {
        case Rep::I8: return addConst<int8_t, B>(pool, off, value);
        case Rep::I16: return addConst<int16_t, B>(pool, off, value);
        case Rep::I32: return addConst<int32_t, B>(pool, off, value);
        case Rep::I64: return addConst<int64_t, B>(pool, off, value);
        default: return nullptr;  // unsigned: rare as counters, left to the general nodes
    }
}

template <class T>
exec::Expr* realToInt(exec::NodePool& pool, exec::Expr* value, int bits, bool isSigned, bool truncate) {
    if (truncate) return pool.make<exec::ConvRealIntT<T, true>>(value, bits, isSigned);
    return pool.make<exec::ConvRealIntT<T, false>>(value, bits, isSigned);
}

// The index variable (and added constant) of a subscript expression.
struct IndexLeaf {
    exec::IndexFrom from = exec::IndexFrom::Node;
    uint32_t off = 0;
    int32_t add = 0;
};

template <class S, exec::IndexFrom SELF, exec::IndexFrom FRAME>
bool indexVar(exec::Expr* e, IndexLeaf& out) {
    if (auto* v = exec::nodeCast<exec::VarNode<S, BaseKind::Self>>(e)) { out.from = SELF; out.off = v->off; return true; }
    if (auto* v = exec::nodeCast<exec::VarNode<S, BaseKind::Frame>>(e)) { out.from = FRAME; out.off = v->off; return true; }
    return false;
}

bool anyIndexVar(exec::Expr* e, IndexLeaf& out) {
    return indexVar<int32_t, exec::IndexFrom::Self32, exec::IndexFrom::Frame32>(e, out) ||
           indexVar<int16_t, exec::IndexFrom::Self16, exec::IndexFrom::Frame16>(e, out);
}

IndexLeaf indexLeafOf(exec::Expr* e) {
    IndexLeaf leaf;
    if (anyIndexVar(e, leaf)) return leaf;
    // v + k, v - k in DINT (INT variables are promoted to DINT).
    using VS = exec::OpVar<int32_t, BaseKind::Self>;
    using VF = exec::OpVar<int32_t, BaseKind::Frame>;
    using K = exec::OpConst<int32_t>;
    auto fusedAdd = [&](exec::IndexFrom from, uint32_t off, int32_t k, bool negate) {
        leaf.from = from;
        leaf.off = off;
        leaf.add = static_cast<int32_t>(negate ? 0u - static_cast<uint32_t>(k) : static_cast<uint32_t>(k));
    };
    if (auto* n = exec::nodeCast<exec::FusedBin<int32_t, BinOp::Add, VS, K>>(e)) { fusedAdd(exec::IndexFrom::Self32, n->l.off, n->r.k, false); return leaf; }
    if (auto* n = exec::nodeCast<exec::FusedBin<int32_t, BinOp::Sub, VS, K>>(e)) { fusedAdd(exec::IndexFrom::Self32, n->l.off, n->r.k, true); return leaf; }
    if (auto* n = exec::nodeCast<exec::FusedBin<int32_t, BinOp::Add, VF, K>>(e)) { fusedAdd(exec::IndexFrom::Frame32, n->l.off, n->r.k, false); return leaf; }
    if (auto* n = exec::nodeCast<exec::FusedBin<int32_t, BinOp::Sub, VF, K>>(e)) { fusedAdd(exec::IndexFrom::Frame32, n->l.off, n->r.k, true); return leaf; }
    IndexLeaf inner;
    if (auto* n = exec::nodeCast<exec::AddIK<int32_t>>(e); n && anyIndexVar(n->l, inner)) {
        inner.add = n->b;
        return inner;
    }
    if (auto* n = exec::nodeCast<exec::SubIK<int32_t>>(e); n && anyIndexVar(n->l, inner)) {
        inner.add = static_cast<int32_t>(0u - static_cast<uint32_t>(n->b));
        return inner;
    }
    return {};
}

template <BaseKind B, exec::IndexFrom IX>
struct IndexBind {
    template <class T>
    using N = exec::Index1Var<T, B, IX>;
};

template <BaseKind B>
exec::Expr* index1From(exec::NodePool& pool, Rep rep, exec::IndexFrom from) {
    switch (from) {
        case exec::IndexFrom::Self32: return makeByRep<IndexBind<B, exec::IndexFrom::Self32>::template N>(pool, rep);
        case exec::IndexFrom::Frame32: return makeByRep<IndexBind<B, exec::IndexFrom::Frame32>::template N>(pool, rep);
        case exec::IndexFrom::Self16: return makeByRep<IndexBind<B, exec::IndexFrom::Self16>::template N>(pool, rep);
        case exec::IndexFrom::Frame16: return makeByRep<IndexBind<B, exec::IndexFrom::Frame16>::template N>(pool, rep);
        default: return nullptr;
    }
}

template <class T>
exec::Stmt* assignConstTyped(exec::NodePool& pool, T k, exec::Expr* place, BaseKind base, uint32_t off) {
    if (place) return pool.make<exec::AssignConst<T>>(place, k);
    switch (base) {
        case BaseKind::Frame: return pool.make<exec::AssignConstLocal<T, BaseKind::Frame>>(off, k);
        case BaseKind::Pending: return pool.make<exec::AssignConstLocal<T, BaseKind::Pending>>(off, k);
        default: return pool.make<exec::AssignConstLocal<T, BaseKind::Self>>(off, k);
    }
}

}  // namespace

exec::Stmt* fuseAssignConst(exec::NodePool& pool, Rep rep, exec::Expr* value, exec::Expr* place, BaseKind base, uint32_t off) {
    if (!exec::nodeCast<exec::ConstInt>(value) && !exec::nodeCast<exec::ConstReal>(value)) return nullptr;
    exec::Ctx none;  // constants read nothing from the context
    switch (rep) {
        case Rep::I8: return assignConstTyped<int8_t>(pool, static_cast<int8_t>(value->i(none)), place, base, off);
        case Rep::I16: return assignConstTyped<int16_t>(pool, static_cast<int16_t>(value->i(none)), place, base, off);
        case Rep::I32: return assignConstTyped<int32_t>(pool, static_cast<int32_t>(value->i(none)), place, base, off);
        case Rep::I64: return assignConstTyped<int64_t>(pool, value->i(none), place, base, off);
        case Rep::U8: return assignConstTyped<uint8_t>(pool, static_cast<uint8_t>(value->i(none)), place, base, off);
        case Rep::Bool: return assignConstTyped<uint8_t>(pool, static_cast<uint8_t>(value->i(none) != 0), place, base, off);
        case Rep::U16: return assignConstTyped<uint16_t>(pool, static_cast<uint16_t>(value->i(none)), place, base, off);
        case Rep::U32: return assignConstTyped<uint32_t>(pool, static_cast<uint32_t>(value->i(none)), place, base, off);
        case Rep::U64: return assignConstTyped<uint64_t>(pool, static_cast<uint64_t>(value->i(none)), place, base, off);
        case Rep::F32: return assignConstTyped<float>(pool, static_cast<float>(value->f(none)), place, base, off);
        case Rep::F64: return assignConstTyped<double>(pool, value->f(none), place, base, off);
        default: return nullptr;
    }
}

namespace {
template <class T, class S = T>
exec::Stmt* storePending(exec::NodePool& pool, Rep rep, exec::Expr* place, exec::Expr* value) {
    BaseKind base;
    uint32_t off;
    if (auto* v = exec::nodeCast<exec::VarNode<S, BaseKind::Pending>>(place)) base = BaseKind::Pending, off = v->off;
    else if (auto* v = exec::nodeCast<exec::VarNode<S, BaseKind::Self>>(place)) base = BaseKind::Self, off = v->off;
    else if (auto* v = exec::nodeCast<exec::VarNode<S, BaseKind::Frame>>(place)) base = BaseKind::Frame, off = v->off;
    else return nullptr;
    if (exec::Stmt* k = fuseAssignConst(pool, rep, value, nullptr, base, off)) return k;
    switch (base) {
        case BaseKind::Pending: return pool.make<exec::AssignPending<T>>(off, value);
        case BaseKind::Frame: return pool.make<exec::AssignLocal<T, true>>(off, value);
        default: return pool.make<exec::AssignLocal<T, false>>(off, value);
    }
}
}  // namespace

namespace {
// T: the assignment's type; S: the storage type of its variables (a BOOL's byte).
template <class T, class S, bool DST_FRAME>
exec::Stmt* copyLocalAs(exec::NodePool& pool, exec::Stmt* assign) {
    auto* a = exec::nodeCast<exec::AssignLocal<T, DST_FRAME>>(assign);
    if (!a) return nullptr;
    const Leaf<S> from = leafOf<S>(a->value);
    if (from.kind == LeafKind::Self) return pool.make<exec::CopyLocal<T, DST_FRAME, false>>(a->off, from.off);
    if (from.kind == LeafKind::Frame) return pool.make<exec::CopyLocal<T, DST_FRAME, true>>(a->off, from.off);
    return nullptr;
}

template <class T, class S = T>
exec::Stmt* copyLocal(exec::NodePool& pool, exec::Stmt* assign) {
    if (exec::Stmt* k = copyLocalAs<T, S, false>(pool, assign)) return k;
    return copyLocalAs<T, S, true>(pool, assign);
}
}  // namespace

exec::Stmt* fuseCopyLocal(exec::NodePool& pool, exec::Stmt* assign) {
    exec::Stmt* k = nullptr;
    (k = copyLocal<int8_t>(pool, assign)) || (k = copyLocal<int16_t>(pool, assign)) || (k = copyLocal<int32_t>(pool, assign)) ||
        (k = copyLocal<int64_t>(pool, assign)) || (k = copyLocal<uint8_t>(pool, assign)) || (k = copyLocal<uint16_t>(pool, assign)) ||
        (k = copyLocal<uint32_t>(pool, assign)) || (k = copyLocal<uint64_t>(pool, assign)) || (k = copyLocal<float>(pool, assign)) ||
        (k = copyLocal<double>(pool, assign)) || (k = copyLocal<bool, uint8_t>(pool, assign));
    return k;
}

exec::Stmt* fuseStorePending(exec::NodePool& pool, Rep rep, exec::Expr* place, exec::Expr* value) {
    switch (rep) {
        case Rep::I8: return storePending<int8_t>(pool, rep, place, value);
        case Rep::I16: return storePending<int16_t>(pool, rep, place, value);
        case Rep::I32: return storePending<int32_t>(pool, rep, place, value);
        case Rep::I64: return storePending<int64_t>(pool, rep, place, value);
        case Rep::U8: return storePending<uint8_t>(pool, rep, place, value);
        case Rep::Bool: return storePending<bool, uint8_t>(pool, rep, place, value);
        case Rep::U16: return storePending<uint16_t>(pool, rep, place, value);
        case Rep::U32: return storePending<uint32_t>(pool, rep, place, value);
        case Rep::U64: return storePending<uint64_t>(pool, rep, place, value);
        case Rep::F32: return storePending<float>(pool, rep, place, value);
        case Rep::F64: return storePending<double>(pool, rep, place, value);
        default: return nullptr;
    }
}

exec::Expr* fuseIndex1(exec::NodePool& pool, Rep rep, BaseKind base, const exec::Index1Fields& fields) {
    IndexLeaf leaf = indexLeafOf(fields.index);
    if (leaf.from == exec::IndexFrom::Node) return nullptr;
    exec::Expr* n = nullptr;
    switch (base) {
        case BaseKind::Self: n = index1From<BaseKind::Self>(pool, rep, leaf.from); break;
        case BaseKind::Frame: n = index1From<BaseKind::Frame>(pool, rep, leaf.from); break;
        case BaseKind::Abs: n = index1From<BaseKind::Abs>(pool, rep, leaf.from); break;
        default: return nullptr;
    }
    auto* f = exec::nodeCast<exec::Index1Fields>(n);
    *f = fields;
    f->indexOff = leaf.off;
    f->indexAdd = leaf.add;
    return n;
}

exec::Expr* fuseBinary(exec::NodePool& pool, BinOp op, Rep rep, exec::Expr* a, exec::Expr* b, int64_t kInt, double kReal) {
    switch (rep) {
        case Rep::I32: return fusion::fuseBinaryDint(pool, op, a, b, kInt);
        case Rep::I64: return fusion::fuseBinaryLint(pool, op, a, b, kInt);
        case Rep::F32: return fusion::fuseBinaryReal(pool, op, a, b, kReal);
        case Rep::F64: return fusion::fuseBinaryLreal(pool, op, a, b, kReal);
        default: return nullptr;
    }
}

exec::Stmt* fuseAddConstLocal(exec::NodePool& pool, Rep rep, bool frame, uint32_t off, exec::Expr* value) {
    return frame ? addConstByRep<BaseKind::Frame>(pool, rep, off, value) : addConstByRep<BaseKind::Self>(pool, rep, off, value);
}

exec::Expr* fuseRealToInt(exec::NodePool& pool, exec::Expr* value, int bits, bool isSigned, bool truncate) {
    // REAL_TO_DINT(x * 10.0): the conversion computes the operator itself (decision 0262).
    if (auto* op = exec::nodeCast<exec::FusedArith>(value); op && (bits == 8 || bits == 16 || bits == 32 || bits == 64))
        if (exec::Expr* n = op->makeRealToInt(pool, exec::RealToIntForm{static_cast<uint8_t>(bits), isSigned, truncate})) return n;
    switch (bits) {
        case 8: return isSigned ? realToInt<int8_t>(pool, value, bits, isSigned, truncate) : realToInt<uint8_t>(pool, value, bits, isSigned, truncate);
        case 16: return isSigned ? realToInt<int16_t>(pool, value, bits, isSigned, truncate) : realToInt<uint16_t>(pool, value, bits, isSigned, truncate);
        case 32: return isSigned ? realToInt<int32_t>(pool, value, bits, isSigned, truncate) : realToInt<uint32_t>(pool, value, bits, isSigned, truncate);
        case 64: return isSigned ? realToInt<int64_t>(pool, value, bits, isSigned, truncate) : realToInt<uint64_t>(pool, value, bits, isSigned, truncate);
        default: return nullptr;
    }
}

exec::Stmt* fuseIf(exec::NodePool& pool, exec::Expr* cond, exec::Block* then, exec::Stmt* otherwise) {
    if (auto* cmp = exec::nodeCast<exec::FusedCompare>(cond)) return cmp->makeIf(pool, then, otherwise);
    // IF flag / IF flags[i] on a BOOL (stored as a byte; a condition is
    // always BOOL) read inline.
    if (Leaf<uint8_t> v = leafOf<uint8_t>(cond); v.isVar())
        return fusion::withVar(v, [&](auto var) -> exec::Stmt* { return pool.make<exec::IfBool<decltype(var)>>(var, then, otherwise); });
    if (exec::OpElem<uint8_t> e; fusion::elemOf<uint8_t>(cond, e))
        return pool.make<exec::IfBool<exec::OpElem<uint8_t>>>(e, then, otherwise);
    // IF a OR b (a AND b, a XOR b): the IF evaluates both operands itself.
    if (auto* n = exec::nodeCast<exec::OrI<uint8_t>>(cond)) return pool.make<exec::IfLogic<BinOp::Or>>(n->l, n->r, then, otherwise);
    if (auto* n = exec::nodeCast<exec::AndI<uint8_t>>(cond)) return pool.make<exec::IfLogic<BinOp::And>>(n->l, n->r, then, otherwise);
    if (auto* n = exec::nodeCast<exec::XorI<uint8_t>>(cond)) return pool.make<exec::IfLogic<BinOp::Xor>>(n->l, n->r, then, otherwise);
    return nullptr;
}

exec::Stmt* fuseWhile(exec::NodePool& pool, exec::Expr* cond, exec::Block* body) {
    if (auto* cmp = exec::nodeCast<exec::FusedCompare>(cond)) return cmp->makeWhile(pool, body);
    return nullptr;
}

}  // namespace strun::sema

namespace strun::sema {

namespace {

using How = exec::ArgBind::How;

// The form of `how` for a stored width of `bytes` (1, 2, 4, 8): the four
// forms of each kind are consecutive.
How withWidth(How first, size_t bytes) {
    const int step = bytes == 1 ? 0 : bytes == 2 ? 1 : bytes == 4 ? 2 : 3;
    return static_cast<How>(static_cast<int>(first) + step);
}

// A bitwise copy from a variable of the instance or frame stored exactly as
// the parameter is (same representation T).
template <class T>
bool copySource(exec::Expr* value, exec::ArgBind& out) {
    Leaf<T> leaf = leafOf<T>(value);
    if (leaf.kind == LeafKind::Self) out.how = withWidth(How::CopySelf1, sizeof(T));
    else if (leaf.kind == LeafKind::Frame) out.how = withWidth(How::CopyFrame1, sizeof(T));
    else return false;
    out.src = leaf.off;
    return true;
}

template <class T>
bool integerArg(exec::Expr* value, exec::ArgBind& out) {
    if (exec::nodeCast<exec::ConstInt>(value)) {
        exec::Ctx none;  // constants read nothing from the context
        out.how = withWidth(How::Const1, sizeof(T));
        out.bits = static_cast<uint64_t>(static_cast<std::make_unsigned_t<T>>(static_cast<T>(value->i(none))));
        return true;
    }
    if (copySource<T>(value, out)) return true;
    out.how = withWidth(How::Int1, sizeof(T));
    out.value = value;
    return true;
}

template <class T>
bool realArg(exec::Expr* value, exec::ArgBind& out) {
    if (exec::nodeCast<exec::ConstInt>(value) || exec::nodeCast<exec::ConstReal>(value)) {
        exec::Ctx none;
        T k = static_cast<T>(value->f(none));
        out.how = withWidth(How::Const1, sizeof(T));
        if constexpr (sizeof(T) == 4) out.bits = std::bit_cast<uint32_t>(k);
        else out.bits = std::bit_cast<uint64_t>(k);
        return true;
    }
    if (copySource<T>(value, out)) return true;
    out.how = sizeof(T) == 4 ? How::F32 : How::F64;
    out.value = value;
    return true;
}

}  // namespace

bool fuseArgBind(Rep rep, uint32_t dst, exec::Expr* value, exec::ArgBind& out) {
    out = exec::ArgBind{};
    out.dst = dst;
    switch (rep) {
        case Rep::I8: return integerArg<int8_t>(value, out);
        case Rep::I16: return integerArg<int16_t>(value, out);
        case Rep::I32: return integerArg<int32_t>(value, out);
        case Rep::I64: return integerArg<int64_t>(value, out);
        case Rep::U8: return integerArg<uint8_t>(value, out);
        case Rep::U16: return integerArg<uint16_t>(value, out);
        case Rep::U32: return integerArg<uint32_t>(value, out);
        case Rep::U64: return integerArg<uint64_t>(value, out);
        case Rep::Bool:
            // A constant, or else through the value: a BOOL is stored as 0/1 whatever its source holds.
            if (exec::nodeCast<exec::ConstInt>(value)) {
                exec::Ctx none;
                out.how = How::Const1;
                out.bits = value->i(none) != 0;
                return true;
            }
            out.how = How::Bool;
            out.value = value;
            return true;
        case Rep::F32: return realArg<float>(value, out);
        case Rep::F64: return realArg<double>(value, out);
        default: return false;
    }
}

}  // namespace strun::sema
