// Statements and POU bodies.
#include <map>

#include <fmt/format.h>

#include "interpreter/exec/class_part_nodes.h"
#include "interpreter/exec/else_nodes.h"
#include "interpreter/sema/case_lowering.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/expr_observer.h"
#include "interpreter/sema/fuse.h"
#include "interpreter/sema/fuse_swap.h"
#include "interpreter/sema/node_factory.h"
#include "interpreter/sema/read_before_write.h"
#include "stdlib/ascii_case.h"

namespace strun::sema {

namespace {
uint32_t alignFrameTop(uint32_t v, uint32_t a) { return a <= 1 ? v : (v + a - 1) / a * a; }

template <class T, bool FRAME>
exec::Stmt* makeLocal(exec::NodePool& pool, uint32_t off, exec::Expr* v) {
    // x := F(...): the call runs without the dispatch to its value node (decision 0154).
    if (auto* call = exec::nodeCast<exec::CallPou>(v)) return pool.make<exec::AssignCallLocal<T, FRAME>>(off, call);
    // x := a OP b with the operator fused (decision 0154).
    if (auto* op = exec::nodeCast<exec::FusedArith>(v))
        if (exec::Stmt* n = op->makeAssignLocal(pool, FRAME, off, typeid(T))) return n;
    return pool.make<exec::AssignLocal<T, FRAME>>(off, v);
}

template <bool FRAME>
exec::Stmt* assignLocal(exec::NodePool& pool, Rep rep, uint32_t off, exec::Expr* v) {
    switch (rep) {
        case Rep::I8: return makeLocal<int8_t, FRAME>(pool, off, v);
        case Rep::I16: return makeLocal<int16_t, FRAME>(pool, off, v);
        case Rep::I32: return makeLocal<int32_t, FRAME>(pool, off, v);
        case Rep::I64: return makeLocal<int64_t, FRAME>(pool, off, v);
        case Rep::U8: return makeLocal<uint8_t, FRAME>(pool, off, v);
        case Rep::Bool: return makeLocal<bool, FRAME>(pool, off, v);
        case Rep::U16: return makeLocal<uint16_t, FRAME>(pool, off, v);
        case Rep::U32: return makeLocal<uint32_t, FRAME>(pool, off, v);
        case Rep::U64: return makeLocal<uint64_t, FRAME>(pool, off, v);
        case Rep::F32: return makeLocal<float, FRAME>(pool, off, v);
        case Rep::F64: return makeLocal<double, FRAME>(pool, off, v);
        default: return nullptr;
    }
}

template <class T>
exec::Stmt* assignBitTyped(exec::NodePool& pool, exec::Expr* place, exec::Expr* v) {
    auto* bp = exec::nodeCast<exec::BitPlace<T>>(place);
    return bp ? pool.make<exec::AssignBit<T>>(bp->base, bp->bit, v) : nullptr;
}
}  // namespace

uint32_t Checker::allocTemp(uint32_t size) {
    frameTop_ = alignFrameTop(frameTop_, 8);
    uint32_t off = frameTop_;
    frameTop_ += std::max<uint32_t>(size, 1);
    return off;
}

exec::Expr* Checker::tempPlace(const Type* t, uint32_t* offsetOut) {
    uint32_t off = allocTemp(t->size);
    if (offsetOut) *offsetOut = off;
    exec::Expr* n = makeByRep<exec::FrameVar>(pool(), isAggregate(t) ? Rep::Void : repOf(t), off);
    n->type = t;
    return n;
}

exec::Stmt* Checker::storeTo(exec::Expr* place, const Type* t, exec::Expr* value, int bit) {
    if (place->bitIndex() >= 0) {
        if (auto* s = assignBitTyped<uint8_t>(pool(), place, value)) return s;
        if (auto* s = assignBitTyped<uint16_t>(pool(), place, value)) return s;
        if (auto* s = assignBitTyped<uint32_t>(pool(), place, value)) return s;
        if (auto* s = assignBitTyped<uint64_t>(pool(), place, value)) return s;
    }
    if (isStringType(t->kind))
        if (exec::Stmt* n = fuseAppendInPlace(pool(), t->kind == TK::WString, place, t->maxLen, value)) return n;
    if (t->kind == TK::String) return pool().make<exec::AssignString<char>>(place, value, t->maxLen);
    if (t->kind == TK::WString) return pool().make<exec::AssignString<char16_t>>(place, value, t->maxLen);
    if (auto* part = exec::nodeCast<exec::ClassPartOf>(value))  // a derived instance into a base class variable (decision 0392)
        return pool().make<exec::AssignClassPart>(place, part->instance, static_cast<uint32_t>(sizeof(const exec::ClassDesc*)), t->size);
    if (isAggregate(t)) return pool().make<exec::AssignBytes>(place, value, t->size);
    if (auto* element = exec::nodeCast<exec::Index1Target>(place))  // a[i] := value (decision 0154)
        if (exec::Stmt* n = element->makeStore(pool(), value, repOf(t) == Rep::Bool)) return n;
    if (exec::Stmt* n = fuseStorePending(pool(), repOf(t), place, value)) return n;  // call arguments, FB inputs
    if (exec::Stmt* n = fuseAssignConst(pool(), repOf(t), value, place, exec::BaseKind::Self, 0)) return n;
    switch (repOf(t)) {
        case Rep::I8: return pool().make<exec::Assign<int8_t>>(place, value);
        case Rep::I16: return pool().make<exec::Assign<int16_t>>(place, value);
        case Rep::I32: return pool().make<exec::Assign<int32_t>>(place, value);
        case Rep::I64: return pool().make<exec::Assign<int64_t>>(place, value);
        case Rep::U8: return pool().make<exec::Assign<uint8_t>>(place, value);
        case Rep::Bool: return pool().make<exec::Assign<bool>>(place, value);
        case Rep::U16: return pool().make<exec::Assign<uint16_t>>(place, value);
        case Rep::U32: return pool().make<exec::Assign<uint32_t>>(place, value);
        case Rep::U64: return pool().make<exec::Assign<uint64_t>>(place, value);
        case Rep::F32: return pool().make<exec::Assign<float>>(place, value);
        case Rep::F64: return pool().make<exec::Assign<double>>(place, value);
        default: return pool().make<exec::NopStmt>();
    }
}

exec::Stmt* Checker::assignChecked(Checked target, Checked value, const ast::Loc& loc) {
    if (!target.ok || !value.ok) return nullptr;
    if (target.propertyInstance) return assignProperty(target, value, loc);
    if (!target.isPlace) {
        error(diag::E0206, loc, "the left side of ':=' is not a variable");
        return nullptr;
    }
    if (target.readOnly) {
        error(diag::E0201, loc, fmt::format("cannot assign: {}", target.readOnlyWhy));
        return nullptr;
    }
    const Type* t = target.type;
    if (isFlexibleRef(t)) return assignFlexibleRef(target, value, loc);
    // An integer converts to an enumeration implicitly (a warning, an error with
    // --strict or {attribute 'strict'}: coerce); another enumeration never does.
    if (t->kind == TK::Enum && value.type && value.type->kind == TK::Enum && value.type != t && value.type->base && t->base) {
        // Another enumeration: CODESYS converts through the integer value with a
        // warning; an error with --strict (decision 0207).
        if (!lenient(diag::W0001, value.loc, fmt::format("implicit conversion from {} to {}: enumerations of different types", typeName(value.type), typeName(t))))
            return nullptr;
        Checked asInt = value;
        asInt.type = value.type->base;
        asInt = convert(asInt, t->base, value.loc);
        if (!asInt.ok) return nullptr;
        asInt.type = t;
        if (asInt.node) asInt.node->type = t;
        value = asInt;
    }
    if (t->kind == TK::Enum && !(value.type == t) && !(value.untypedInt || isInteger(value.type->kind) || isBitString(value.type->kind))) {
        error(diag::E0201, value.loc, fmt::format("cannot assign {} to {} (an enumeration takes only its own values)", typeName(value.type), typeName(t)));
        return nullptr;
    }
    Checked v = coerce(value, t, value.loc, "assignment");
    if (!v.ok) return nullptr;
    if (target.var && pou_ && target.var == pou_->result) assignedResult_ = true;
    if ((target.direct == Checked::Direct::Self || target.direct == Checked::Direct::Frame) && !isAggregate(t) && target.node->bitIndex() < 0) {
        // Fused forms (decision 0151): x := x + k, x := constant.
        const bool frame = target.direct == Checked::Direct::Frame;
        if (exec::Stmt* n = fuseAddConstLocal(pool(), repOf(t), frame, target.directOffset, v.node)) return n;
        if (exec::Stmt* n = fuseAssignConst(pool(), repOf(t), v.node, nullptr, frame ? exec::BaseKind::Frame : exec::BaseKind::Self, target.directOffset)) return n;
    }
    if (target.direct == Checked::Direct::Self && !isAggregate(t))
        return assignLocal<false>(pool(), repOf(t), target.directOffset, v.node);
    if (target.direct == Checked::Direct::Frame && !isAggregate(t))
        return assignLocal<true>(pool(), repOf(t), target.directOffset, v.node);
    return storeTo(target.node, t, v.node);
}

int Checker::labelId(const std::string& key) {
    auto it = labels_.find(key);
    if (it != labels_.end()) return it->second;
    int id = static_cast<int>(labels_.size());
    labels_[key] = id;
    return id;
}

exec::Block* Checker::checkBlock(const ast::StmtList& list) {
    auto* block = pool().make<exec::Block>();
    const ast::Stmt* leaving = nullptr;  // the RETURN / EXIT / CONTINUE / JMP the list already left by
    for (const auto& s : list) {
        if (!s) continue;
        if (leaving && s->kind != ast::StmtKind::Label && s->kind != ast::StmtKind::Empty) {
            const char* how = leaving->kind == ast::StmtKind::Return ? "RETURN" : leaving->kind == ast::StmtKind::Exit ? "EXIT"
                              : leaving->kind == ast::StmtKind::Continue ? "CONTINUE" : "JMP";
            warning(diag::W0011, s->loc, fmt::format("unreachable code: it follows {}", how))
                .note(leaving->loc, fmt::format("the statements after this {} never run", how));
            leaving = nullptr;  // one warning per unreachable stretch
        }
        if ((s->kind == ast::StmtKind::Return && !s->expr) || s->kind == ast::StmtKind::Exit || s->kind == ast::StmtKind::Continue ||
            s->kind == ast::StmtKind::Jmp)
            leaving = s.get();
        if (s->kind == ast::StmtKind::Label) leaving = nullptr;
        if (s->kind == ast::StmtKind::Label) {
            std::string key = upper(s->name);
            if (definedLabels_.count(key)) error(diag::E0504, s->loc, fmt::format("duplicate label '{}'", s->name));
            definedLabels_.insert(key);
            block->labels.push_back({labelId(key), block->stmts.size()});
            continue;
        }
        if (s->kind == ast::StmtKind::Empty) continue;
        exec::Stmt* st = checkStmt(*s);
        if (st) {
            st->line = s->loc.line;
            st->file = s->loc.file;
            st->col = s->loc.col;
            block->stmts.push_back(st);
        }
    }
    fuseSwaps(pool(), *block);  // t := a[i]; a[i] := a[j]; a[j] := t as one node (decision 0379)
    return block;
}

// `RETURN (xDone);` (CODESYS, TwinCAT): leaves the POU when the condition is
// TRUE, as `IF xDone THEN RETURN; END_IF` (decision 0433). Not IEC 61131-3:
// --strict refuses it.
exec::Stmt* Checker::checkConditionalReturn(const ast::Stmt& s) {
    if (refusedByStrict(diag::E0001, s.expr->loc, "a conditional RETURN (expr) is a CODESYS extension; --strict needs IF expr THEN RETURN; END_IF"))
        return nullptr;
    Checked c = checkCondition(*s.expr, "a RETURN condition");
    if (!c.ok) return nullptr;
    auto* leave = pool().make<exec::FlowStmt>(exec::Flow::Return);
    leave->line = s.loc.line;
    leave->file = s.loc.file;
    leave->col = s.loc.col;
    auto* block = pool().make<exec::Block>();
    block->stmts.push_back(leave);
    if (exec::Stmt* fused = fuseIf(pool(), c.node, block, nullptr)) return fused;
    return pool().make<exec::If1Stmt>(c.node, block, nullptr);
}

// r REF= x (bind a REFERENCE) and itf ?= x (assignment attempt: the address
// when the instance implements the interface, else 0).
exec::Stmt* Checker::checkRefAssign(const ast::Stmt& s) {
    bool saved = suppressAutoDeref_;
    suppressAutoDeref_ = true;
    Checked target = checkExpr(*s.target);
    suppressAutoDeref_ = saved;
    if (!target.ok) return nullptr;
    if (s.kind == ast::StmtKind::RefAssign) {
        bool isNull = s.expr->kind == ast::ExprKind::Literal && s.expr->lit == ast::LitKind::Integer && s.expr->text == "0";
        if (target.propertyInstance && target.type->kind == TK::Reference) {
            // `i_Timer.Input REF= _Input;` on a REFERENCE TO property: SET with the reference (decision 0443).
            Checked src = isNull ? constInt(0, target.type, s.expr->loc) : checkExpr(*s.expr);
            if (!src.ok) return nullptr;
            return assignProperty(target, src, s.loc);
        }
        if (target.type->kind != TK::Reference || !target.isPlace) {
            error(diag::E0206, s.target->loc, "REF= needs a REFERENCE TO variable on the left");
            return nullptr;
        }
        Checked v;
        if (isNull) {
            v = constInt(0, target.type, s.expr->loc);
        } else {
            // `r REF= GetTest(name)`: a function or method returning REFERENCE TO T
            // gives the address itself, NULL included (TcUnit binds its results
            // this way), not the variable it refers to (decision 0477).
            Checked src;
            if (s.expr->kind == ast::ExprKind::Call) {
                src = checkCall(*s.expr, false);
                if (observer_) observer_->checked(*s.expr, src, pou_);
            } else {
                src = checkExpr(*s.expr);
            }
            if (!src.ok) return nullptr;
            if (src.type->kind == TK::Reference && sameType(src.type->target, target.type->target))
                return storeTo(target.node, types().elementary(TK::LWord), src.node);
            if (!src.isPlace || !(sameType(src.type, target.type->target) || isBlockOrExtends(src.type, target.type->target))) {
                error(diag::E0206, s.expr->loc, fmt::format("REF= needs a variable of type {}, not {}", typeName(target.type->target), typeName(src.type)));
                return nullptr;
            }
            v.ok = true;
            v.loc = s.expr->loc;
            v.type = target.type;
            v.node = pool().make<exec::AddressOf>(src.node);
        }
        return storeTo(target.node, types().elementary(TK::LWord), v.node);
    }
    Checked src = checkExpr(*s.expr);
    if (!src.ok) return nullptr;
    // A REF_TO / POINTER TO a class on the left (IEC Ed.3, SIMATIC AX): the
    // address when the instance is of that class or one derived from it, else NULL (decision 0366).
    const bool classRef = (target.type->kind == TK::Pointer || target.type->kind == TK::Reference) && target.type->target &&
                          target.type->target->kind == TK::FunctionBlock && target.type->target->pou && target.isPlace;
    if ((target.type->kind != TK::Interface && !classRef) || !target.isPlace) {
        error(diag::E0206, s.target->loc, "?= needs an interface variable on the left");
        return nullptr;
    }
    exec::Expr* addr = nullptr;
    if (src.type->kind == TK::Interface) addr = src.node;
    else if (src.type->kind == TK::FunctionBlock && src.isPlace) addr = pool().make<exec::AddressOf>(src.node);
    else if (src.type->kind == TK::Pointer && src.type->target->kind == TK::FunctionBlock) addr = src.node;
    if (!addr) {
        error(diag::E0405, s.expr->loc, fmt::format("?= needs an interface, a function-block instance or a pointer to one, not {}", typeName(src.type)));
        return nullptr;
    }
    exec::Expr* cast = pool().make<exec::TryCastInterface>(addr, classRef ? target.type->target->pou : target.type->pou);
    return storeTo(target.node, types().elementary(TK::LWord), cast);
}

// An inferred temporary (VarSym::inferred) named by `target` that no
// assignment has typed yet, else null.
VarSym* Checker::inferredTemp(const ast::Expr& target) {
    if (target.kind != ast::ExprKind::Name) return nullptr;
    VarSym* v = lookupVar(upper(target.name));
    return v && v->inferred ? v : nullptr;
}

// The first assignment of an inferred temporary: it takes the value's type
// and a place in the frame of the body being checked, for the whole body.
void Checker::fixInferredTemp(VarSym* v, const Type* t) {
    frameTop_ = alignFrameTop(frameTop_, std::max<uint32_t>(t->align, 1));
    v->offset = allocTemp(t->size) - frameBias_;
    v->type = t;
    v->inferredPending = false;
}

Checked Checker::inferredValue(const ast::Expr& e) {
    Checked value = checkExpr(e);
    if (!value.ok) return value;
    // `LD 40`: an untyped integer literal is an INT where it fits (decision 0415).
    if (value.untypedInt && value.isConst && value.constInt >= -32768 && value.constInt <= 32767)
        value = coerce(value, types().elementary(TK::Int), e.loc, "current result");
    return settle(value);
}

namespace {
// The first assignment to `name` (upper case) in the text of `list`, in IF
// branches too (where an IL jump assigns a label's temporary), or null.
const ast::Stmt* firstAssignment(const ast::StmtList& list, const std::string& name) {
    for (const auto& s : list) {
        if (s->kind == ast::StmtKind::Assign && s->target && s->target->kind == ast::ExprKind::Name && upper(s->target->name) == name)
            return s.get();
        for (const ast::StmtList& b : s->blocks)
            if (const ast::Stmt* found = firstAssignment(b, name)) return found;
        if (s->elseBlock)
            if (const ast::Stmt* found = firstAssignment(*s->elseBlock, name)) return found;
    }
    return nullptr;
}
}  // namespace

bool Checker::typeInferredTempAhead(VarSym* v) {
    if (!pou_ || !pou_->ast || typingAhead_) return false;
    const ast::Stmt* first = firstAssignment(pou_->ast->body, upper(v->name));
    if (!first) return false;
    // Checked here only for its type: its messages come where it stands.
    typingAhead_ = true;
    const size_t before = log_.messages().size();
    Checked value = inferredValue(*first->expr);
    log_.dropFrom(before);
    typingAhead_ = false;
    if (!value.ok) return false;
    fixInferredTemp(v, value.type);
    return true;
}

exec::Stmt* Checker::checkAssign(const ast::Stmt& s) {
    VarSym* temp = s.kind == ast::StmtKind::Assign ? inferredTemp(*s.target) : nullptr;
    if (temp && !temp->inferredPending) {
        // A value that does not fit the type an earlier path gave it (a label
        // reached with a BOOL and an INT): one message here, none at its reads.
        const size_t before = log_.messages().size();
        Checked target = checkExpr(*s.target);
        Checked value = checkExpr(*s.expr);
        if (!target.ok || !value.ok) return nullptr;
        exec::Stmt* st = assignChecked(std::move(target), std::move(value), s.loc);
        if (log_.messages().size() != before && !st) temp->inferredConflict = true;
        return st;
    }
    if (temp) {
            Checked value = inferredValue(*s.expr);
            if (!value.ok) return nullptr;
            fixInferredTemp(temp, value.type);
            Checked target = checkExpr(*s.target);
            return target.ok ? assignChecked(std::move(target), std::move(value), s.loc) : nullptr;
        }
    if (pou_ && pou_->result) {
        // F.x := ... and F[i] := ... assign (part of) the function result too.
        const ast::Expr* root = s.target.get();
        while (root && (root->kind == ast::ExprKind::Member || root->kind == ast::ExprKind::Index) && !root->kids.empty()) root = root->kids[0].get();
        if (root && root->kind == ast::ExprKind::Name && stdlib::equalsIgnoreCase(root->name, pou_->result->name)) assignedResult_ = true;
    }
    Checked target = checkExpr(*s.target);
    Checked value = checkExprExpecting(*s.expr, target.ok ? target.type : nullptr);
    if (!target.ok || !value.ok) return nullptr;
    if (s.kind == ast::StmtKind::SetAssign || s.kind == ast::StmtKind::ResetAssign) {
        if (target.type->kind != TK::Bool || value.type->kind != TK::Bool) {
            error(diag::E0202, s.loc, fmt::format("{} needs BOOL operands", s.kind == ast::StmtKind::SetAssign ? "S=" : "R="));
            return nullptr;
        }
        exec::Stmt* set = assignChecked(target, constInt(s.kind == ast::StmtKind::SetAssign, types().elementary(TK::Bool), s.loc), s.loc);
        if (!set) return nullptr;
        return pool().make<exec::CondStmt>(value.node, set);
    }
    if (s.kind == ast::StmtKind::RefAssign || s.kind == ast::StmtKind::TryAssign) return checkRefAssign(s);
    // A call inside that was aborted (watchdog / STOP) stops the activation
    // at the next tick (decision 0267).
    return assignChecked(std::move(target), std::move(value), s.loc);
}

exec::Stmt* Checker::checkFor(const ast::Stmt& s) {
    ast::Expr varExpr;
    varExpr.kind = ast::ExprKind::Name;
    varExpr.name = s.name;
    varExpr.loc = s.nameLoc.line ? s.nameLoc : s.loc;
    Checked var = checkExpr(s.target ? *s.target : varExpr);  // `FOR a[1] := ...`: a place (TwinCAT)
    Checked from = checkExpr(*s.from);
    Checked to = checkExpr(*s.to);
    Checked by;
    if (s.by) by = checkExpr(*s.by);
    if (!var.ok || !from.ok || !to.ok || (s.by && !by.ok)) return nullptr;
    if (!(isInteger(var.type->kind) || isBitString(var.type->kind)) || !var.isPlace) {
        error(diag::E0502, s.loc, fmt::format("the FOR control variable '{}' must be an integer variable, not {}", s.name, typeName(var.type)));
        return nullptr;
    }
    if (var.readOnly) {
        error(diag::E0502, s.loc, fmt::format("cannot use '{}' as FOR control variable: {}", s.name, var.readOnlyWhy));
        return nullptr;
    }
    from = coerce(from, var.type, s.from->loc, "FOR start");
    to = coerce(to, var.type, s.to->loc, "FOR end");
    // `FOR i := n TO 1 BY -1` on an unsigned i (TwinCAT accepts it): the step
    // wraps to the variable's type, so adding it counts down, and the loop
    // runs while i >= end (decision 0326).
    bool descending = false;
    const bool unsignedVar = !isSignedInt(integerView(var.type->kind));
    if (s.by && by.isConst && by.constInt < 0 && unsignedVar && (by.untypedInt || isSignedInt(integerView(by.type->kind)))) {
        if (!lenient(diag::W0001, s.by->loc,
                     fmt::format("FOR step {} on the unsigned control variable '{}' ({}): it counts down", by.constInt, s.name, typeName(var.type))))
            return nullptr;
        by = constInt(by.constInt, var.type, s.by->loc);
        descending = true;
    } else if (s.by) {
        by = coerce(by, var.type, s.by->loc, "FOR step");
    }
    if (!from.ok || !to.ok || (s.by && !by.ok)) return nullptr;
    ++loopDepth_;
    exec::Block* body = checkBlock(s.body);
    --loopDepth_;
    auto fill = [&](auto* n) {
        n->var = var.node;
        n->from = from.node;
        n->to = to.node;
        n->by = s.by ? by.node : nullptr;
        n->descending = descending;
        n->body = body;
        return n;
    };
    switch (repOf(var.type)) {
        case Rep::I8: return fill(pool().make<exec::ForStmt<int8_t>>());
        case Rep::I16: return fill(pool().make<exec::ForStmt<int16_t>>());
        case Rep::I32: return fill(pool().make<exec::ForStmt<int32_t>>());
        case Rep::I64: return fill(pool().make<exec::ForStmt<int64_t>>());
        case Rep::U8: return fill(pool().make<exec::ForStmt<uint8_t>>());
        case Rep::U16: return fill(pool().make<exec::ForStmt<uint16_t>>());
        case Rep::U32: return fill(pool().make<exec::ForStmt<uint32_t>>());
        default: return fill(pool().make<exec::ForStmt<uint64_t>>());
    }
}

exec::Stmt* Checker::checkCase(const ast::Stmt& s) {
    Checked sel = checkExpr(*s.expr);
    if (!sel.ok) return nullptr;
    sel = settle(sel);
    const Type* st = sel.type;
    // CHAR and STRING selectors: SIMATIC AX (decision 0394, checker_case_text.cpp).
    const bool textual = isCharType(st->kind) || isStringType(st->kind);
    if (!(isInteger(st->kind) || isBitString(st->kind) || st->kind == TK::Enum || textual)) {
        error(diag::E0503, s.expr->loc, fmt::format("the CASE selector must be an integer or an enumeration, not {}", typeName(st)));
        return nullptr;
    }
    exec::Expr* textKey = caseTextSelector(sel);
    exec::CaseArms arms;
    arms.isUnsigned64 = repOf(st) == Rep::U64;
    std::map<int64_t, int64_t> used;
    for (const auto& br : s.cases) {
        size_t index = arms.blocks.size();
        for (const auto& lab : br.labels) {
            auto one = [&](const ast::Expr* e, int64_t& out) -> bool {
                Checked c = checkExprExpecting(*e, st);
                if (!c.ok) return false;
                if (!c.isConst) {
                    error(diag::E0503, e->loc, "a CASE label must be a constant");
                    return false;
                }
                if (textual) {
                    if (isStringType(st->kind) && e == lab.hi.get()) {
                        error(diag::E0503, e->loc, "a CASE on a string has no ranges of labels");
                        return false;
                    }
                    return caseTextLabel(textKey, st, c, e->loc, out);
                }
                if (st->kind == TK::Enum) {
                    if (c.type != st) {
                        error(diag::E0503, e->loc, fmt::format("CASE label of type {} does not match the selector type {}", typeName(c.type), typeName(st)));
                        return false;
                    }
                } else {
                    // An enumeration value as the label of an integer selector is its
                    // integer (`CASE UDINT_TO_INT(any.TypeClass) OF IBaseLibrary.TypeClass.TYPE_INT:`,
                    // as CODESYS/TwinCAT accept; decision 0302). Not with --strict.
                    if (c.type->kind == TK::Enum && !options_.strict && (isInteger(st->kind) || isBitString(st->kind)))
                        c = constInt(c.constInt, st, e->loc);
                    if (!(c.untypedInt || isInteger(c.type->kind) || isBitString(c.type->kind))) {
                        error(diag::E0503, e->loc, fmt::format("CASE label of type {} does not match the selector type {}", typeName(c.type), typeName(st)));
                        return false;
                    }
                    c = coerce(c, st, e->loc, "CASE label");
                    if (!c.ok) return false;
                }
                out = c.constInt;
                return true;
            };
            int64_t lo = 0, hi = 0;
            if (!one(lab.lo.get(), lo)) continue;
            hi = lo;
            if (lab.hi && !one(lab.hi.get(), hi)) continue;
            if (hi < lo) error(diag::E0503, lab.lo->loc, fmt::format("empty CASE range {}..{}", lo, hi));
            // The labels so far, as disjoint ranges by their start: only the
            // range starting last at or before `hi` can overlap (O(log n) per
            // label; a linear scan made 200 000 arms take 19 s).
            auto after = used.upper_bound(hi);
            if (after != used.begin() && std::prev(after)->second >= lo)
                error(diag::E0503, lab.lo->loc, fmt::format("CASE label {} is already used", lo == hi ? std::to_string(lo) : fmt::format("{}..{}", lo, hi)));
            else if (lo <= hi)
                used.emplace(lo, hi);
            arms.entries.push_back({lo, hi, index});
        }
        arms.blocks.push_back(checkBlock(br.body));
    }
    if (s.elseBlock) arms.elseBlock = checkBlock(*s.elseBlock);
    return makeCaseNode(pool(), textKey ? textKey : sel.node, std::move(arms));
}

exec::Stmt* Checker::checkStmt(const ast::Stmt& s) {
    switch (s.kind) {
        case ast::StmtKind::Assign:
        case ast::StmtKind::SetAssign:
        case ast::StmtKind::ResetAssign:
        case ast::StmtKind::RefAssign:
        case ast::StmtKind::TryAssign:
            return checkAssign(s);
        case ast::StmtKind::Call: {
            if (!s.expr || s.expr->kind != ast::ExprKind::Call) {
                error(diag::E0206, s.loc, "this expression is not a statement");
                return nullptr;
            }
            const ast::Expr& callee = *s.expr->kids[0];
            // A function-block instance called as a statement?
            bool maybeFb = callee.kind != ast::ExprKind::Name || lookupVar(upper(callee.name)) != nullptr;
            // Lib.F(...) / NS.F(...) as a statement: a function of a namespace or library, not an instance.
            if (callee.kind == ast::ExprKind::Member && isNamespace(*callee.kids[0]) && !lookupVar(upper(chainRoot(*callee.kids[0]).name)) &&
                !lookupVar(upper(callee.name)))
                maybeFb = false;
            if (callee.kind == ast::ExprKind::Name) {
                // CODESYS: a PROGRAM called from another POU runs its (single) instance.
                if (findProgram(upper(callee.name))) maybeFb = true;
            }
            if (callee.kind == ast::ExprKind::Name && pou_ && pou_->result && stdlib::equalsIgnoreCase(callee.name, pou_->result->name)) maybeFb = false;
            if (isSuiteBuiltinCall(callee)) maybeFb = false;  // THIS^.AssertTrue(...) in a suite (decision 0145)
            if (maybeFb) {
                bool isMethod = false;
                const bool qualifiedGlobal = callee.kind == ast::ExprKind::Member && isNamespace(*callee.kids[0]) &&
                                             !lookupVar(upper(chainRoot(*callee.kids[0]).name));  // GVL.fbInstance(...)
                if (callee.kind == ast::ExprKind::Member && !qualifiedGlobal) {
                    // inst.Method(...) vs. structVar.fbMember(...)
                    Checked base = checkMethodBase(*callee.kids[0]);
                    PouInfo* method = nullptr;
                    if (base.ok && (base.type->kind == TK::FunctionBlock || base.type->kind == TK::Interface) && base.type->pou)
                        method = findMethod(base.type->pou, upper(callee.name));
                    if (!base.ok) return nullptr;
                    isMethod = method != nullptr || methodOverloads_.count(upper(callee.name)) != 0 ||  // overloaded (decision 0362)
                               isImplicitFbInit(base.type, callee.name);                                        // decision 0457
                    if (method && method->ast->isAction && !s.expr->args.empty()) return callActionWithArguments(*s.expr, base.type->pou);
                }
                if (!isMethod) {
                    Checked inst = checkExpr(callee);
                    if (!inst.ok) return nullptr;
                    if (inst.type->kind == TK::FunctionBlock)
                        return usesFbEnEno(inst, *s.expr) ? callFunctionBlockEnEno(inst, *s.expr) : callFunctionBlock(inst, *s.expr);
                }
            }
            Checked c = checkCall(*s.expr, true);
            if (!c.ok) return nullptr;
            auto rep = isRealRep(c.type) ? exec::EvalStmt::Rep::Real
                       : isIntRep(c.type) ? exec::EvalStmt::Rep::Int
                       : isAggregate(c.type) ? exec::EvalStmt::Rep::Addr : exec::EvalStmt::Rep::Int;
            return pool().make<exec::EvalStmt>(c.node, rep);
        }
        case ast::StmtKind::If: {
            std::vector<exec::Expr*> conds;
            std::vector<exec::Block*> blocks;
            for (size_t k = 0; k < s.conds.size(); ++k) {
                Checked c = checkCondition(*s.conds[k], "an IF condition");
                exec::Block* b = checkBlock(s.blocks[k]);
                if (!c.ok) continue;
                conds.push_back(c.node);
                blocks.push_back(b);
            }
            exec::Stmt* chain = s.elseBlock ? exec::ElseStmts::of(pool(), checkBlock(*s.elseBlock)) : nullptr;  // decision 0378
            if (conds.empty()) return chain;
            // IF/ELSIF/ELSE as a chain of one-condition links, built from the end.
            for (size_t k = conds.size(); k-- > 0;) {
                if (exec::Stmt* fused = fuseIf(pool(), conds[k], blocks[k], chain)) chain = fused;
                else chain = pool().make<exec::If1Stmt>(conds[k], blocks[k], chain);
            }
            return chain;
        }
        case ast::StmtKind::Case: return checkCase(s);
        case ast::StmtKind::For: return checkFor(s);
        case ast::StmtKind::While: {
            Checked c = checkCondition(*s.expr, "a WHILE condition");
            ++loopDepth_;
            exec::Block* b = checkBlock(s.body);
            --loopDepth_;
            if (!c.ok) return nullptr;
            if (exec::Stmt* fused = fuseWhile(pool(), c.node, b)) return fused;
            auto* n = pool().make<exec::WhileStmt>();
            n->cond = c.node;
            n->body = b;
            return n;
        }
        case ast::StmtKind::Repeat: {
            ++loopDepth_;
            exec::Block* b = checkBlock(s.body);
            --loopDepth_;
            Checked c = checkCondition(*s.expr, "an UNTIL condition");
            if (!c.ok) return nullptr;
            auto* n = pool().make<exec::RepeatStmt>();
            n->cond = c.node;
            n->body = b;
            return n;
        }
        case ast::StmtKind::Exit:
        case ast::StmtKind::Continue:
            if (loopDepth_ == 0) {
                error(diag::E0501, s.loc, fmt::format("{} outside a loop", s.kind == ast::StmtKind::Exit ? "EXIT" : "CONTINUE"));
                return nullptr;
            }
            return pool().make<exec::FlowStmt>(s.kind == ast::StmtKind::Exit ? exec::Flow::Exit : exec::Flow::Continue);
        case ast::StmtKind::Return: return s.expr ? checkConditionalReturn(s) : pool().make<exec::FlowStmt>(exec::Flow::Return);
        case ast::StmtKind::Jmp: {
            std::string key = upper(s.name);
            pendingJumps_.push_back({s.nameLoc.line ? s.nameLoc : s.loc, s.name});
            return pool().make<exec::JumpStmt>(labelId(key));
        }
        case ast::StmtKind::Label:
        case ast::StmtKind::Empty:
            return nullptr;
    }
    return nullptr;
}

void Checker::checkBody(PouInfo* pou) {
    if (pou->bodyChecked || (!pou->ast->hasBody && pou->ast->body.empty())) {
        if (!pou->code->body) pou->code->body = pool().make<exec::Block>();
        pou->bodyChecked = true;
        return;
    }
    pou->bodyChecked = true;
    NameScopeGuard scope(*this, pou->ast->nameSpace, pou->ast->loc.file);
    pou_ = pou;
    model_.names.push_back(pou->code->name);
    currentPouName_ = &model_.names.back();
    frameTop_ = pou->frameSize;
    loopDepth_ = 0;
    labels_.clear();
    definedLabels_.clear();
    pendingJumps_.clear();
    assignedResult_ = false;
    const size_t messagesBefore = log_.messages().size();
    const uint64_t callsBefore = userCallsMade_;
    PouInfo* savedCaller = inlineCaller_;
    inlineCaller_ = pou;  // calls in the body proper (not in initialisers) run in this frame
    pou->code->body = checkBlock(pou->ast->body);
    inlineCaller_ = savedCaller;
    if (!pou->frameAddressInits.empty()) {
        // `p : POINTER TO INT := ADR(local)` in a FUNCTION or METHOD: the address
        // is one of this call's frame, so the assignment runs first in every call.
        auto* block = static_cast<exec::Block*>(pou->code->body);
        std::vector<exec::Stmt*> inits;
        for (const RuntimeInit& init : pou->frameAddressInits)
            if (exec::Stmt* st = addressInitStmt(init)) inits.push_back(st);
        block->stmts.insert(block->stmts.begin(), inits.begin(), inits.end());
        for (auto& label : block->labels) label.second += inits.size();
    }
    // The body is final now: a short one runs inline in every call (decision 0266).
    pou->code->inlineBody = exec::Body(pou->code->body);
    pou->code->hasInlineBody = !pou->code->inlineBody.block;
    for (const auto& [loc, name] : pendingJumps_)
        if (!definedLabels_.count(upper(name))) error(diag::E0504, loc, fmt::format("JMP to undefined label '{}'", name));
    if (pou->kind == ast::PouKind::Function && pou->result && !assignedResult_ && !libraryFiles_.count(pou->ast->loc.file))
        log_.warning(diag::W0004, pou->ast->loc, fmt::format("function '{}' never assigns its result", pou->name));
    if (!libraryFiles_.count(pou->ast->loc.file)) warnReadBeforeWrite(*pou, log_);
    uint32_t size = alignFrameTop(frameTop_, 16);
    pou->code->frameSize = size;
    pou->code->initSize = size;
    pou->bodyName = currentPouName_;
    noteInlinable(pou, messagesBefore, callsBefore);
    pou->code->frameInit.resize(exec::frameImageSize(size), 0);
    model_.maxFrameSize = std::max(model_.maxFrameSize, size);
    pou_ = nullptr;
    currentPouName_ = nullptr;
}

void Checker::checkBodies() {
    for (size_t i = 0; i < pouOrder_.size(); ++i) {  // by index: see Checker::run
        PouInfo* p = pouOrder_[i];
        if (p->kind == ast::PouKind::Interface) continue;
        checkBody(p);
        for (auto& [name, m] : p->methods) checkBody(m);
    }
}

}  // namespace strun::sema
