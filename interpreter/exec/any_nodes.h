// An input declared ANY / ANY_NUM / ... (decision 0302): the callee receives
// a __SYSTEM.AnyType {TypeClass, pValue, diSize} describing the argument.
#pragma once

#include "interpreter/exec/value_nodes.h"

namespace strun::exec {

// Fills the AnyType at `slot` (the parameter in the pending frame) with the
// argument's type class, address and size.
struct BindAnyArgument final : Stmt {
    Expr* slot;
    Expr* value;  // place of the argument (or of the temporary holding it)
    int32_t typeClass;  // a UDINT (__SYSTEM.TYPE_CLASS)
    int32_t size;
    uint32_t classOffset, pointerOffset, sizeOffset;
    BindAnyArgument(Expr* s, Expr* v, int32_t tc, int32_t n, uint32_t co, uint32_t po, uint32_t so)
        : slot(s), value(v), typeClass(tc), size(n), classOffset(co), pointerOffset(po), sizeOffset(so) {}
    Flow exec(Ctx& c) override {
        uint8_t* p = value->addr(c);
        uint8_t* s = slot->addr(c);
        storeAs<int32_t>(s + classOffset, typeClass);
        storeAs<int64_t>(s + pointerOffset, static_cast<int64_t>(reinterpret_cast<intptr_t>(p)));
        storeAs<int32_t>(s + sizeOffset, size);
        return Flow::Next;
    }
};

}  // namespace strun::exec
