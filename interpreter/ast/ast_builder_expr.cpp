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

ExprPtr AstBuilder::expr(P::ExpressionContext* c) {
    if (c == nullptr) return placeholder(Loc{file_, 0, 0});
    const Loc at = loc(c);
    DepthScope scope(exprDepth_);
    if (exprDepth_ > kMaxExpressionDepth) {
        if (!depthReported_)
            error(at, fmt::format("expression too complex: more than {} nested operations", kMaxExpressionDepth));
        depthReported_ = true;
        return placeholder(at);
    }

    if (auto* p = dynamic_cast<P::PostfixExpressionContext*>(c)) return postfix(p->postfixExpr());
    if (auto* l = dynamic_cast<P::LiteralExpressionContext*>(c)) return literal(l->literal());
    if (auto* u = dynamic_cast<P::UnaryExpressionContext*>(c)) {
        auto e = makeExpr(ExprKind::Unary, at);
        const size_t type = u->op ? u->op->getType() : static_cast<size_t>(L::MINUS);
        e->op = type == L::NOT ? Op::Not : type == L::PLUS ? Op::Plus : Op::Neg;
        e->kids.push_back(expr(u->expression()));
        return e;
    }
    if (auto* b = dynamic_cast<P::BinaryExpressionContext*>(c)) {
        auto e = makeExpr(ExprKind::Binary, at);
        e->op = binaryOp(b->op ? b->op->getType() : 0);
        e->kids.push_back(expr(b->expression(0)));
        e->kids.push_back(expr(b->expression(1)));
        return e;
    }
    return placeholder(at);
}

ExprPtr AstBuilder::postfix(P::PostfixExprContext* c) {
    const Loc at = loc(c);
    if (c == nullptr) return placeholder(at);
    ExprPtr current = primary(c->primary());
    const auto ops = c->postfixOp();
    if (static_cast<int>(ops.size()) + exprDepth_ > kMaxExpressionDepth) {
        if (!depthReported_)
            error(at, fmt::format("expression too complex: more than {} nested operations", kMaxExpressionDepth));
        depthReported_ = true;
        return placeholder(at);
    }
    for (auto* op : ops) {
        ExprPtr next;
        if (auto* m = dynamic_cast<P::MemberOpContext*>(op)) {
            next = makeExpr(ExprKind::Member, at);
            next->name = text(m->memberName());
            next->nameLoc = loc(m->memberName());
        } else if (auto* i = dynamic_cast<P::IndexOpContext*>(op)) {
            next = makeExpr(ExprKind::Index, at);
            next->kids.push_back(std::move(current));
            if (i->expressionList())
                for (auto* sub : i->expressionList()->expression()) next->kids.push_back(expr(sub));
            current = std::move(next);
            continue;
        } else if (dynamic_cast<P::DerefOpContext*>(op)) {
            next = makeExpr(ExprKind::Deref, at);
        } else if (auto* call = dynamic_cast<P::CallOpContext*>(op)) {
            next = makeExpr(ExprKind::Call, at);
            next->args = args(call->argList());
        } else {
            continue;
        }
        next->kids.insert(next->kids.begin(), std::move(current));
        current = std::move(next);
    }
    return current;
}

ExprPtr AstBuilder::primary(P::PrimaryContext* c) {
    const Loc at = loc(c);
    if (c == nullptr) return placeholder(at);
    if (c->identifier()) {
        auto e = makeExpr(ExprKind::Name, at);
        e->name = text(c->identifier());
        return e;
    }
    if (c->keywordFunction) {
        auto e = makeExpr(ExprKind::Name, at);
        e->name = c->keywordFunction->getText();
        return e;
    }
    if (c->DIRECT_ADDRESS()) {
        auto e = makeExpr(ExprKind::Name, at);
        e->name = c->DIRECT_ADDRESS()->getText();
        return e;
    }
    if (c->THIS()) return makeExpr(ExprKind::This, at);
    if (c->SUPER()) return makeExpr(ExprKind::Super, at);
    if (c->expression()) return expr(c->expression());
    return placeholder(at);
}

ExprPtr AstBuilder::literal(P::LiteralContext* c) {
    const Loc at = loc(c);
    if (c == nullptr || c->getStart() == nullptr) return placeholder(at);
    auto e = makeExpr(ExprKind::Literal, at);
    const antlr4::Token* token = c->getStart();
    e->text = token->getText();
    switch (token->getType()) {
        case L::INTEGER: case L::BASED_INTEGER: e->lit = LitKind::Integer; break;
        case L::REAL_LITERAL: e->lit = LitKind::Real; break;
        case L::TRUE: case L::FALSE: e->lit = LitKind::Bool; break;
        case L::STRING_LITERAL: e->lit = LitKind::String; break;
        case L::WSTRING_LITERAL: e->lit = LitKind::WString; break;
        case L::DURATION_LITERAL: e->lit = LitKind::Duration; break;
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

std::vector<Arg> AstBuilder::args(P::ArgListContext* c) {
    std::vector<Arg> out;
    if (c == nullptr) return out;
    for (auto* a : c->arg()) {
        Arg arg;
        arg.loc = loc(a);
        if (auto* in = dynamic_cast<P::InputArgContext*>(a)) {
            arg.name = text(in->identifier());
            if (in->expression()) arg.value = expr(in->expression());
        } else if (auto* outArg = dynamic_cast<P::OutputArgContext*>(a)) {
            arg.name = text(outArg->identifier());
            arg.output = true;
            arg.negated = outArg->NOT() != nullptr;
            if (outArg->expression()) arg.value = expr(outArg->expression());
        } else if (auto* pos = dynamic_cast<P::PositionalArgContext*>(a)) {
            arg.value = expr(pos->expression());
        }
        out.push_back(std::move(arg));
    }
    return out;
}

}  // namespace strun::ast
