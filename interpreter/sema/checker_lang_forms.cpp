// TwinCAT/CODESYS expression forms beyond IEC 61131-3 (issue 22):
// a STRING/WSTRING indexed like an array of its bytes/words, a pointer
// indexed like an array, and an assignment used as a value.
#include <deque>

#include <fmt/format.h>

#include "interpreter/ast/ast_clone.h"
#include "interpreter/exec/text_value_nodes.h"
#include "interpreter/exec/value_nodes.h"
#include "interpreter/sema/checker.h"

namespace strun::sema {

namespace {

// `p[i]` on a POINTER TO T: the address p + i * SIZEOF(T), as an integer
// (the DerefPlace around it checks it against the memory map).
struct PointerElementAddress final : exec::Expr {
    exec::Expr* pointer;
    exec::Expr* index;
    int64_t stride;
    PointerElementAddress(exec::Expr* p, exec::Expr* i, int64_t s) : pointer(p), index(i), stride(s) {}
    int64_t i(exec::Ctx& c) override {
        return static_cast<int64_t>(static_cast<uint64_t>(pointer->i(c)) +
                                    static_cast<uint64_t>(index->i(c)) * static_cast<uint64_t>(stride));
    }
};

// `(x := v)` as a value: runs the assignment, then reads the place.
struct AssignmentValue final : exec::Expr {
    exec::Stmt* assign;
    exec::Expr* read;
    AssignmentValue(exec::Stmt* a, exec::Expr* r) : assign(a), read(r) {}
    int64_t i(exec::Ctx& c) override {
        assign->exec(c);
        return read->i(c);
    }
    double f(exec::Ctx& c) override {
        assign->exec(c);
        return read->f(c);
    }
    uint8_t* addr(exec::Ctx& c) override {
        assign->exec(c);
        return read->addr(c);
    }
};

}  // namespace

Checked Checker::checkStringOrPointerIndex(const ast::Expr& e, const Checked& base) {
    const Type* t = base.type;
    if (e.kids.size() != 2) {
        error(diag::E0301, e.loc, fmt::format("{} subscript(s) given, a {} takes one", e.kids.size() - 1, typeName(t)));
        return bad(e.loc);
    }
    Checked ix = checkExpr(*e.kids[1]);
    if (!ix.ok) return bad(e.loc);
    if (!(isInteger(ix.type->kind) || isBitString(ix.type->kind) || ix.untypedInt)) {
        error(diag::E0204, e.kids[1]->loc, fmt::format("a subscript must be an integer, not {}", typeName(ix.type)));
        return bad(e.loc);
    }
    ix = settle(ix);
    Checked c;
    c.ok = true;
    c.loc = e.loc;
    c.hasCall = base.hasCall || ix.hasCall;
    if (isStringType(t->kind)) {
        // TwinCAT/CODESYS: s[i] is the byte (WSTRING: the word) at index i,
        // counted from 0, over the string's whole storage (decision 0205).
        // SIMATIC AX (IEC Ed.3): the i-th CHAR (WCHAR), counted from 1, over
        // the string's characters: the same storage, one place further on;
        // outside, the NUL character (decision 0394). Library files keep the
        // TwinCAT reading.
        const bool wide = t->kind == TK::WString;
        const bool ax = options_.axStrings && !libraryFiles_.count(e.loc.file);
        if (ax) {
            c.type = types().elementary(wide ? TK::WChar : TK::Char);
            c.isPlace = base.isPlace;
            c.readOnly = base.readOnly;
            c.readOnlyWhy = base.readOnlyWhy;
            auto* n = pool().make<exec::AxCharPlace>(base.node, ix.node, std::max<uint64_t>(t->maxLen, 1), wide ? 2u : 1u);
            c.node = loadFrom(n, c.type);
            c.node->type = c.type;
            return c;
        }
        c.type = types().elementary(wide ? TK::Word : TK::Byte);
        c.isPlace = base.isPlace;
        c.readOnly = base.readOnly;
        c.readOnlyWhy = base.readOnlyWhy;
        auto* n = pool().make<exec::Index1Place>();
        n->base = base.node;
        n->index = ix.node;
        n->lo = 0;
        n->count = static_cast<int64_t>(t->maxLen) + 1;
        n->stride = wide ? 2 : 1;
        n->site = site(e.loc);
        c.node = loadFrom(n, c.type);
        c.node->type = c.type;
        return c;
    }
    // p[i] is (p + i * SIZEOF(p^))^, checked like every dereference.
    const Type* target = t->target;
    if (!target || target->size == 0) {
        error(diag::E0204, e.loc, fmt::format("cannot index a {}: its target has no size", typeName(t)));
        return bad(e.loc);
    }
    c.type = target;
    c.isPlace = true;
    auto* address = pool().make<PointerElementAddress>(base.node, ix.node, static_cast<int64_t>(target->size));
    address->type = types().elementary(TK::ULInt);
    c.node = loadFrom(pool().make<exec::DerefPlace>(address, site(e.loc), static_cast<uint32_t>(target->size)), c.type);
    c.node->type = c.type;
    return c;
}

Checked Checker::checkAssignmentValue(const ast::Expr& e) {
    // The assignment statement the expression stands for, kept alive with
    // the checker (the exec tree does not point into it, but its messages do).
    auto stmt = std::make_unique<ast::Stmt>();
    stmt->kind = ast::StmtKind::Assign;
    stmt->loc = e.loc;
    stmt->target = ast::cloneExpr(*e.kids[0]);
    stmt->expr = ast::cloneExpr(*e.kids[1]);
    exec::Stmt* assign = checkAssign(*stmt);
    assignmentValues_.push_back(std::move(stmt));
    if (!assign) return bad(e.loc);
    Checked read = checkExpr(*e.kids[0]);
    if (!read.ok) return read;
    Checked c = read;
    c.isPlace = false;
    c.var = nullptr;
    c.isConst = false;
    c.hasCall = true;
    c.direct = Checked::Direct::None;
    c.node = pool().make<AssignmentValue>(assign, read.node);
    c.node->type = read.type;
    return c;
}

}  // namespace strun::sema
