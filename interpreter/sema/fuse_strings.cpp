// Recognises `s := CONCAT(s, piece, ...)` for the in-place append of
// interpreter/exec/string_append_nodes.h (decision 0155).
#include "interpreter/sema/fuse.h"

#include <algorithm>

#include "interpreter/exec/string_append_nodes.h"

namespace strun::sema {

namespace {

// Where a string variable node keeps its text; Kind::None for any other node.
struct StringVar {
    enum class Kind : uint8_t { None, Self, Frame, Abs } kind = Kind::None;
    uint32_t off = 0;
    uint8_t* abs = nullptr;
    bool sameStorage(const StringVar& o) const { return kind == o.kind && off == o.off && abs == o.abs; }
};

StringVar stringVarOf(exec::Expr* e) {
    using exec::BaseKind;
    if (auto* v = exec::nodeCast<exec::VarNode<void, BaseKind::Self>>(e)) return {StringVar::Kind::Self, v->off, nullptr};
    if (auto* v = exec::nodeCast<exec::VarNode<void, BaseKind::Frame>>(e)) return {StringVar::Kind::Frame, v->off, nullptr};
    if (auto* v = exec::nodeCast<exec::VarNode<void, BaseKind::Abs>>(e)) return {StringVar::Kind::Abs, v->off, v->abs};
    return {};
}

template <class Ch, exec::BaseKind B>
exec::Stmt* make(exec::NodePool& pool, const StringVar& target, uint32_t limit, const std::vector<exec::Expr*>& pieces) {
    auto* n = pool.make<exec::AppendInPlace<Ch, B>>();
    n->off = target.off;
    n->abs = target.abs;
    n->limit = limit;
    n->pieces = pieces;
    return n;
}

template <class Ch>
exec::Stmt* fuseTyped(exec::NodePool& pool, exec::Expr* place, uint32_t placeMaxLen, exec::Expr* value) {
    auto* concat = exec::nodeCast<exec::ConcatNode<Ch>>(value);
    if (!concat || concat->parts.size() < 2) return nullptr;
    StringVar target = stringVarOf(place);
    if (target.kind == StringVar::Kind::None || !target.sameStorage(stringVarOf(concat->parts[0]))) return nullptr;
    // The pieces are read after s has been extended: only constants and other
    // variables, which neither change s nor share its storage.
    std::vector<exec::Expr*> pieces(concat->parts.begin() + 1, concat->parts.end());
    for (exec::Expr* p : pieces) {
        if (exec::nodeCast<exec::ConstBytes>(p)) continue;
        StringVar v = stringVarOf(p);
        if (v.kind == StringVar::Kind::None || v.sameStorage(target)) return nullptr;
        if (v.kind == StringVar::Kind::Abs && target.kind == StringVar::Kind::Abs) {
            // Two fixed addresses: disjoint unless one variable lies inside the other (AT overlays).
            const uint8_t* a = target.abs + target.off;
            const uint8_t* b = v.abs + v.off;
            const size_t bytes = (placeMaxLen + 1) * sizeof(Ch);
            if (b < a + bytes && a < b + bytes) return nullptr;
        }
    }
    const uint32_t limit = std::min(placeMaxLen, concat->maxLen);
    switch (target.kind) {
        case StringVar::Kind::Self: return make<Ch, exec::BaseKind::Self>(pool, target, limit, pieces);
        case StringVar::Kind::Frame: return make<Ch, exec::BaseKind::Frame>(pool, target, limit, pieces);
        default: return make<Ch, exec::BaseKind::Abs>(pool, target, limit, pieces);
    }
}

}  // namespace

exec::Stmt* fuseAppendInPlace(exec::NodePool& pool, bool wide, exec::Expr* place, uint32_t placeMaxLen, exec::Expr* value) {
    return wide ? fuseTyped<char16_t>(pool, place, placeMaxLen, value) : fuseTyped<char>(pool, place, placeMaxLen, value);
}

}  // namespace strun::sema
