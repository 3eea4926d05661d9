// FusedBin nodes computing in REAL or LREAL (see fuse_binary.h).
#include "interpreter/sema/fuse_binary.h"

namespace strun::sema::fusion {

exec::Expr* fuseBinaryReal(exec::NodePool& pool, BinOp op, bool wide, exec::Expr* a, exec::Expr* b, double kReal) {
    if (wide) return fuseOp<double>(pool, op, a, b, kReal);
    return fuseOp<float>(pool, op, a, b, static_cast<float>(kReal));
}

}  // namespace strun::sema::fusion
