// Selection (SEL MAX MIN LIMIT MUX) and comparison functions (GT GE EQ LE LT NE).
#include <fmt/format.h>

#include "interpreter/builtins/bind_support.h"
#include "interpreter/builtins/register_groups.h"
#include "interpreter/builtins/select_nodes.h"

namespace strun::stdlib::bind {

namespace {

bool comparable(const Type* t) {
    return sema::isElementary(t->kind) || t->kind == TK::Enum;
}

// Brings the inputs to one type; the same rules as the operators.
// `selectorVaries`: a SEL/MUX whose selector is not constant gives a
// non-constant result even from literal inputs (see literalType).
const Type* unify(Checker& ck, CallArgs& call, std::vector<Checked>& ins, bool needComparable, bool selectorVaries = false) {
    const Type* t = selectorVaries && allUntyped(ins) ? literalType(ck, ins) : commonTypeOf(ck, ins, call.loc, call.name);
    if (!t) return nullptr;
    if (needComparable && !comparable(t)) {
        ck.error(diag::E0202, call.loc, fmt::format("{}: {} values cannot be compared", call.name, sema::typeName(t)));
        return nullptr;
    }
    if (!coerceAll(ck, ins, t, call.name)) return nullptr;
    return t;
}

std::vector<exec::Expr*> nodesOf(const std::vector<Checked>& v, size_t from = 0) {
    std::vector<exec::Expr*> out;
    for (size_t k = from; k < v.size(); ++k) out.push_back(v[k].node);
    return out;
}

Checked checkSel(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"G"}, {"IN0"}, {"IN1"}}, a)) return ck.bad(call.loc);
    // SEL(1, a, b): the literal 0 or 1 is a BOOL, as in `b : BOOL := 1`.
    if (a[0].untypedInt) a[0] = ck.coerce(a[0], ck.types().elementary(TK::Bool), a[0].loc, "G");
    if (!a[0].ok) return ck.bad(call.loc);
    if (a[0].type->kind != TK::Bool) return argError(ck, a[0], call.name, "G must be BOOL");
    std::vector<Checked> ins = {a[1], a[2]};
    const Type* t = unify(ck, call, ins, false, !a[0].isConst);
    if (!t) return ck.bad(call.loc);
    auto* n = ck.pool().make<SelNode>(a[0].node, ins[0].node, ins[1].node);
    std::vector<Checked> all = {a[0], a[1], a[2]};
    std::vector<Checked> values = {a[1], a[2]};
    return makeResult(ck, n, t, call, all, true, &values);
}

template <class K>
using MuxOf = MuxNode<K>;

Checked checkMux(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindExtensible(ck, call, {{"K"}}, "IN", 0, 2, a)) return ck.bad(call.loc);
    if (!isIntegerArg(a[0]) && !isBitArg(a[0])) return argError(ck, a[0], call.name, "K must be an integer");
    Checked k = ck.settle(a[0]);
    std::vector<Checked> ins(a.begin() + 1, a.end());
    const Type* t = unify(ck, call, ins, false, !k.isConst);
    if (!t) return ck.bad(call.loc);
    exec::Expr* n = sema::makeIntByRep<MuxOf>(ck.pool(), sema::repOf(k.type), k.node);
    // makeIntByRep passes the selector only; the inputs are filled in afterwards.
    std::vector<exec::Expr*> nodes = nodesOf(ins);
    switch (sema::repOf(k.type)) {
        case Rep::I8: static_cast<MuxNode<int8_t>*>(n)->ins = nodes; break;
        case Rep::I16: static_cast<MuxNode<int16_t>*>(n)->ins = nodes; break;
        case Rep::I32: static_cast<MuxNode<int32_t>*>(n)->ins = nodes; break;
        case Rep::I64: static_cast<MuxNode<int64_t>*>(n)->ins = nodes; break;
        case Rep::U8: case Rep::Bool: static_cast<MuxNode<uint8_t>*>(n)->ins = nodes; break;
        case Rep::U16: static_cast<MuxNode<uint16_t>*>(n)->ins = nodes; break;
        case Rep::U32: static_cast<MuxNode<uint32_t>*>(n)->ins = nodes; break;
        default: static_cast<MuxNode<uint64_t>*>(n)->ins = nodes; break;
    }
    std::vector<Checked> values(a.begin() + 1, a.end());
    return makeResult(ck, n, t, call, a, true, &values);
}

template <class N>
exec::Expr* withInputs(exec::NodePool& pool, std::vector<exec::Expr*> ins) {
    N* n = pool.make<N>();
    n->ins = std::move(ins);
    return n;
}

template <bool MAX>
exec::Expr* extremeNode(exec::NodePool& pool, const Type* t, std::vector<exec::Expr*> ins) {
    switch (t->kind) {
        case TK::String: return withInputs<ExtremeStr<char, MAX>>(pool, std::move(ins));
        case TK::WString: return withInputs<ExtremeStr<char16_t, MAX>>(pool, std::move(ins));
        default: break;
    }
    switch (sema::repOf(t)) {
        case Rep::F32: return withInputs<ExtremeF<float, MAX>>(pool, std::move(ins));
        case Rep::F64: return withInputs<ExtremeF<double, MAX>>(pool, std::move(ins));
        case Rep::I8: return withInputs<ExtremeI<int8_t, MAX>>(pool, std::move(ins));
        case Rep::I16: return withInputs<ExtremeI<int16_t, MAX>>(pool, std::move(ins));
        case Rep::I32: return withInputs<ExtremeI<int32_t, MAX>>(pool, std::move(ins));
        case Rep::I64: return withInputs<ExtremeI<int64_t, MAX>>(pool, std::move(ins));
        case Rep::U8: case Rep::Bool: return withInputs<ExtremeI<uint8_t, MAX>>(pool, std::move(ins));
        case Rep::U16: return withInputs<ExtremeI<uint16_t, MAX>>(pool, std::move(ins));
        case Rep::U32: return withInputs<ExtremeI<uint32_t, MAX>>(pool, std::move(ins));
        default: return withInputs<ExtremeI<uint64_t, MAX>>(pool, std::move(ins));
    }
}

template <bool MAX>
Checked checkExtreme(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindExtensible(ck, call, {}, "IN", 1, 2, a)) return ck.bad(call.loc);
    std::vector<Checked> ins = a;
    const Type* t = unify(ck, call, ins, true);
    if (!t) return ck.bad(call.loc);
    return makeResult(ck, extremeNode<MAX>(ck.pool(), t, nodesOf(ins)), t, call, a);
}

Checked checkLimit(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"MN"}, {"IN"}, {"MX"}}, a)) return ck.bad(call.loc);
    std::vector<Checked> ins = a;
    const Type* t = unify(ck, call, ins, true);
    if (!t) return ck.bad(call.loc);
    auto& pool = ck.pool();
    exec::Expr *mn = ins[0].node, *in = ins[1].node, *mx = ins[2].node;
    exec::Expr* n = nullptr;
    if (t->kind == TK::String) n = pool.make<LimitStr<char>>(mn, in, mx);
    else if (t->kind == TK::WString) n = pool.make<LimitStr<char16_t>>(mn, in, mx);
    else if (sema::isReal(t->kind)) n = sema::makeRealByRep<LimitF>(pool, sema::repOf(t), mn, in, mx);
    else n = sema::makeIntByRep<LimitI>(pool, sema::repOf(t), mn, in, mx);
    return makeResult(ck, n, t, call, a);
}

template <CmpOp OP>
struct ChainBind {
    template <class T>
    using I = CmpChainI<T, OP>;
};

template <CmpOp OP>
exec::Expr* chainNode(exec::NodePool& pool, const Type* t, std::vector<exec::Expr*> ins) {
    switch (t->kind) {
        case TK::String: return withInputs<CmpChainStr<char, OP>>(pool, std::move(ins));
        case TK::WString: return withInputs<CmpChainStr<char16_t, OP>>(pool, std::move(ins));
        default: break;
    }
    switch (sema::repOf(t)) {
        case Rep::F32: return withInputs<CmpChainF<float, OP>>(pool, std::move(ins));
        case Rep::F64: return withInputs<CmpChainF<double, OP>>(pool, std::move(ins));
        case Rep::I8: return withInputs<CmpChainI<int8_t, OP>>(pool, std::move(ins));
        case Rep::I16: return withInputs<CmpChainI<int16_t, OP>>(pool, std::move(ins));
        case Rep::I32: return withInputs<CmpChainI<int32_t, OP>>(pool, std::move(ins));
        case Rep::I64: return withInputs<CmpChainI<int64_t, OP>>(pool, std::move(ins));
        case Rep::U8: case Rep::Bool: return withInputs<CmpChainI<uint8_t, OP>>(pool, std::move(ins));
        case Rep::U16: return withInputs<CmpChainI<uint16_t, OP>>(pool, std::move(ins));
        case Rep::U32: return withInputs<CmpChainI<uint32_t, OP>>(pool, std::move(ins));
        default: return withInputs<CmpChainI<uint64_t, OP>>(pool, std::move(ins));
    }
}

template <CmpOp OP>
Checked checkCompare(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    bool ok = OP == CmpOp::Ne ? bindFixed(ck, call, {{"IN1"}, {"IN2"}}, a) : bindExtensible(ck, call, {}, "IN", 1, 2, a);
    if (!ok) return ck.bad(call.loc);
    std::vector<Checked> ins = a;
    const Type* t = unify(ck, call, ins, true);
    if (!t) return ck.bad(call.loc);
    return makeResult(ck, chainNode<OP>(ck.pool(), t, nodesOf(ins)), ck.types().elementary(TK::Bool), call, a);
}

}  // namespace

void registerSelect(Checker& ck) {
    ck.addBuiltin("SEL", checkSel);
    ck.addBuiltin("MUX", checkMux);
    ck.addBuiltin("MAX", checkExtreme<true>);
    ck.addBuiltin("MIN", checkExtreme<false>);
    ck.addBuiltin("LIMIT", checkLimit);
    ck.addBuiltin("GT", checkCompare<CmpOp::Gt>);
    ck.addBuiltin("GE", checkCompare<CmpOp::Ge>);
    ck.addBuiltin("EQ", checkCompare<CmpOp::Eq>);
    ck.addBuiltin("LE", checkCompare<CmpOp::Le>);
    ck.addBuiltin("LT", checkCompare<CmpOp::Lt>);
    ck.addBuiltin("NE", checkCompare<CmpOp::Ne>);
}

}  // namespace strun::stdlib::bind
