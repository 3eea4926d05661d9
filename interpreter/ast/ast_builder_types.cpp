// AstBuilder: VAR blocks, variable declarations, type specifications and
// initial values.
#include "interpreter/ast/ast_builder.h"
#include "interpreter/ast/ast_clone.h"

#include <cctype>

#include "grammar/STLexer.h"

namespace strun::ast {

using L = strun_grammar::STLexer;

namespace {

VarSection sectionOf(size_t tokenType) {
    switch (tokenType) {
        case L::VAR_INPUT: return VarSection::Input;
        case L::VAR_OUTPUT: return VarSection::Output;
        case L::VAR_IN_OUT: return VarSection::InOut;
        case L::VAR_TEMP: return VarSection::Temp;
        case L::VAR_STAT: return VarSection::Stat;
        case L::VAR_INST: return VarSection::Inst;
        case L::VAR_GLOBAL: return VarSection::Global;
        case L::VAR_EXTERNAL: return VarSection::External;
        case L::VAR_ACCESS: return VarSection::Access;
        case L::VAR_CONFIG: return VarSection::Config;
        default: return VarSection::Var;
    }
}

}  // namespace

VarBlock AstBuilder::varBlock(P::VarBlockContext* c) {
    VarBlock out;
    out.loc = loc(c);
    if (c->access != nullptr) out.section = VarSection::Access;
    else if (c->section) out.section = sectionOf(c->section->getStart()->getType());
    if (c->section && c->section->getStart()->getType() == L::VAR_GENERIC) {
        out.generic = true;
        out.constant = true;  // a generic variable is a constant of its instance's type (decision 0312)
    }
    for (auto* q : c->qualifiers) {
        switch (q->getStart()->getType()) {
            case L::CONSTANT: out.constant = true; break;
            case L::RETAIN: out.retain = true; break;
            case L::NON_RETAIN: out.nonRetain = true; break;
            case L::PERSISTENT: out.persistent = true; break;
            case L::PUBLIC: out.access = Access::Public; break;
            case L::PRIVATE: out.access = Access::Private; break;
            case L::PROTECTED: out.access = Access::Protected; break;
            case L::INTERNAL: out.access = Access::Internal; break;
            default: break;
        }
    }
    for (auto* d : c->decls) out.vars.push_back(varDecl(d, out.section));
    for (auto* d : c->accessDecls) out.vars.push_back(accessDecl(d));
    return out;
}

// `name : prog.var : TYPE READ_ONLY;` (VAR_ACCESS)
VarDecl AstBuilder::accessDecl(P::AccessDeclContext* c) {
    VarDecl out;
    out.loc = loc(c);
    out.pragmas = pragmasBefore(c->getStart());
    if (c->name) {
        out.names.push_back(text(c->name));
        out.nameLocs.push_back(loc(c->name));
    }
    out.accessPath = text(c->path);
    out.readOnly = c->accessMode != nullptr && c->accessMode->getType() == L::READ_ONLY;
    out.type = typeSpec(c->type);
    return out;
}

VarDecl AstBuilder::varDecl(P::VarDeclContext* c, VarSection section) {
    VarDecl out;
    if (c->semi == nullptr && c->exception == nullptr && c->getStop() != nullptr && c->getStart() != nullptr)
        reportMissingDeclarationSemicolon(errors_, &tokens_, c->getStart(), c->getStop());
    out.loc = loc(c);
    out.pragmas = pragmasBefore(c->getStart());
    for (auto* n : c->names) {
        out.names.push_back(text(n));
        out.nameLocs.push_back(loc(n));
        // A path (prog.x, arr[1]) names something declared elsewhere: only
        // VAR_CONFIG (and VAR_ACCESS) refer to other declarations that way.
        const bool isPath = n->getStart() != n->getStop();
        if (isPath && section != VarSection::Config && section != VarSection::Access)
            error(diag::E0009, loc(n), "'" + out.names.back() + "' is not a simple name; paths are only allowed in VAR_CONFIG");
    }
    if (c->address != nullptr) out.address = c->address->getText();
    if (c->names.empty()) {
        // IEC's located declaration without a name, `AT %MW1 : INT := 2;`:
        // the address is the variable's only name (code writes `%MW1`), so
        // the declaration gives it its type and initial value; hidden from
        // --dump and --vcd, which list named variables (decision 0339).
        if (c->address == nullptr) {
            error(diag::E0001, loc(c), "a declaration needs a name, or AT and an address");
        } else if (section != VarSection::Var && section != VarSection::Global) {
            error(diag::E0009, loc(c), "a declaration without a name ('AT " + out.address + " : ...') is only allowed in VAR and VAR_GLOBAL");
        } else {
            out.names.push_back(out.address);
            out.nameLocs.push_back(loc(c->address));
            out.pragmas.push_back({out.loc, "attribute 'strun_hidden'"});
        }
    }
    out.type = typeSpec(c->type);
    if (c->edge != nullptr) out.edge = c->edge->getType() == L::R_EDGE ? VarDecl::Edge::Rising : VarDecl::Edge::Falling;
    if (c->init != nullptr) out.init = initializer(c->init);
    // TwinCAT `r : REFERENCE TO INT REF= x;`: bound to x once per instance (decision 0201).
    if (auto* ref = exactly<P::ReferenceTypeContext>(c->type); ref != nullptr && ref->refOperator != nullptr) {
        std::string op = text(ref->refOperator);
        for (char& ch : op) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        if (op != "REF") {
            error(diag::E0001, loc(ref->refOperator), "unknown initialisation operator '" + text(ref->refOperator) + "=', expected ':=' or 'REF='");
        } else if (out.init == nullptr) {
            // A reference's initial value names the variable it refers to (as `:= x`).
            out.init = std::make_unique<Init>();
            out.init->kind = InitKind::Expr;
            out.init->loc = loc(ref->refInit);
            out.init->expr = ref->refInit ? expr(ref->refInit) : placeholder(out.init->loc);
        }
    }
    return out;
}

TypeSpecPtr AstBuilder::namedType(P::QualifiedNameContext* c) {
    auto out = std::make_unique<TypeSpec>();
    out->kind = TypeSpecKind::Named;
    out->loc = loc(c);
    out->name = text(c);
    return out;
}

// `<6, (2 * c), cMax, -1>`: each value as an expression, checked where the
// instance is declared.
std::vector<ExprPtr> AstBuilder::genericArguments(P::GenericArgumentsContext* c) {
    std::vector<ExprPtr> out;
    if (c == nullptr) return out;
    for (auto* v : c->values) {
        if (v->value) {
            out.push_back(expr(v->value));
        } else if (v->number) {
            ExprPtr e = literal(v->number);
            if (v->sign) {
                auto neg = std::make_unique<Expr>();
                neg->kind = ExprKind::Unary;
                neg->op = Op::Neg;
                neg->loc = loc(v->sign);
                neg->kids.push_back(std::move(e));
                e = std::move(neg);
            }
            out.push_back(std::move(e));
        } else if (v->name) {
            // A dotted name `Ns.cMax` becomes Name `Ns` with Member `cMax`, as in an expression.
            ExprPtr e;
            const std::string written = text(v->name);
            for (size_t from = 0; from <= written.size();) {
                size_t dot = written.find('.', from);
                if (dot == std::string::npos) dot = written.size();
                const std::string word = written.substr(from, dot - from);
                from = dot + 1;
                if (word.empty()) continue;
                auto next = std::make_unique<Expr>();
                next->loc = loc(v->name);
                next->nameLoc = next->loc;
                next->name = word;
                if (e) {
                    next->kind = ExprKind::Member;
                    next->kids.push_back(std::move(e));
                } else {
                    next->kind = ExprKind::Name;
                }
                e = std::move(next);
            }
            out.push_back(e ? std::move(e) : placeholder(loc(v)));
        } else {
            out.push_back(placeholder(loc(v)));
        }
    }
    return out;
}

EnumValue AstBuilder::enumValue(P::EnumValueContext* c) {
    EnumValue out;
    out.loc = loc(c);
    out.name = text(c->name);
    if (c->value) out.value = expr(c->value);
    return out;
}

TypeSpecPtr AstBuilder::typeSpec(P::TypeSpecContext* c) {
    auto out = std::make_unique<TypeSpec>();
    out->loc = loc(c);
    if (c == nullptr) return out;  // missing after a syntax error: an unnamed Named type

    if (auto* n = exactly<P::NamedTypeContext>(c)) {
        out->kind = TypeSpecKind::Named;
        P::TypeArgumentsContext* arguments = n->arguments;
        if (arguments == nullptr) {
            out->name = text(n->name);
        } else if (auto* sr = exactly<P::SubrangeArgsContext>(arguments)) {
            out->kind = TypeSpecKind::Subrange;
            if (n->name) out->elem = namedType(n->name);
            out->lo = sr->lo ? expr(sr->lo) : placeholder(out->loc);
            out->hi = sr->hi ? expr(sr->hi) : placeholder(out->loc);
        } else if (auto* te = exactly<P::EnumArgsContext>(arguments)) {
            out->kind = TypeSpecKind::Enum;
            for (auto* v : te->values) out->enumValues.push_back(enumValue(v));
            if (n->name) out->elem = namedType(n->name);
        } else if (auto* ia = exactly<P::InstanceArgsContext>(arguments)) {
            out->name = text(n->name);
            out->initArgs = args(ia->args);
        } else if (auto* pe = exactly<P::PerElementArgsContext>(arguments)) {
            out->name = text(n->name);
            for (auto* element : pe->elements)
                out->elementInitArgs.push_back(element->args ? args(element->args) : std::vector<Arg>{});
        }
        // `FB_X<4>(a := 1)` arrives as an enumeration on FB_X: the values go with the name.
        if (n->generic) (out->elem ? out->elem->genericArgs : out->genericArgs) = genericArguments(n->generic);
    } else if (sharedTypeForm<P::ArrayTypeContext, P::PointerTypeContext, P::ReferenceTypeContext, P::StringTypeContext>(
                   c, *out, [&](auto* form) { return typeSpec(form->element); })) {
        // ARRAY, POINTER TO, REFERENCE TO, STRING
    } else if (auto* st = exactly<P::StructTypeContext>(c)) {
        out->kind = TypeSpecKind::Struct;
        for (auto* d : st->fields) out->fields.push_back(varDecl(d, VarSection::Var));
    } else if (auto* un = exactly<P::UnionTypeContext>(c)) {
        out->kind = TypeSpecKind::Struct;
        out->isUnion = true;
        for (auto* d : un->fields) out->fields.push_back(varDecl(d, VarSection::Var));
    } else if (auto* e = exactly<P::EnumTypeContext>(c)) {
        out->kind = TypeSpecKind::Enum;
        for (auto* v : e->values) out->enumValues.push_back(enumValue(v));
        if (e->base) out->elem = namedType(e->base);
    }
    return out;
}

// The forms typeSpec and returnType share, for either rule's contexts;
// `element` builds the type after OF or TO. False if `c` is none of them.
template <typename ArrayForm, typename PointerForm, typename ReferenceForm, typename StringForm, typename Context,
          typename Element>
bool AstBuilder::sharedTypeForm(Context* c, TypeSpec& out, Element&& element) {
    if (auto* a = exactly<ArrayForm>(c)) {
        out.kind = TypeSpecKind::Array;
        out.dims = arrayRanges(a->ranges);
        out.elem = element(a);
    } else if (auto* p = exactly<PointerForm>(c)) {
        out.kind = TypeSpecKind::Pointer;
        // The parser builds no tree of tokens: the form's first token tells the spelling.
        out.refTo = p->getStart() != nullptr && p->getStart()->getType() == L::REF_TO;
        out.elem = element(p);
    } else if (auto* r = exactly<ReferenceForm>(c)) {
        out.kind = TypeSpecKind::Reference;
        out.elem = element(r);
    } else if (auto* s = exactly<StringForm>(c)) {
        out.kind = TypeSpecKind::String;
        out.wide = s->kind != nullptr && s->kind->getType() == L::WSTRING;
        if (s->length) out.length = expr(s->length);
    } else {
        return false;
    }
    return true;
}

std::vector<Range> AstBuilder::arrayRanges(const std::vector<P::ArrayRangeContext*>& ranges) {
    std::vector<Range> out;
    for (auto* r : ranges) {
        Range range;
        if (r->star) {
            range.star = true;
        } else {
            range.lo = r->lo ? expr(r->lo) : placeholder(loc(r));
            range.hi = r->hi ? expr(r->hi) : placeholder(loc(r));
        }
        out.push_back(std::move(range));
    }
    return out;
}

// The same TypeSpec as typeSpec() builds for the same text.
TypeSpecPtr AstBuilder::returnType(P::ReturnTypeContext* c) {
    auto out = std::make_unique<TypeSpec>();
    out->loc = loc(c);
    if (c == nullptr) return out;
    if (auto* n = exactly<P::NamedReturnTypeContext>(c)) {
        out->kind = TypeSpecKind::Named;
        if (n->lo != nullptr || n->hi != nullptr) {  // `METHOD M : UINT(0..9)` (TwinCAT)
            out->kind = TypeSpecKind::Subrange;
            if (n->name) out->elem = namedType(n->name);
            out->lo = n->lo ? expr(n->lo) : placeholder(out->loc);
            out->hi = n->hi ? expr(n->hi) : placeholder(out->loc);
        } else {
            out->name = text(n->name);
        }
    } else {
        sharedTypeForm<P::ArrayReturnTypeContext, P::PointerReturnTypeContext, P::ReferenceReturnTypeContext,
                       P::StringReturnTypeContext>(c, *out, [&](auto* form) { return returnType(form->element); });
    }
    return out;
}

namespace {
bool isDottedName(const Expr& e) {
    if (e.kind == ExprKind::Name) return true;
    return e.kind == ExprKind::Member && isDottedName(*e.kids[0]);
}
}  // namespace

// `[PMPS_GVL.AUX_ATTENUATORS(st)]` reads as a call; it may be IEC's repetition
// with a named constant as the count. Which one only the checker can tell
// (a constant or a function), so the item keeps both readings.
void AstBuilder::repetitionByName(ArrayInitItem& item) {
    if (!item.value || item.value->kind != InitKind::Expr || !item.value->expr) return;
    const Expr& call = *item.value->expr;
    if (call.kind != ExprKind::Call || call.args.size() != 1 || !isDottedName(*call.kids[0])) return;
    const Arg& arg = call.args[0];
    if (!arg.name.empty() || arg.output || !arg.value) return;
    item.repeat = cloneExpr(*call.kids[0]);
    auto value = std::make_unique<Init>();
    value->kind = InitKind::Expr;
    value->loc = arg.value->loc;
    value->expr = cloneExpr(*arg.value);
    item.callForm = std::move(item.value);
    item.value = std::move(value);
}

InitPtr AstBuilder::initializer(P::InitializerContext* c) {
    auto out = std::make_unique<Init>();
    out->loc = loc(c);
    if (c == nullptr) {
        out->expr = placeholder(out->loc);
        return out;
    }
    if (auto* a = exactly<P::ArrayInitContext>(c)) {
        out->kind = InitKind::Array;
        for (auto* item : a->items) {
            ArrayInitItem built;
            if (item->count != nullptr) {  // count(value)
                auto repeat = std::make_unique<Expr>();
                repeat->kind = ExprKind::Literal;
                repeat->lit = LitKind::Integer;
                repeat->loc = loc(item->count);
                repeat->text = item->count->getText();
                built.repeat = std::move(repeat);
                if (item->value) built.value = initializer(item->value);
            } else {
                built.value = initializer(item->value);
                repetitionByName(built);
            }
            out->items.push_back(std::move(built));
        }
    } else if (auto* s = exactly<P::StructInitContext>(c)) {
        out->kind = InitKind::Struct;
        for (auto* item : s->fields) {
            StructInitItem built;
            built.loc = loc(item);
            built.name = text(item->name);
            built.value = initializer(item->value);
            out->fields.push_back(std::move(built));
        }
    } else if (auto* e = exactly<P::ExprInitContext>(c)) {
        out->kind = InitKind::Expr;
        out->expr = expr(e->value);
    } else {
        out->expr = placeholder(out->loc);
    }
    return out;
}

}  // namespace strun::ast
