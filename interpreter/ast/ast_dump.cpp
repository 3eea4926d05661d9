#include "interpreter/ast/ast_dump.h"

#include <fmt/format.h>

namespace strun::ast {

namespace {

const char* opText(Op op) {
    switch (op) {
        case Op::Add: return "+";
        case Op::Sub: return "-";
        case Op::Mul: return "*";
        case Op::Div: return "/";
        case Op::Mod: return "MOD";
        case Op::Pow: return "**";
        case Op::Eq: return "=";
        case Op::Ne: return "<>";
        case Op::Lt: return "<";
        case Op::Le: return "<=";
        case Op::Gt: return ">";
        case Op::Ge: return ">=";
        case Op::And: return "AND";
        case Op::Or: return "OR";
        case Op::Xor: return "XOR";
        case Op::AndThen: return "AND_THEN";
        case Op::OrElse: return "OR_ELSE";
        case Op::Neg: return "neg";
        case Op::Plus: return "plus";
        case Op::Not: return "not";
    }
    return "?";
}

std::string kid(const Expr& e, size_t i) { return i < e.kids.size() && e.kids[i] ? dump(*e.kids[i]) : "<null>"; }
std::string opt(const ExprPtr& e) { return e ? dump(*e) : "<null>"; }

}  // namespace

std::string dump(const Expr& e) {
    switch (e.kind) {
        case ExprKind::Literal: return e.text;
        case ExprKind::Name: return e.name;
        case ExprKind::This: return "THIS";
        case ExprKind::Super: return "SUPER";
        case ExprKind::Assign: return "(:= " + kid(e, 0) + " " + kid(e, 1) + ")";
        case ExprKind::Member: return "(. " + kid(e, 0) + " " + e.name + ")";
        case ExprKind::Deref: return "(^ " + kid(e, 0) + ")";
        case ExprKind::Unary: return std::string("(") + opText(e.op) + " " + kid(e, 0) + ")";
        case ExprKind::Binary: return std::string("(") + opText(e.op) + " " + kid(e, 0) + " " + kid(e, 1) + ")";
        case ExprKind::Index: {
            std::string out = "([] " + kid(e, 0);
            for (size_t i = 1; i < e.kids.size(); ++i) out += fmt::format(" {}", kid(e, i));
            return out + ")";
        }
        case ExprKind::Call: {
            std::string out = "(call " + kid(e, 0);
            for (const Arg& a : e.args) {
                out += " ";
                if (a.negated) out += "NOT ";
                if (!a.name.empty()) out += a.name + (a.output ? "=>" : ":=");
                if (a.value) out += dump(*a.value);
            }
            return out + ")";
        }
    }
    return "?";
}

std::string dump(const StmtList& list) {
    std::string out = "{";
    for (size_t i = 0; i < list.size(); ++i) {
        if (i > 0) out += " ";
        out += list[i] ? dump(*list[i]) : "<null>";
    }
    return out + "}";
}

std::string dump(const Stmt& s) {
    auto assign = [&](const char* op) { return std::string("(") + op + " " + opt(s.target) + " " + opt(s.expr) + ")"; };
    switch (s.kind) {
        case StmtKind::Assign: return assign(":=");
        case StmtKind::SetAssign: return assign("S=");
        case StmtKind::ResetAssign: return assign("R=");
        case StmtKind::TryAssign: return assign("?=");
        case StmtKind::RefAssign: return assign("REF=");
        case StmtKind::Call: return "(call-stmt " + opt(s.expr) + ")";
        case StmtKind::If: {
            std::string out = "(if";
            for (size_t i = 0; i < s.conds.size(); ++i)
                out += fmt::format(" {} {}", opt(s.conds[i]), i < s.blocks.size() ? dump(s.blocks[i]) : "<null>");
            if (s.elseBlock) out += " else " + dump(*s.elseBlock);
            return out + ")";
        }
        case StmtKind::Case: {
            std::string out = "(case " + opt(s.expr);
            for (const CaseBranch& b : s.cases) {
                out += " [";
                for (size_t i = 0; i < b.labels.size(); ++i) {
                    if (i > 0) out += ",";
                    out += opt(b.labels[i].lo);
                    if (b.labels[i].hi) out += ".." + opt(b.labels[i].hi);
                }
                out += ": " + dump(b.body) + "]";
            }
            if (s.elseBlock) out += " else " + dump(*s.elseBlock);
            return out + ")";
        }
        case StmtKind::For:
            return "(for " + s.name + " " + opt(s.from) + " " + opt(s.to) + (s.by ? " " + opt(s.by) : "") + " " +
                   dump(s.body) + ")";
        case StmtKind::While: return "(while " + opt(s.expr) + " " + dump(s.body) + ")";
        case StmtKind::Repeat: return "(repeat " + dump(s.body) + " " + opt(s.expr) + ")";
        case StmtKind::Exit: return "EXIT";
        case StmtKind::Continue: return "CONTINUE";
        case StmtKind::Return: return s.expr ? "(return " + opt(s.expr) + ")" : "RETURN";
        case StmtKind::Jmp: return "(jmp " + s.name + ")";
        case StmtKind::Label: return "(label " + s.name + ")";
        case StmtKind::Empty: return ";";
    }
    return "?";
}

std::string dump(const TypeSpec& t) {
    auto sub = [](const TypeSpecPtr& p) { return p ? dump(*p) : std::string("<null>"); };
    switch (t.kind) {
        case TypeSpecKind::Named: return t.name;
        case TypeSpecKind::String:
            return std::string(t.wide ? "WSTRING" : "STRING") + (t.length ? "[" + dump(*t.length) + "]" : "");
        case TypeSpecKind::Array: {
            std::string out = "ARRAY[";
            for (size_t i = 0; i < t.dims.size(); ++i) {
                if (i > 0) out += ",";
                out += t.dims[i].star ? "*" : opt(t.dims[i].lo) + ".." + opt(t.dims[i].hi);
            }
            return out + "] OF " + sub(t.elem);
        }
        case TypeSpecKind::Pointer: return (t.refTo ? "REF_TO " : "POINTER TO ") + sub(t.elem);
        case TypeSpecKind::Reference: return "REFERENCE TO " + sub(t.elem);
        case TypeSpecKind::Subrange: return sub(t.elem) + "(" + opt(t.lo) + ".." + opt(t.hi) + ")";
        case TypeSpecKind::Enum: {
            std::string out = "(";
            for (size_t i = 0; i < t.enumValues.size(); ++i) {
                if (i > 0) out += ",";
                out += t.enumValues[i].name;
                if (t.enumValues[i].value) out += ":=" + dump(*t.enumValues[i].value);
            }
            return out + ")" + (t.elem ? " " + dump(*t.elem) : "");
        }
        case TypeSpecKind::Struct: {
            std::string out = "STRUCT(";
            for (size_t i = 0; i < t.fields.size(); ++i) {
                const VarDecl& f = t.fields[i];
                if (i > 0) out += ";";
                for (size_t n = 0; n < f.names.size(); ++n) out += (n > 0 ? "," : "") + f.names[n];
                out += fmt::format(":{}", sub(f.type));
                if (f.init) out += ":=" + dump(*f.init);
            }
            return out + ")";
        }
    }
    return "?";
}

std::string dump(const Init& i) {
    switch (i.kind) {
        case InitKind::Expr: return opt(i.expr);
        case InitKind::Array: {
            std::string out = "[";
            for (size_t k = 0; k < i.items.size(); ++k) {
                if (k > 0) out += ",";
                const ArrayInitItem& item = i.items[k];
                if (item.repeat) out += dump(*item.repeat) + "(" + (item.value ? dump(*item.value) : "") + ")";
                else out += item.value ? dump(*item.value) : "<null>";
            }
            return out + "]";
        }
        case InitKind::Struct: {
            std::string out = "(";
            for (size_t k = 0; k < i.fields.size(); ++k) {
                if (k > 0) out += ",";
                out += i.fields[k].name + ":=" + (i.fields[k].value ? dump(*i.fields[k].value) : "<null>");
            }
            return out + ")";
        }
    }
    return "?";
}

}  // namespace strun::ast
