// FusedBin nodes computing in DINT (see fuse_binary.h).
#include "interpreter/sema/fuse_binary.h"

namespace strun::sema::fusion {

exec::Expr* fuseBinaryDint(exec::NodePool& pool, BinOp op, exec::Expr* a, exec::Expr* b, int64_t k) {
    return fuseOp<int32_t>(pool, op, a, b, static_cast<int32_t>(k));
}

}  // namespace strun::sema::fusion
