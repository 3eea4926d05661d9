// REF_TO ARRAY[*] OF T, as SIMATIC AX's json library keeps its buffer
// (`buffer : REF_TO ARRAY[*] OF CHAR; buffer := REF(arr); buffer^[i]`;
// decision 0402). The variable holds the descriptor of an ARRAY[*]
// parameter, { address, lo0, hi0, ... }: assigning it stores an array's
// address and bounds, ref^ is an ARRAY[*] whose descriptor is the variable.
#include <fmt/format.h>

#include "interpreter/exec/flex_ref_nodes.h"
#include "interpreter/sema/checker.h"

namespace strun::sema {

Checked Checker::derefFlexibleRef(const Checked& ref, const ast::Loc& loc) {
    const Type* arr = ref.type->target;
    if (!ref.isPlace) {
        error(diag::E0201, loc, fmt::format("'^' on a {} needs a variable, not a computed value", typeName(ref.type)));
        return bad(loc);
    }
    Checked c;
    c.ok = true;
    c.loc = loc;
    c.type = arr;
    c.isPlace = true;
    c.hasCall = ref.hasCall;
    c.flexDesc = pool().make<exec::FlexRefDesc>(ref.node, site(loc), arr->dims.size());
    // The array itself (never read whole: ARRAY[*] has no size); its NULL test.
    c.node = pool().make<exec::RefSlotPlace>(ref.node, site(loc), 1u);
    c.node->type = arr;
    return c;
}

exec::Stmt* Checker::assignFlexibleRef(const Checked& target, const Checked& value, const ast::Loc& loc) {
    const Type* want = target.type->target;
    auto* bind = pool().make<exec::BindArrayDesc>();
    bind->slot = target.node;
    bind->sourceDesc = nullptr;
    const Type* v = value.type;
    if (value.isConst && value.constInt == 0 && (value.untypedInt || isInteger(v->kind))) {
        // NULL: address 0, bounds 0.
        bind->place = pool().make<exec::AddressValuePlace>(pool().make<exec::ConstInt>(0));
        bind->bounds.assign(2 * want->dims.size(), 0);
        return bind;
    }
    const Type* arr = v->kind == TK::Pointer ? v->target : nullptr;
    if (!arr || arr->kind != TK::Array || arr->dims.size() != want->dims.size() || !sameType(arr->elem, want->elem)) {
        error(diag::E0201, value.loc,
              fmt::format("cannot assign {} to {}: it takes REF() of an array of {} with {} dimension(s), another such reference, or NULL",
                          typeName(v), typeName(target.type), typeName(want->elem), want->dims.size()));
        return nullptr;
    }
    if (arr->flexible) {
        // Another REF_TO ARRAY[*]: its whole descriptor.
        if (value.flexDesc) {
            // REF(arr) of an ARRAY[*] parameter (or of ref^): that descriptor.
            bind->place = nullptr;
            bind->sourceDesc = value.flexDesc;
            bind->bounds.assign(2 * want->dims.size(), 0);
            return bind;
        }
        if (!value.isPlace) {
            error(diag::E0201, value.loc, fmt::format("a {} can be assigned from a variable of its type, not a computed value", typeName(target.type)));
            return nullptr;
        }
        bind->place = nullptr;
        bind->sourceDesc = value.node;
        bind->bounds.assign(2 * want->dims.size(), 0);
        return bind;
    }
    // REF(a) (or a REF_TO a fixed array): its address and the array's bounds.
    bind->place = pool().make<exec::AddressValuePlace>(value.node);
    for (const auto& d : arr->dims) {
        bind->bounds.push_back(d.lo);
        bind->bounds.push_back(d.hi);
    }
    return bind;
}

}  // namespace strun::sema
