// FusedBin nodes computing in DINT or LINT (see fuse_binary.h).
#include "interpreter/sema/fuse_binary.h"

namespace strun::sema::fusion {

exec::Expr* fuseBinaryInteger(exec::NodePool& pool, BinOp op, bool wide, exec::Expr* a, exec::Expr* b, int64_t kInt) {
    if (wide) return fuseOp<int64_t>(pool, op, a, b, kInt);
    return fuseOp<int32_t>(pool, op, a, b, static_cast<int32_t>(kInt));
}

}  // namespace strun::sema::fusion
