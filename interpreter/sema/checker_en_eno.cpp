// EN/ENO on a function call (decision 0333): `MOVE(EN := bRun, IN := 1,
// ENO => bDone)`, as IEC 61131-3 allows on every function and Beremiz and
// OpenPLC write for the blocks of an LD rung. The call is checked without
// EN and ENO; EN (default TRUE) goes into a temporary, ENO receives it, and
// the function runs only when it is TRUE.
#include <fmt/format.h>

#include "interpreter/ast/ast_clone.h"
#include "interpreter/sema/checker.h"
#include "stdlib/number_scan.h"

namespace strun::sema {

// Without building an upper-case copy: checkCall asks this of every argument.
bool Checker::isEnArgument(const ast::Arg& a) { return !a.output && stdlib::equalsIgnoreCase(a.name, "EN"); }
bool Checker::isEnoArgument(const ast::Arg& a) { return a.output && stdlib::equalsIgnoreCase(a.name, "ENO"); }

bool Checker::hasEnEno(const ast::Expr& call) {
    for (const ast::Arg& a : call.args)
        if (isEnArgument(a) || isEnoArgument(a)) return true;
    return false;
}

bool Checker::splitEnEno(const ast::Expr& e, EnEnoParts& out) {
    const ast::Arg* en = nullptr;
    for (const ast::Arg& a : e.args) {
        if (isEnArgument(a)) en = &a;
        if (isEnoArgument(a)) out.eno = &a;
    }
    ast::ExprPtr plain = ast::cloneExpr(e);
    std::erase_if(plain->args, [](const ast::Arg& a) { return isEnArgument(a) || isEnoArgument(a); });
    out.call = plain.get();
    enEnoCalls_.push_back(std::move(plain));  // the checked nodes point into it
    const Type* boolType = types().elementary(TK::Bool);
    Checked enable = en && en->value ? checkExpr(*en->value) : constInt(1, boolType, e.loc);
    if (!enable.ok) return false;
    enable = coerce(enable, boolType, en && en->value ? en->value->loc : e.loc, "EN");
    if (!enable.ok) return false;
    out.temp = tempPlace(boolType);
    out.storeEn = storeTo(out.temp, boolType, enable.node, -1);
    return true;
}

Checked Checker::checkEnEnoCall(const ast::Expr& e, bool statement) {
    EnEnoParts parts;
    if (!splitEnEno(e, parts)) return bad(e.loc);
    const ast::Expr& call = *parts.call;
    const ast::Arg* eno = parts.eno;
    exec::Expr* temp = parts.temp;
    exec::Stmt* storeEn = parts.storeEn;
    const Type* boolType = types().elementary(TK::Bool);

    Checked inner = checkCall(call, statement);
    if (!inner.ok) return inner;
    if (!inner.type || !(isIntRep(inner.type) || isRealRep(inner.type))) {
        error(diag::E0301, e.loc, fmt::format("EN/ENO on a call whose value is {}: only calls with an elementary value take them",
                                              inner.type ? typeName(inner.type) : std::string("nothing")));
        return bad(e.loc);
    }
    exec::Stmt* storeEno = nullptr;
    if (eno && eno->value) {
        Checked target = checkExpr(*eno->value);
        Checked flag;
        flag.ok = true;
        flag.loc = eno->value->loc;
        flag.type = boolType;
        flag.node = temp;  // the temporary EN was written to
        storeEno = assignChecked(target, flag, eno->value->loc);
        if (!storeEno) return bad(e.loc);
    }
    Checked r;  // a value computed at run time, never a constant or a literal
    r.ok = true;
    r.loc = e.loc;
    r.type = inner.type;
    r.hasCall = true;
    // MOVE(IN := 2), SQRT(EN := x, IN := 16.0): from untyped literals, the value
    // takes the type it is assigned to, as without EN/ENO.
    r.flexibleLiteral = inner.untypedInt || inner.untypedReal || inner.flexibleLiteral;
    r.node = pool().make<exec::EnEnoCall>(storeEn, temp, inner.node, storeEno);
    r.node->type = inner.type;
    return r;
}

}  // namespace strun::sema
