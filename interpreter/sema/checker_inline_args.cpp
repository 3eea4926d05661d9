// Arguments substituted into an inlined body (decision 0403). An inlined
// call's body is checked once per call site (decision 0317), so a parameter
// can be resolved, in that check, as what the call passes it:
//   - a constant: the parameter reads as that constant (folded into the
//     body's expressions like a CONSTANT), and nothing is stored per call;
//   - a scalar variable of the caller (instance or frame), copied bit for bit
//     (ArgBind::CopySelf* / CopyFrame*): the parameter reads that variable,
//     when nothing can change it between the binding and the body's reads.
// A substituted parameter is no place: a body that writes it, takes its
// address or passes it to a VAR_IN_OUT fails its (silent) check, and the
// call is then inlined without substitution.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cstring>
#include <string_view>

#include <fmt/format.h>

#include "interpreter/sema/checker.h"
#include "interpreter/sema/node_factory.h"

namespace strun::sema {

namespace {

using How = exec::ArgBind::How;

bool isConstBind(How h) { return h == How::Const1 || h == How::Const2 || h == How::Const4 || h == How::Const8; }
bool isCopySelf(How h) { return h == How::CopySelf1 || h == How::CopySelf2 || h == How::CopySelf4 || h == How::CopySelf8; }
bool isCopyFrame(How h) { return h == How::CopyFrame1 || h == How::CopyFrame2 || h == How::CopyFrame4 || h == How::CopyFrame8; }

// Standard functions that compute a value from their inputs and write
// nothing (no address, no VAR_IN_OUT, no state); and the conversions.
constexpr std::string_view kPureFunctions[] = {
    "ABS", "SQRT", "LN",  "LOG", "EXP", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "ATAN2", "EXPT",
    "ADD", "SUB",  "MUL", "DIV", "MOD", "MOVE", "AND", "OR", "XOR", "NOT", "SHL", "SHR", "ROL", "ROR",
    "SEL", "MUX",  "MAX", "MIN", "LIMIT", "GT", "GE", "EQ", "LE", "LT", "NE", "TRUNC"};

bool isPureFunctionName(const std::string& key) {
    for (std::string_view n : kPureFunctions)
        if (key == n) return true;
    return key.find("_TO_") != std::string::npos || key.starts_with("TO_");  // INT_TO_REAL, TO_DINT
}

bool scalarType(const Type* t) { return t && (isIntRep(t) || isRealRep(t)); }

constexpr int kMaxScanDepth = 32;  // nesting of expressions scanned; deeper counts as "may write"
}  // namespace

// An assignment target that is the function's (or method's) own frame
// variable: a scalar, a bit of one, or an element of an array of scalars.
// Nothing reached through a reference, pointer or VAR_IN_OUT.
bool Checker::ownFrameTarget(const PouInfo& fn, const ast::Expr& t) {
    const ast::Expr* root = &t;
    bool element = false;
    if (t.kind == ast::ExprKind::Index && !t.kids.empty()) {
        for (size_t k = 1; k < t.kids.size(); ++k)
            if (!t.kids[k] || !readsOnly(*t.kids[k], false, 0)) return false;
        root = t.kids[0].get();
        element = true;
    } else if (t.kind == ast::ExprKind::Member && !t.kids.empty()) {
        // A bit: x.3
        if (t.name.empty() || !std::isdigit(static_cast<unsigned char>(t.name[0]))) return false;
        root = t.kids[0].get();
    }
    if (!root || root->kind != ast::ExprKind::Name) return false;
    auto it = fn.vars.find(upper(root->name));
    if (it == fn.vars.end()) return false;
    const VarSym* v = it->second;
    if (v->owner != &fn || v->storage != Storage::Frame || v->byRef || v->bit >= 0 || !v->type) return false;
    if (element) return v->type->kind == TK::Array && !v->type->flexible && scalarType(v->type->elem);
    return scalarType(v->type);
}

// Statements that write nothing but the POU's own frame variables.
bool Checker::writesOnlyOwnFrame(const PouInfo& fn, const ast::StmtList& list) {
    for (const ast::StmtPtr& sp : list) {
        if (!sp) continue;
        const ast::Stmt& s = *sp;
        switch (s.kind) {
            case ast::StmtKind::Assign:
            case ast::StmtKind::SetAssign:
            case ast::StmtKind::ResetAssign:
                if (!s.target || !s.expr || !ownFrameTarget(fn, *s.target) || !readsOnly(*s.expr, false, 0)) return false;
                break;
            case ast::StmtKind::If:
                for (const ast::ExprPtr& c : s.conds)
                    if (!c || !readsOnly(*c, false, 0)) return false;
                for (const ast::StmtList& b : s.blocks)
                    if (!writesOnlyOwnFrame(fn, b)) return false;
                if (s.elseBlock && !writesOnlyOwnFrame(fn, *s.elseBlock)) return false;
                break;
            case ast::StmtKind::Case:
                if (!s.expr || !readsOnly(*s.expr, false, 0)) return false;
                for (const ast::CaseBranch& b : s.cases)
                    if (!writesOnlyOwnFrame(fn, b.body)) return false;
                if (s.elseBlock && !writesOnlyOwnFrame(fn, *s.elseBlock)) return false;
                break;
            case ast::StmtKind::For: {
                if (s.target) return false;
                ast::Expr var;
                var.kind = ast::ExprKind::Name;
                var.name = s.name;
                if (!ownFrameTarget(fn, var)) return false;
                for (const ast::ExprPtr* e : {&s.from, &s.to, &s.by})
                    if (*e && !readsOnly(**e, false, 0)) return false;
                if (!writesOnlyOwnFrame(fn, s.body)) return false;
                break;
            }
            case ast::StmtKind::While:
            case ast::StmtKind::Repeat:
                if (!s.expr || !readsOnly(*s.expr, false, 0) || !writesOnlyOwnFrame(fn, s.body)) return false;
                break;
            case ast::StmtKind::Exit:
            case ast::StmtKind::Continue:
            case ast::StmtKind::Return:
            case ast::StmtKind::Empty:
                break;
            default:
                return false;  // a call statement, ?=, REF=, JMP, a label
        }
    }
    return true;
}

// Whether `fn`, an inlinable FUNCTION (a leaf: it calls no POU), writes
// nothing but its own frame: then it cannot change a variable of its caller.
bool Checker::touchesOnlyOwnFrame(const PouInfo& fn) {
    auto found = touchesOnlyOwnFrame_.find(&fn);
    if (found != touchesOnlyOwnFrame_.end()) return found->second;
    bool only = false;
    if (fn.inlinable && fn.ast && fn.kind == ast::PouKind::Function) {
        PouInfo* saved = pou_;
        pou_ = const_cast<PouInfo*>(&fn);  // names resolve in the callee's scope
        only = writesOnlyOwnFrame(fn, fn.ast->body);
        pou_ = saved;
    }
    touchesOnlyOwnFrame_[&fn] = only;
    return only;
}

// Whether evaluating `e` can write nothing (reads, operators, pure standard
// functions). A call's argument (`callerArgument`) may also call a FUNCTION
// that touches only its own frame; its names must be variables or
// enumeration values (a bare name may be a property, whose getter is a call).
// Conservative: anything not recognised may write.
bool Checker::readsOnly(const ast::Expr& e, bool callerArgument, int depth) {
    if (depth > kMaxScanDepth) return false;
    auto kidsRead = [&](size_t from) {
        for (size_t k = from; k < e.kids.size(); ++k)
            if (!e.kids[k] || !readsOnly(*e.kids[k], callerArgument, depth + 1)) return false;
        return true;
    };
    switch (e.kind) {
        case ast::ExprKind::Literal: return true;
        case ast::ExprKind::Name: {
            if (!callerArgument) return true;  // a leaf's names are variables, enumeration values or constants
            const std::string key = upper(e.name);
            const Type* enumType = nullptr;
            bool ambiguous = false;  // a value several enumerations share is still a value
            return lookupVar(key) != nullptr || lookupEnumValue(key, &enumType, ambiguous) != nullptr || ambiguous;
        }
        case ast::ExprKind::Member:
            // In a leaf a member is a field, a bit or a qualified name, never a
            // property (its getter would be a call); in a caller it may be one.
            return !callerArgument && kidsRead(0);
        case ast::ExprKind::Index:
        case ast::ExprKind::Deref:
        case ast::ExprKind::Unary:
        case ast::ExprKind::Binary: return kidsRead(0);
        case ast::ExprKind::Call: {
            if (e.kids.empty() || !e.kids[0] || e.kids[0]->kind != ast::ExprKind::Name) return false;  // a method, through a pointer
            for (const ast::Arg& a : e.args)
                if (a.output || (a.value && !readsOnly(*a.value, callerArgument, depth + 1))) return false;
            const std::string key = upper(e.kids[0]->name);
            if (const VarSym* v = lookupVar(key); v && v->type && !scalarType(v->type)) return false;  // an instance, a pointer
            if (overloads_.count(key)) return false;
            if (pou_) {
                PouInfo* owner = pou_->owner ? pou_->owner : pou_;
                if (owner->kind != ast::PouKind::Function && findMethod(owner, key)) return false;  // a method of the caller's instance
            }
            auto it = pous_.find(scopedKey(key));
            if (it != pous_.end()) {
                const PouInfo* fn = it->second;
                if (!callerArgument || fn->kind != ast::PouKind::Function) return false;
                for (const VarSym* p : fn->params)
                    if (p->section != ast::VarSection::Input || p->byRef) return false;
                return touchesOnlyOwnFrame(*fn);
            }
            return isPureFunctionName(key);
        }
        default: return false;  // THIS, SUPER, an assignment used as a value
    }
}

// The parameters of `site`'s callee that its inlined body reads as their
// arguments. Constants always qualify (the body is checked with them; if it
// writes one, it fails and is checked without). A caller's variable only when
// nothing can change it during the call:
//   - the callee writes only its own frame (touchesOnlyOwnFrame),
//   - no argument of the call can write anything (readsOnly): the variable is
//     then read after the later arguments are evaluated, not before,
//   - the project has one task: no other task can run (and write it) at a
//     statement boundary inside the call, and the live writes (HTTP, Modbus,
//     --set) are applied only when an activation starts, which then happens
//     only between two cycles of this task,
//   - a METHOD's body runs on its instance (self), so only the caller's frame
//     variables are reachable there.
std::vector<Checker::ArgSubstitute> Checker::argumentSubstitutes(const InlineSite& site) {
    std::vector<ArgSubstitute> out;
    if (!site.call || !site.expr) return out;
    const PouInfo* fn = site.callee;
    int copies = -1;  // whether caller variables may be substituted: unknown until the first copy
    for (const exec::ArgBind& b : site.call->binds) {
        const VarSym* param = nullptr;
        for (const VarSym* p : fn->params)
            if (p->section == ast::VarSection::Input && !p->byRef && p->storage == Storage::Frame && p->offset == b.dst) param = p;
        if (!param || !scalarType(param->type)) continue;
        // A parameter named twice (`F(x := 2, x := G())`, W0044) is bound twice: both stay.
        size_t bindsOfParam = 0;
        for (const exec::ArgBind& other : site.call->binds) bindsOfParam += other.dst == b.dst;
        if (bindsOfParam != 1) continue;
        if (isConstBind(b.how)) {
            out.push_back({param, b});
            continue;
        }
        const bool self = isCopySelf(b.how);
        if (!self && !isCopyFrame(b.how)) continue;
        if (self && site.onInstance) continue;
        if (copies < 0) {
            copies = 0;
            if (model_.tasks.size() <= 1 && touchesOnlyOwnFrame(*fn)) {
                PouInfo* saved = pou_;
                pou_ = site.caller;  // the arguments' names resolve in the caller's scope
                copies = 1;
                for (const ast::Arg& a : site.expr->args)
                    if (a.output || (a.value && !readsOnly(*a.value, true, 0))) copies = 0;
                pou_ = saved;
            }
        }
        if (copies == 1) out.push_back({param, b});
    }
    return out;
}

// How an inlined call binds its per-call arguments (`in.binds`, ended by
// How::End) and initialises its area (decision 0404): one 4-byte integer
// argument without the list's dispatch; only the result initialised when
// every other variable of the area is an input bound per call or read as
// its argument (then nothing reads the image's other bytes).
void Checker::chooseInlinedArgs(exec::InlinedCall& in, const PouInfo& fn, const std::vector<ArgSubstitute>& substitutes) {
    const size_t perCall = in.binds.size() - 1;
    if (perCall == 0) in.args = exec::InlinedCall::Args::None;
    else if (perCall == 1 && in.binds[0].how == How::Int4) {
        in.args = exec::InlinedCall::Args::One4;
        in.arg = in.binds[0].value;
        in.argDst = in.binds[0].dst;
    } else if (perCall > 1 && std::all_of(in.binds.begin(), in.binds.end() - 1, [](const exec::ArgBind& b) { return b.how == How::Int4; })) {
        // Decision 0471: several computed DINT/UDINT/DWORD arguments stored
        // without the list's dispatch per argument.
        in.args = exec::InlinedCall::Args::Int4s;
        for (size_t k = 0; k < perCall; ++k) in.ints.push_back({in.binds[k].value, in.binds[k].dst});
        in.ints.push_back({});
    }
    auto boundOrRead = [&](const VarSym* v) {
        for (size_t k = 0; k < perCall; ++k)
            if (in.binds[k].dst == v->offset) return true;
        for (const ArgSubstitute& s : substitutes)
            if (s.param == v) return true;
        return false;
    };
    if (in.resultOffset + sizeof(uint64_t) > in.image.size()) return;
    for (const auto& owned : fn.ownedVars) {
        const VarSym* v = owned.get();
        if (v->storage != Storage::Frame || v == fn.result) continue;
        if (v->section != ast::VarSection::Input || v->byRef || !boundOrRead(v)) return;
    }
    in.resultOnly = true;
    std::memcpy(&in.resultInit, in.image.data() + in.resultOffset, sizeof(uint64_t));
}

// A substituted parameter read in the inlined body: what the call would have
// stored, read as the parameter's type. A constant is folded like a CONSTANT
// (checker_expr.cpp varAccess); neither is a place, so a write or an address
// of it is an error of this (silent) check.
Checked Checker::substitutedArgument(const ArgSubstitute& s, const ast::Loc& loc) {
    const VarSym* v = s.param;
    Checked c;
    c.ok = true;
    c.loc = loc;
    c.type = v->type;
    c.readOnly = true;
    c.readOnlyWhy = fmt::format("'{}' is an input read as its argument", v->name);
    const Rep rep = repOf(v->type);
    if (isConstBind(s.bind.how)) {
        const uint64_t b = s.bind.bits;
        c.isConst = true;
        switch (rep) {
            case Rep::I8: c.constInt = static_cast<int8_t>(b); break;
            case Rep::I16: c.constInt = static_cast<int16_t>(b); break;
            case Rep::I32: c.constInt = static_cast<int32_t>(b); break;
            case Rep::U8: case Rep::Bool: c.constInt = static_cast<uint8_t>(b); break;
            case Rep::U16: c.constInt = static_cast<uint16_t>(b); break;
            case Rep::U32: c.constInt = static_cast<uint32_t>(b); break;
            case Rep::F32: c.constReal = std::bit_cast<float>(static_cast<uint32_t>(b)); break;
            case Rep::F64: c.constReal = std::bit_cast<double>(b); break;
            default: c.constInt = static_cast<int64_t>(b); break;
        }
        exec::Expr* k = isRealRep(v->type) ? static_cast<exec::Expr*>(pool().make<exec::ConstReal>(c.constReal))
                                           : pool().make<exec::ConstInt>(c.constInt);
        k->type = v->type;
        c.node = k;
        return c;
    }
    const bool self = isCopySelf(s.bind.how);
    c.direct = self ? Checked::Direct::Self : Checked::Direct::Frame;
    c.directOffset = s.bind.src;
    c.node = self ? makeByRep<exec::SelfVar>(pool(), rep, s.bind.src) : makeByRep<exec::FrameVar>(pool(), rep, s.bind.src);
    c.node->type = v->type;
    return c;
}

}  // namespace strun::sema
