// Character-string functions for STRING and WSTRING (1-based positions):
// LEN LEFT RIGHT MID CONCAT INSERT DELETE REPLACE FIND. Formal names are the
// IEC ones (IN, IN1, L, P) and the CODESYS ones (STR, STR1, SIZE, LEN, POS).
#include <fmt/format.h>

#include "interpreter/builtins/bind_support.h"
#include "interpreter/builtins/register_groups.h"
#include "interpreter/builtins/string_nodes.h"

namespace strun::stdlib::bind {

namespace {

// The string kind of the first input; both string inputs must agree.
bool stringInputs(Checker& ck, CallArgs& call, std::initializer_list<const Checked*> strs, bool& wide) {
    const Checked* first = *strs.begin();
    if (!sema::isStringType(first->type->kind)) {
        argError(ck, *first, call.name, "the input must be a STRING or WSTRING");
        return false;
    }
    wide = first->type->kind == TK::WString;
    for (const Checked* s : strs)
        if (s->type->kind != first->type->kind) {
            argError(ck, *s, call.name, fmt::format("the inputs must all be {}", wide ? "WSTRING" : "STRING"));
            return false;
        }
    return true;
}

bool integerInputs(Checker& ck, CallArgs& call, std::initializer_list<Checked*> ints) {
    for (Checked* v : ints) {
        if (!isIntegerArg(*v) && !isBitArg(*v)) {
            argError(ck, *v, call.name, "lengths and positions must be integers");
            return false;
        }
        *v = ck.settle(*v);
    }
    return true;
}

const Type* intResult(Checker& ck) { return ck.types().elementary(TK::Int); }

// Arguments that are STRING/WSTRING CONSTANTs with a known value (decision
// 0331) read as that value when every argument is a constant, so that the
// call folds (below); otherwise they stay reads of the variable.
void constantArguments(std::vector<Checked>& a) {
    std::vector<Checked> folded = a;
    for (Checked& v : folded)
        if (v.var && v.var->constText && v.type == v.var->type && !allConst({v})) {
            v.node = v.var->constText;
            v.isConst = true;
        }
    if (allConst(folded)) a = std::move(folded);
}

// A call on constant strings and integers is itself a constant (decision
// 0331): `cTopic : STRING(100) := CONCAT(CONCAT(cMain, cType), cDevice);` in a
// VAR_GLOBAL CONSTANT list, as CODESYS and TwinCAT accept it. The node runs
// once, now, on a scratch frame that holds its result temporary (at `off`);
// the value becomes a literal of its own length, so assigning it warns only
// when its text is too long.
template <class Ch>
Checked foldedString(Checker& ck, Checked r, const std::vector<Checked>& a, uint32_t off) {
    if (!r.ok || a.empty() || !allConst(a)) return r;
    std::vector<uint8_t> frame(off + r.type->size, 0);
    exec::Ctx scratch;
    scratch.frame = frame.data();
    std::basic_string_view<Ch> text(reinterpret_cast<const Ch*>(r.node->addr(scratch)));
    const auto* first = reinterpret_cast<const uint8_t*>(text.data());
    return ck.constantString(std::vector<uint8_t>(first, first + text.size() * sizeof(Ch)), text.size(), sizeof(Ch) == 2, r.loc);
}

Checked checkLen(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN|STR"}}, a)) return ck.bad(call.loc);
    bool wide = false;
    if (!stringInputs(ck, call, {&a[0]}, wide)) return ck.bad(call.loc);
    constantArguments(a);
    exec::Expr* n = wide ? static_cast<exec::Expr*>(ck.pool().make<LenNode<char16_t>>(a[0].node)) : ck.pool().make<LenNode<char>>(a[0].node);
    return makeResult(ck, n, intResult(ck), call, a);
}

Checked checkFind(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN1|STR1"}, {"IN2|STR2"}}, a)) return ck.bad(call.loc);
    bool wide = false;
    if (!stringInputs(ck, call, {&a[0], &a[1]}, wide)) return ck.bad(call.loc);
    constantArguments(a);
    exec::Expr* n = wide ? static_cast<exec::Expr*>(ck.pool().make<FindNode<char16_t>>(a[0].node, a[1].node))
                         : ck.pool().make<FindNode<char>>(a[0].node, a[1].node);
    return makeResult(ck, n, intResult(ck), call, a);
}

template <class Ch>
exec::Expr* concatNode(Checker& ck, const std::vector<Checked>& a, const Type* t) {
    auto* n = ck.pool().make<ConcatNode<Ch>>();
    for (const auto& v : a) n->parts.push_back(v.node);
    n->maxLen = t->maxLen;
    n->off = ck.allocTemp(t->size);
    return n;
}

Checked checkConcat(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    // TwinCAT/CODESYS name CONCAT's inputs STR1, STR2 (IEC: IN1, IN2).
    bool strNames = false;
    for (const std::string& n : call.names) strNames = strNames || n.rfind("STR", 0) == 0;
    if (!bindExtensible(ck, call, {}, strNames ? "STR" : "IN", 1, 2, a)) return ck.bad(call.loc);
    bool wide = false;
    int64_t total = 0;
    // A CHAR (WCHAR) input is the string of that character, as SIMATIC AX's
    // Concat takes it (the implicit CHAR -> STRING of decision 0394).
    for (auto& v : a)
        if (v.type && sema::isCharType(v.type->kind))
            v = ck.coerce(v, ck.types().string(1, v.type->kind == TK::WChar), v.loc, call.name.c_str());
    for (const auto& v : a) {
        if (!v.ok) return ck.bad(call.loc);
        if (!sema::isStringType(v.type->kind)) return argError(ck, v, call.name, "the inputs must be STRING or WSTRING");
        total += v.type->maxLen;
    }
    wide = a[0].type->kind == TK::WString;
    for (const auto& v : a)
        if (v.type->kind != a[0].type->kind) return argError(ck, v, call.name, fmt::format("the inputs must all be {}", wide ? "WSTRING" : "STRING"));
    const Type* t = stringResultType(ck, wide, total);
    constantArguments(a);
    exec::Expr* n = wide ? concatNode<char16_t>(ck, a, t) : concatNode<char>(ck, a, t);
    Checked r = makeResult(ck, n, t, call, a);
    const uint32_t off = wide ? static_cast<ConcatNode<char16_t>*>(n)->off : static_cast<ConcatNode<char>*>(n)->off;
    return wide ? foldedString<char16_t>(ck, r, a, off) : foldedString<char>(ck, r, a, off);
}

template <class Ch, StrFn F>
exec::Expr* editNode(Checker& ck, const Type* t, exec::Expr* s1, exec::Expr* s2, exec::Expr* l, exec::Expr* p) {
    auto* n = ck.pool().make<StrEditNode<Ch, F>>();
    n->s1 = s1;
    n->s2 = s2;
    n->l = l;
    n->p = p;
    n->maxLen = t->maxLen;
    n->off = ck.allocTemp(t->size);
    return n;
}

template <StrFn F>
Checked finishEdit(Checker& ck, CallArgs& call, bool wide, int64_t maxLen, const std::vector<Checked>& a, exec::Expr* s1,
                   exec::Expr* s2, exec::Expr* l, exec::Expr* p) {
    const Type* t = stringResultType(ck, wide, maxLen);
    if (wide) {
        auto* n = editNode<char16_t, F>(ck, t, s1, s2, l, p);
        return foldedString<char16_t>(ck, makeResult(ck, n, t, call, a), a, static_cast<StrEditNode<char16_t, F>*>(n)->off);
    }
    auto* n = editNode<char, F>(ck, t, s1, s2, l, p);
    return foldedString<char>(ck, makeResult(ck, n, t, call, a), a, static_cast<StrEditNode<char, F>*>(n)->off);
}

template <StrFn F>
Checked checkLeftRight(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN|STR"}, {"L|SIZE"}}, a)) return ck.bad(call.loc);
    bool wide = false;
    if (!stringInputs(ck, call, {&a[0]}, wide) || !integerInputs(ck, call, {&a[1]})) return ck.bad(call.loc);
    constantArguments(a);
    return finishEdit<F>(ck, call, wide, a[0].type->maxLen, a, a[0].node, nullptr, a[1].node, nullptr);
}

Checked checkMid(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN|STR"}, {"L|LEN"}, {"P|POS"}}, a)) return ck.bad(call.loc);
    bool wide = false;
    if (!stringInputs(ck, call, {&a[0]}, wide) || !integerInputs(ck, call, {&a[1], &a[2]})) return ck.bad(call.loc);
    constantArguments(a);
    return finishEdit<StrFn::Mid>(ck, call, wide, a[0].type->maxLen, a, a[0].node, nullptr, a[1].node, a[2].node);
}

Checked checkInsert(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN1|STR1"}, {"IN2|STR2"}, {"P|POS"}}, a)) return ck.bad(call.loc);
    bool wide = false;
    if (!stringInputs(ck, call, {&a[0], &a[1]}, wide) || !integerInputs(ck, call, {&a[2]})) return ck.bad(call.loc);
    constantArguments(a);
    int64_t maxLen = int64_t(a[0].type->maxLen) + a[1].type->maxLen;
    return finishEdit<StrFn::Insert>(ck, call, wide, maxLen, a, a[0].node, a[1].node, nullptr, a[2].node);
}

Checked checkDelete(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN|STR"}, {"L|LEN"}, {"P|POS"}}, a)) return ck.bad(call.loc);
    bool wide = false;
    if (!stringInputs(ck, call, {&a[0]}, wide) || !integerInputs(ck, call, {&a[1], &a[2]})) return ck.bad(call.loc);
    constantArguments(a);
    return finishEdit<StrFn::Delete>(ck, call, wide, a[0].type->maxLen, a, a[0].node, nullptr, a[1].node, a[2].node);
}

Checked checkReplace(Checker& ck, CallArgs& call) {
    std::vector<Checked> a;
    if (!bindFixed(ck, call, {{"IN1|STR1"}, {"IN2|STR2"}, {"L"}, {"P"}}, a)) return ck.bad(call.loc);
    bool wide = false;
    if (!stringInputs(ck, call, {&a[0], &a[1]}, wide) || !integerInputs(ck, call, {&a[2], &a[3]})) return ck.bad(call.loc);
    constantArguments(a);
    int64_t maxLen = int64_t(a[0].type->maxLen) + a[1].type->maxLen;
    return finishEdit<StrFn::Replace>(ck, call, wide, maxLen, a, a[0].node, a[1].node, a[2].node, a[3].node);
}

}  // namespace

void registerStrings(Checker& ck) {
    ck.addBuiltin("LEN", checkLen);
    ck.addBuiltin("FIND", checkFind);
    ck.addBuiltin("CONCAT", checkConcat);
    ck.addBuiltin("LEFT", checkLeftRight<StrFn::Left>);
    ck.addBuiltin("RIGHT", checkLeftRight<StrFn::Right>);
    ck.addBuiltin("MID", checkMid);
    ck.addBuiltin("INSERT", checkInsert);
    ck.addBuiltin("DELETE", checkDelete);
    ck.addBuiltin("REPLACE", checkReplace);
    // The WSTRING names of CODESYS' and TwinCAT's standard library (WLEN,
    // WCONCAT, ...): the same functions, which take WSTRING as IEC's do.
    ck.addBuiltin("WLEN", checkLen);
    ck.addBuiltin("WFIND", checkFind);
    ck.addBuiltin("WCONCAT", checkConcat);
    ck.addBuiltin("WLEFT", checkLeftRight<StrFn::Left>);
    ck.addBuiltin("WRIGHT", checkLeftRight<StrFn::Right>);
    ck.addBuiltin("WMID", checkMid);
    ck.addBuiltin("WINSERT", checkInsert);
    ck.addBuiltin("WDELETE", checkDelete);
    ck.addBuiltin("WREPLACE", checkReplace);
}

}  // namespace strun::stdlib::bind
