// FusedBin nodes computing in LINT (see fuse_binary.h).
#include "interpreter/sema/fuse_binary.h"

namespace strun::sema::fusion {

exec::Expr* fuseBinaryLint(exec::NodePool& pool, BinOp op, exec::Expr* a, exec::Expr* b, int64_t k) {
    return fuseOp<int64_t>(pool, op, a, b, static_cast<int64_t>(k));
}

}  // namespace strun::sema::fusion
