// FusedBin nodes computing in REAL (see fuse_binary.h).
#include "interpreter/sema/fuse_binary.h"

namespace strun::sema::fusion {

exec::Expr* fuseBinaryReal(exec::NodePool& pool, BinOp op, exec::Expr* a, exec::Expr* b, double k) {
    return fuseOp<float>(pool, op, a, b, static_cast<float>(k));
}

}  // namespace strun::sema::fusion
