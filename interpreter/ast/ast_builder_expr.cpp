// AstBuilder: expressions, literals and call arguments.
#include "interpreter/ast/ast_builder.h"

#include <fmt/format.h>

#include "grammar/STLexer.h"

namespace strun::ast {

using L = strun_grammar::STLexer;

namespace {

ExprPtr makeExpr(ExprKind kind, const Loc& at) {
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    e->loc = at;
    return e;
}

Op binaryOp(size_t tokenType) {
    switch (tokenType) {
        case L::PLUS: return Op::Add;
        case L::MINUS: return Op::Sub;
        case L::STAR: return Op::Mul;
        case L::SLASH: return Op::Div;
        case L::MOD: return Op::Mod;
        case L::POW: return Op::Pow;
        case L::EQ: return Op::Eq;
        case L::NE: return Op::Ne;
        case L::LT_OP: return Op::Lt;
        case L::LE: return Op::Le;
        case L::GT_OP: return Op::Gt;
        case L::GE: return Op::Ge;
        case L::AND: case L::AMP: return Op::And;
        case L::AND_THEN: return Op::AndThen;
        case L::OR: return Op::Or;
        case L::OR_ELSE: return Op::OrElse;
        case L::XOR: return Op::Xor;
        default: return Op::Add;
    }
}

// Binding strength of a binary operator: higher binds tighter (IEC 61131-3
// table "Operators of the ST language"). All are left-associative.
int precedence(size_t tokenType) {
    switch (tokenType) {
        case L::POW: return 7;
        case L::STAR: case L::SLASH: case L::MOD: return 6;
        case L::PLUS: case L::MINUS: return 5;
        case L::LT_OP: case L::GT_OP: case L::LE: case L::GE: return 4;
        case L::EQ: case L::NE: return 3;
        case L::AND: case L::AMP: case L::AND_THEN: return 2;
        case L::XOR: return 1;
        default: return 0;  // OR, OR_ELSE
    }
}

// Operator-precedence parsing of `operand op operand op ...` with an
// operand stack: `operand(i)` makes operand i, `combine(lhs, op, rhs)` one
// binary node. Runs in a loop, so a chain of any length costs no stack.
template <typename Value, typename Operand, typename Combine>
Value climb(size_t operandCount, const std::vector<antlr4::Token*>& ops, Operand&& operand, Combine&& combine) {
    std::vector<Value> values;
    std::vector<size_t> pending;  // indexes into ops
    auto reduce = [&] {
        Value rhs = std::move(values.back());
        values.pop_back();
        Value lhs = std::move(values.back());
        values.pop_back();
        values.push_back(combine(std::move(lhs), ops[pending.back()], std::move(rhs)));
        pending.pop_back();
    };
    values.push_back(operand(0));
    for (size_t i = 0; i < ops.size() && i + 1 < operandCount; ++i) {
        const int p = precedence(ops[i]->getType());
        while (!pending.empty() && precedence(ops[pending.back()]->getType()) >= p) reduce();
        pending.push_back(i);
        values.push_back(operand(i + 1));
    }
    while (!pending.empty()) reduce();
    return std::move(values.back());
}

// Counts the depth of the expression being built; see kMaxExpressionDepth.
class DepthScope {
public:
    explicit DepthScope(int& depth) : depth_(depth) { ++depth_; }
    ~DepthScope() { --depth_; }
    DepthScope(const DepthScope&) = delete;
    DepthScope& operator=(const DepthScope&) = delete;

private:
    int& depth_;
};

}  // namespace

ExprPtr AstBuilder::placeholder(const Loc& at) {
    auto e = makeExpr(ExprKind::Literal, at);
    e->lit = LitKind::Integer;
    e->text.push_back('0');  // (assigning "0" trips GCC 12 -Wrestrict bug 105329)
    return e;
}

// Past kMaxExpressionDepth: one error per file, and a placeholder.
ExprPtr AstBuilder::tooComplex(const Loc& at) {
    if (!depthReported_)
        error(diag::E0007, at, fmt::format("expression too complex: more than {} nested operations", kMaxExpressionDepth));
    depthReported_ = true;
    return placeholder(at);
}

ExprPtr AstBuilder::expr(P::ExpressionContext* c) {
    if (c == nullptr) return placeholder(Loc{file_, 0, 0});
    const Loc at = loc(c);
    DepthScope scope(exprDepth_);
    const std::vector<P::UnaryExprContext*>& operands = c->operands;
    if (operands.empty()) return placeholder(at);
    // The depth of the tree the chain makes, before making it: a chain
    // `1 + 1 + ...` 100 000 long must be refused, not built and then
    // destroyed recursively.
    // (A lone operand, the most common expression, needs no count.)
    const int depth = c->ops.empty() ? 0
                                     : climb<int>(operands.size(), c->ops, [](size_t) { return 0; },
                                                  [](int lhs, antlr4::Token*, int rhs) { return 1 + std::max(lhs, rhs); });
    if (exprDepth_ + depth > kMaxExpressionDepth) return tooComplex(at);
    if (operands.size() == 1) return unary(operands[0]);
    struct Operand {
        ExprPtr expr;
        Loc start;  // where its text starts: a binary node is located at its left operand's
    };
    Operand built = climb<Operand>(
        operands.size(), c->ops, [&](size_t i) { return Operand{unary(operands[i]), loc(operands[i])}; },
        [&](Operand lhs, antlr4::Token* op, Operand rhs) {
            auto e = makeExpr(ExprKind::Binary, lhs.start);
            e->op = binaryOp(op->getType());
            e->kids.push_back(std::move(lhs.expr));
            e->kids.push_back(std::move(rhs.expr));
            return Operand{std::move(e), lhs.start};
        });
    return std::move(built.expr);
}

ExprPtr AstBuilder::unary(P::UnaryExprContext* c) {
    if (c == nullptr) return placeholder(Loc{file_, 0, 0});
    if (auto* p = exactly<P::PostfixExpressionContext>(c)) return postfix(p);
    if (auto* l = exactly<P::LiteralExpressionContext>(c)) return literal(l->value);
    const Loc at = loc(c);
    if (auto* p = exactly<P::PointerTypeExpressionContext>(c)) {
        auto e = makeExpr(ExprKind::Name, at);
        if (p->pointee) e->name = text(p->pointee);
        e->pointerTo = true;
        return e;
    }
    if (auto* u = exactly<P::UnaryExpressionContext>(c)) {
        DepthScope scope(exprDepth_);
        if (exprDepth_ > kMaxExpressionDepth) return tooComplex(at);
        auto e = makeExpr(ExprKind::Unary, at);
        const size_t type = u->op ? u->op->getType() : static_cast<size_t>(L::MINUS);
        e->op = type == L::NOT ? Op::Not : type == L::PLUS ? Op::Plus : Op::Neg;
        e->kids.push_back(unary(u->operand));
        return e;
    }
    return placeholder(at);
}

const antlr4::Token* AstBuilder::bareName(P::ExpressionContext* c) {
    if (c == nullptr || !c->ops.empty() || c->operands.size() != 1) return nullptr;
    return bareName(c->operands[0]);
}

const antlr4::Token* AstBuilder::bareName(P::UnaryExprContext* c) {
    auto* p = exactly<P::PostfixExpressionContext>(c);
    if (p == nullptr || p->name == nullptr || !p->suffixes.empty()) return nullptr;
    return p->name;
}

// A primary and the postfix operators after it (an iteration, not a
// recursion: a long chain `a.b.c[1]^.d()` costs no parser stack).
ExprPtr AstBuilder::postfix(P::PostfixExpressionContext* c) {
    const Loc at = loc(c);
    if (c == nullptr) return placeholder(at);
    ExprPtr current = primary(c);
    const std::vector<P::PostfixOpContext*>& ops = c->suffixes;
    if (static_cast<int>(ops.size()) + exprDepth_ > kMaxExpressionDepth) return tooComplex(at);
    for (auto* op : ops) {
        ExprPtr next;
        if (auto* m = exactly<P::MemberOpContext>(op)) {
            next = makeExpr(ExprKind::Member, at);
            if (m->member != nullptr) {
                next->name = m->member->getText();
                next->nameLoc = loc(m->member);
            }
        } else if (auto* i = exactly<P::IndexOpContext>(op)) {
            next = makeExpr(ExprKind::Index, at);
            next->kids.push_back(std::move(current));
            if (i->indexes)
                for (auto* sub : i->indexes->items) next->kids.push_back(expr(sub));
            current = std::move(next);
            continue;
        } else if (exactly<P::DerefOpContext>(op)) {
            next = makeExpr(ExprKind::Deref, at);
        } else if (auto* call = exactly<P::CallOpContext>(op)) {
            next = makeExpr(ExprKind::Call, at);
            next->args = args(call->args);
        } else {
            continue;
        }
        next->kids.insert(next->kids.begin(), std::move(current));
        current = std::move(next);
    }
    return current;
}

ExprPtr AstBuilder::primary(P::PostfixExpressionContext* c) {
    const Loc at = loc(c);
    if (const antlr4::Token* name = c->name != nullptr ? c->name : c->keywordFunction) {
        auto e = makeExpr(ExprKind::Name, at);
        e->name = name->getText();
        return e;
    }
    if (c->special != nullptr) switch (c->special->getType()) {
            case L::DIRECT_ADDRESS: {
                auto e = makeExpr(ExprKind::Name, at);
                e->name = c->special->getText();
                return e;
            }
            case L::THIS: return makeExpr(ExprKind::This, at);
            case L::SUPER: return makeExpr(ExprKind::Super, at);
            default: break;
        }
    if (c->inner && c->assigned) {  // `(i := i + 1)`: an assignment used as a value (CODESYS)
        auto e = makeExpr(ExprKind::Assign, loc(c->inner));
        e->kids.push_back(expr(c->inner));
        e->kids.push_back(expr(c->assigned));
        return e;
    }
    if (c->inner) return expr(c->inner);
    return placeholder(at);
}

ExprPtr AstBuilder::literal(const antlr4::Token* token) {
    const Loc at = loc(token);
    if (token == nullptr) return placeholder(at);
    auto e = makeExpr(ExprKind::Literal, at);
    e->text = token->getText();
    switch (token->getType()) {
        case L::INTEGER: case L::BASED_INTEGER: e->lit = LitKind::Integer; break;
        case L::REAL_LITERAL: e->lit = LitKind::Real; break;
        case L::TRUE: case L::FALSE: e->lit = LitKind::Bool; break;
        case L::STRING_LITERAL: e->lit = LitKind::String; break;
        case L::WSTRING_LITERAL: e->lit = LitKind::WString; break;
        case L::DURATION_LITERAL: {
            e->lit = LitKind::Duration;
            // `T# 30ms` (matiec): the blanks after '#' are no part of the value (decision 0357).
            const auto hash = e->text.find('#');
            const auto value = e->text.find_first_not_of(" \t", hash + 1);
            if (hash != std::string::npos && value != std::string::npos && value > hash + 1) e->text.erase(hash + 1, value - hash - 1);
            break;
        }
        case L::DATE_LITERAL: e->lit = LitKind::Date; break;
        case L::TOD_LITERAL: e->lit = LitKind::TimeOfDay; break;
        case L::DT_LITERAL: e->lit = LitKind::DateTime; break;
        case L::TYPED_LITERAL: {
            e->lit = LitKind::Typed;
            const auto hash = e->text.find('#');
            e->typePrefix = e->text.substr(0, hash);
            e->valueText = hash == std::string::npos ? std::string() : e->text.substr(hash + 1);
            break;
        }
        default: return placeholder(at);
    }
    return e;
}

// `name := value`, `name => variable`, `NOT name => variable` or a value:
// the grammar parses each as expressions around an optional ':=' / '=>'.
std::vector<Arg> AstBuilder::args(P::ArgListContext* c) {
    std::vector<Arg> out;
    if (c == nullptr) return out;
    // A comma right before ')' is TwinCAT's trailing comma `F(a := 1,)`;
    // a comma before another comma, or first in the list, leaves an empty argument.
    if (c->commas.size() >= c->items.size()) {
        for (size_t k = 0; k < c->commas.size(); ++k) {
            const antlr4::Token* after = nullptr;
            for (size_t i = c->commas[k]->getTokenIndex() + 1; i < tokens_.size(); ++i) {
                antlr4::Token* t = tokens_.get(i);
                if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL) { after = t; break; }
            }
            const bool first = c->items.empty() || c->items.front()->getStart()->getTokenIndex() > c->commas[k]->getTokenIndex();
            if (first || (after != nullptr && after->getType() == L::COMMA)) {
                error(diag::E0001, loc(c->commas[k]), "empty argument: expected an expression before ','");
                break;
            }
        }
    }
    for (auto* a : c->items) {
        Arg arg;
        arg.loc = loc(a);
        const std::vector<P::ExpressionContext*>& parts = a->parts;
        if (a->op == nullptr) {
            arg.value = parts.empty() ? placeholder(arg.loc) : expr(parts[0]);
            out.push_back(std::move(arg));
            continue;
        }
        arg.output = a->op->getType() == L::ARROW;
        const antlr4::Token* name = parts.empty() ? nullptr : bareName(parts[0]);
        if (name == nullptr && arg.output && !parts.empty() && parts[0]->ops.empty() && parts[0]->operands.size() == 1) {
            // NOT name => variable: the output negated
            auto* u = exactly<P::UnaryExpressionContext>(parts[0]->operands[0]);
            if (u != nullptr && u->op != nullptr && u->op->getType() == L::NOT) {
                name = bareName(u->operand);
                arg.negated = name != nullptr;
            }
        }
        if (name == nullptr) {
            error(diag::E0001, arg.loc, fmt::format("'{}' cannot name a parameter: expected 'name {} ...'",
                                       parts.empty() ? std::string() : sourceText(parts[0]), a->op->getText()));
            continue;
        }
        arg.name = name->getText();
        if (parts.size() > 1) arg.value = expr(parts[1]);
        out.push_back(std::move(arg));
    }
    return out;
}

}  // namespace strun::ast
