// FusedBin nodes computing in LREAL (see fuse_binary.h).
#include "interpreter/sema/fuse_binary.h"

namespace strun::sema::fusion {

exec::Expr* fuseBinaryLreal(exec::NodePool& pool, BinOp op, exec::Expr* a, exec::Expr* b, double k) {
    return fuseOp<double>(pool, op, a, b, static_cast<double>(k));
}

}  // namespace strun::sema::fusion
