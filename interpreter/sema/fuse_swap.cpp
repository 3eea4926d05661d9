// Recognises t := a[i + k1]; a[i + k1] := a[i + k2]; a[i + k2] := t in a
// statement list (decision 0379). Only the nodes the checker already built
// are inspected: each of the three must be the fused form of its statement
// (decision 0154), with the element operands of decision 0262.
#include "interpreter/sema/fuse_swap.h"

#include "interpreter/exec/swap_nodes.h"
#include "interpreter/sema/fuse_leaf.h"

namespace strun::sema {

namespace {

using exec::BaseKind;
using exec::IndexFrom;

// The element operand that the place of a[j] := ... (AssignIndex1) stores to.
template <class T, BaseKind B, IndexFrom IX>
bool storeAs(exec::Stmt* s, exec::OpElem<T>& place, exec::Expr*& value) {
    auto* n = exec::nodeCast<exec::AssignIndex1<T, B, IX>>(s);
    if (!n) return false;
    place.base = exec::ctxBase<B>();
    place.off = n->off;
    place.indexBase = IX == IndexFrom::Self32 ? &exec::Ctx::self : &exec::Ctx::frame;
    place.indexOff = n->indexOff;
    place.indexAdd = n->indexAdd;
    place.lo = n->lo;
    place.count = n->count;
    place.stride = n->stride;
    place.site = &n->site;
    value = n->value;
    return true;
}
template <class T>
bool elementStore(exec::Stmt* s, exec::OpElem<T>& place, exec::Expr*& value) {
    return storeAs<T, BaseKind::Self, IndexFrom::Self32>(s, place, value) || storeAs<T, BaseKind::Self, IndexFrom::Frame32>(s, place, value) ||
           storeAs<T, BaseKind::Frame, IndexFrom::Self32>(s, place, value) || storeAs<T, BaseKind::Frame, IndexFrom::Frame32>(s, place, value);
}

template <class T>
bool sameElement(const exec::OpElem<T>& a, const exec::OpElem<T>& b) {
    return a.base == b.base && a.off == b.off && a.indexBase == b.indexBase && a.indexOff == b.indexOff && a.indexAdd == b.indexAdd &&
           a.lo == b.lo && a.count == b.count && a.stride == b.stride;
}

// Storage [off, off + size) of base `b` and [off2, off2 + size2) of `b2` overlap.
bool overlaps(exec::CtxBase b, uint64_t off, uint64_t size, exec::CtxBase b2, uint64_t off2, uint64_t size2) {
    return b == b2 && off < off2 + size2 && off2 < off + size;
}

// t, the array and the subscript variable are three separate pieces of
// storage: no store of the swap changes the subscript or t.
template <class T>
bool separate(const exec::OpElem<T>& e, exec::CtxBase tmpBase, uint32_t tmpOff) {
    const uint64_t arraySize = static_cast<uint64_t>(e.count) * e.stride;
    return !overlaps(tmpBase, tmpOff, sizeof(T), e.indexBase, e.indexOff, sizeof(int32_t)) &&
           !overlaps(tmpBase, tmpOff, sizeof(T), e.base, e.off, arraySize) &&
           !overlaps(e.indexBase, e.indexOff, sizeof(int32_t), e.base, e.off, arraySize) && e.stride == sizeof(T);
}

template <class T>
exec::Stmt* swapOf(exec::NodePool& pool, exec::Stmt* s1, exec::Stmt* s2, exec::Stmt* s3) {
    // t := a[i + k1]
    exec::CtxBase tmpBase;
    uint32_t tmpOff;
    exec::Expr* v1;
    if (auto* n = exec::nodeCast<exec::AssignLocal<T, false>>(s1)) tmpBase = &exec::Ctx::self, tmpOff = n->off, v1 = n->value;
    else if (auto* n = exec::nodeCast<exec::AssignLocal<T, true>>(s1)) tmpBase = &exec::Ctx::frame, tmpOff = n->off, v1 = n->value;
    else return nullptr;
    exec::OpElem<T> x;
    if (!fusion::elemOf<T>(v1, x)) return nullptr;
    // a[i + k1] := a[i + k2]
    exec::OpElem<T> place2, y;
    exec::Expr* v2;
    if (!elementStore<T>(s2, place2, v2) || !sameElement(place2, x) || !fusion::elemOf<T>(v2, y)) return nullptr;
    // a[i + k2] := t
    exec::OpElem<T> place3;
    exec::Expr* v3;
    if (!elementStore<T>(s3, place3, v3) || !sameElement(place3, y)) return nullptr;
    fusion::Leaf<T> t = fusion::leafOf<T>(v3);
    if (!t.isVar() || t.off != tmpOff || (t.kind == fusion::LeafKind::Frame) != (tmpBase == &exec::Ctx::frame)) return nullptr;
    if (!separate(x, tmpBase, tmpOff) || !separate(y, tmpBase, tmpOff)) return nullptr;
    // The subscript of one element is not stored into by the other's array.
    const uint64_t ySize = static_cast<uint64_t>(y.count) * y.stride, xSize = static_cast<uint64_t>(x.count) * x.stride;
    if (overlaps(x.indexBase, x.indexOff, sizeof(int32_t), y.base, y.off, ySize) || overlaps(y.indexBase, y.indexOff, sizeof(int32_t), x.base, x.off, xSize))
        return nullptr;
    auto* n = pool.make<exec::SwapElems<T>>(x, y, tmpBase, tmpOff, s1, s2, s3);
    n->line = s1->line;
    n->file = s1->file;
    n->col = s1->col;
    return n;
}

exec::Stmt* swapAt(exec::NodePool& pool, exec::Stmt* s1, exec::Stmt* s2, exec::Stmt* s3) {
    if (exec::Stmt* n = swapOf<int32_t>(pool, s1, s2, s3)) return n;
    if (exec::Stmt* n = swapOf<int64_t>(pool, s1, s2, s3)) return n;
    if (exec::Stmt* n = swapOf<int16_t>(pool, s1, s2, s3)) return n;
    if (exec::Stmt* n = swapOf<double>(pool, s1, s2, s3)) return n;
    return swapOf<float>(pool, s1, s2, s3);
}

}  // namespace

void fuseSwaps(exec::NodePool& pool, exec::Block& block) {
    if (!block.labels.empty() || block.stmts.size() < 3) return;
    auto& s = block.stmts;
    for (size_t k = 0; k + 2 < s.size(); ++k) {
        if (exec::Stmt* n = swapAt(pool, s[k], s[k + 1], s[k + 2])) {
            s[k] = n;
            s.erase(s.begin() + static_cast<std::ptrdiff_t>(k) + 1, s.begin() + static_cast<std::ptrdiff_t>(k) + 3);
        }
    }
}

}  // namespace strun::sema
