// AstBuilder: files, namespaces, POUs, methods, properties, TYPE blocks,
// global lists and configurations.
#include "interpreter/ast/ast_builder.h"

#include "grammar/STLexer.h"

namespace strun::ast {

using L = strun_grammar::STLexer;

// ---------------------------------------------------------------- helpers

Loc AstBuilder::loc(const antlr4::Token* token) const {
    if (token == nullptr) return Loc{file_, 0, 0};
    return Loc{file_, static_cast<int>(token->getLine()), static_cast<int>(token->getCharPositionInLine()) + 1};
}

Loc AstBuilder::loc(antlr4::ParserRuleContext* c) const { return loc(c ? c->getStart() : nullptr); }

// The tokens of the context, without the blanks and comments between them
// (as ParseTree::getText, which builds a std::stringstream per node and
// recursed over every child: a tenth of `strun check`). A token the error
// recovery made up is not in the stream and not in the text: by then the
// error has been reported, and the text only names things in messages.
std::string AstBuilder::text(antlr4::ParserRuleContext* c) const {
    if (c == nullptr || c->getStart() == nullptr || c->getStop() == nullptr) return std::string();
    const size_t first = c->getStart()->getTokenIndex(), last = c->getStop()->getTokenIndex();
    if (first == last) return c->getStart()->getText();
    if (last < first || last >= tokens_.size()) return std::string();
    std::string out;
    for (size_t i = first; i <= last; ++i) {
        antlr4::Token* t = tokens_.get(i);
        if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL) out += t->getText();
    }
    return out;
}

std::string AstBuilder::sourceText(antlr4::ParserRuleContext* c) {
    if (c == nullptr || c->getStart() == nullptr || c->getStop() == nullptr) return "";
    antlr4::CharStream* input = c->getStart()->getInputStream();
    const size_t start = c->getStart()->getStartIndex();
    const size_t stop = c->getStop()->getStopIndex();
    if (input == nullptr || stop < start) return std::string();
    std::string out = input->getText(antlr4::misc::Interval(start, stop));
    if (out.size() > 40) out = out.substr(0, 37) + "...";
    return out;
}

Diagnostic& AstBuilder::error(diag::Code code, const Loc& at, const std::string& message) {
    return errors_.report(code, static_cast<size_t>(at.line), at.col > 0 ? static_cast<size_t>(at.col - 1) : 0, message);
}

const antlr4::Token* AstBuilder::previousOnChannel(const antlr4::Token* token) const {
    if (token == nullptr || token->getTokenIndex() >= tokens_.size()) return nullptr;
    for (size_t i = token->getTokenIndex(); i-- > 0;) {
        antlr4::Token* t = tokens_.get(i);
        if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL) return t;
    }
    return nullptr;
}

std::vector<Pragma> AstBuilder::pragmasBefore(const antlr4::Token* token) {
    std::vector<Pragma> out;
    if (token == nullptr || token->getType() == antlr4::Token::EOF) return out;
    for (antlr4::Token* p : tokens_.getHiddenTokensToLeft(token->getTokenIndex(), L::PRAGMAS)) {
        std::string body = p->getText();
        if (body.size() >= 2) body = body.substr(1, body.size() - 2);  // drop { }
        const auto first = body.find_first_not_of(" \t\r\n");
        const auto last = body.find_last_not_of(" \t\r\n");
        body = first == std::string::npos ? std::string() : body.substr(first, last - first + 1);
        out.push_back(Pragma{loc(p), body});
    }
    return out;
}

void AstBuilder::modifiers(const std::vector<P::ModifierContext*>& mods, Access& access, bool& isAbstract,
                           bool& isFinal) {
    for (auto* m : mods) {
        switch (m->getStart()->getType()) {
            case L::PUBLIC: access = Access::Public; break;
            case L::PRIVATE: access = Access::Private; break;
            case L::PROTECTED: access = Access::Protected; break;
            case L::INTERNAL: access = Access::Internal; break;
            case L::ABSTRACT: isAbstract = true; break;
            case L::FINAL: isFinal = true; break;
            default: break;
        }
    }
}

// ---------------------------------------------------------------- files

CompilationUnit AstBuilder::build(P::CompilationUnitContext* tree) {
    CompilationUnit unit;
    unit.file = file_;
    if (tree == nullptr) return unit;
    for (auto* item : tree->items) topLevelItem(item, "", unit);
    return unit;
}

void AstBuilder::topLevelItem(P::TopLevelItemContext* c, const std::string& nameSpace, CompilationUnit& unit) {
    if (auto* p = c->pou) {
        if (auto built = pou(p, nameSpace)) unit.pous.push_back(std::move(built));
    } else if (auto* m = c->method) {
        unit.pous.push_back(method(m, nameSpace, false));
    } else if (auto* a = c->action) {
        // CODESYS writes an ACTION after the POU it belongs to.
        Pou* owner = unit.pous.empty() ? nullptr : unit.pous.back().get();
        if (!owner || (owner->kind != PouKind::Program && owner->kind != PouKind::FunctionBlock)) {
            error(diag::E0009, loc(a), "ACTION '" + text(a->name) + "' must follow the PROGRAM or FUNCTION_BLOCK it belongs to");
            return;
        }
        owner->methods.push_back(action(a, owner->nameSpace));
    } else if (auto* t = c->types) {
        typeDecl(t, nameSpace, unit);
    } else if (auto* v = c->globals) {
        VarBlock block = varBlock(v);
        if (block.section != VarSection::Global) {
            error(diag::E0009, block.loc, "only VAR_GLOBAL is allowed outside a POU, found " + v->getStart()->getText());
            return;
        }
        GlobalList list;
        list.loc = block.loc;
        list.nameSpace = nameSpace;
        list.pragmas = pragmasBefore(v->getStart());
        list.blocks.push_back(std::move(block));
        unit.globals.push_back(std::move(list));
    } else if (auto* cfg = c->config) {
        unit.configurations.push_back(configuration(cfg));
    } else if (auto* ns = c->space) {
        const std::string inner = text(ns->name);
        const std::string path = nameSpace.empty() ? inner : nameSpace + "." + inner;
        for (auto* item : ns->items) topLevelItem(item, path, unit);
    } else if (auto* u = c->uses) {
        for (auto* name : u->names) unit.usings.push_back(UsingDirective{loc(name), text(name)});
    }
}

// ---------------------------------------------------------------- POUs

std::unique_ptr<Pou> AstBuilder::pou(P::PouDeclContext* c, const std::string& nameSpace) {
    auto out = std::make_unique<Pou>();
    out->loc = loc(c);
    out->nameSpace = nameSpace;
    out->pragmas = pragmasBefore(c->getStart());
    out->hasBody = true;

    auto addElements = [&](const std::vector<P::PouElementContext*>& elements) {
        for (auto* e : elements) {
            if (auto* v = e->vars) out->vars.push_back(varBlock(v));
            else if (auto* m = e->member) member(m, *out, false);
        }
    };

    if (auto* prog = exactly<P::ProgramDeclContext>(c)) {
        out->kind = PouKind::Program;
        out->name = text(prog->name);
        modifiers(prog->modifiers, out->access, out->abstract, out->final);
        out->nameLoc = loc(prog->name);
        addElements(prog->elements);
        if (prog->body) statements(prog->body->statements, out->body);
        for (auto* m : prog->members) member(m, *out, false);
        out->endLoc = loc(prog->end ? prog->end : c->getStop());
    } else if (auto* fn = exactly<P::FunctionDeclContext>(c)) {
        out->kind = PouKind::Function;
        out->name = text(fn->name);
        modifiers(fn->modifiers, out->access, out->abstract, out->final);
        out->nameLoc = loc(fn->name);
        if (fn->result) out->returnType = returnType(fn->result);
        for (auto* v : fn->vars) out->vars.push_back(varBlock(v));
        stmtList(fn->body, out->body);
        out->endLoc = loc(fn->end ? fn->end : c->getStop());
    } else if (auto* fb = exactly<P::FunctionBlockDeclContext>(c)) {
        out->kind = PouKind::FunctionBlock;
        out->name = text(fb->name);
        out->nameLoc = loc(fb->name);
        modifiers(fb->modifiers, out->access, out->abstract, out->final);
        if (fb->base) out->extends = text(fb->base);
        if (fb->baseGeneric) out->extendsGenericArgs = genericArguments(fb->baseGeneric);
        for (auto* i : fb->interfaces) out->implements.push_back(text(i));
        addElements(fb->elements);
        if (fb->body) statements(fb->body->statements, out->body);
        for (auto* m : fb->members) member(m, *out, false);
        out->endLoc = loc(fb->end ? fb->end : c->getStop());
    } else if (auto* cls = exactly<P::ClassDeclContext>(c)) {
        // IEC 61131-3 Ed.3 CLASS: a function block without a body of its own (decision 0209).
        out->kind = PouKind::FunctionBlock;
        out->name = text(cls->name);
        out->nameLoc = loc(cls->name);
        modifiers(cls->modifiers, out->access, out->abstract, out->final);
        if (cls->base) out->extends = text(cls->base);
        if (cls->baseGeneric) out->extendsGenericArgs = genericArguments(cls->baseGeneric);
        for (auto* i : cls->interfaces) out->implements.push_back(text(i));
        addElements(cls->elements);
        out->endLoc = loc(cls->end ? cls->end : c->getStop());
    } else if (auto* itf = exactly<P::InterfaceDeclContext>(c)) {
        out->kind = PouKind::Interface;
        out->name = text(itf->name);
        modifiers(itf->modifiers, out->access, out->abstract, out->final);
        out->nameLoc = loc(itf->name);
        out->hasBody = false;
        for (auto* base : itf->bases) out->extendsList.push_back(text(base));
        if (!out->extendsList.empty()) out->extends = out->extendsList.front();
        for (auto* m : itf->members) member(m, *out, true);
        out->endLoc = loc(itf->end ? itf->end : c->getStop());
    } else {
        return nullptr;  // nothing recognisable; the syntax error is reported
    }
    return out;
}

void AstBuilder::member(P::MemberDeclContext* c, Pou& owner, bool inInterface) {
    if (auto* m = c->method) owner.methods.push_back(method(m, owner.nameSpace, inInterface));
    else if (auto* a = c->action) {
        if (inInterface) error(diag::E0009, loc(a), "an INTERFACE cannot have an ACTION");
        else owner.methods.push_back(action(a, owner.nameSpace));
    }
    else if (auto* p = c->property) owner.properties.push_back(property(p, owner.nameSpace, inInterface));
}

std::unique_ptr<Pou> AstBuilder::method(P::MethodDeclContext* c, const std::string& nameSpace, bool inInterface) {
    auto out = std::make_unique<Pou>();
    out->kind = PouKind::Method;
    out->loc = loc(c);
    out->nameSpace = nameSpace;
    out->pragmas = pragmasBefore(c->getStart());
    out->name = text(c->name);
    out->nameLoc = loc(c->name);
    modifiers(c->modifiers, out->access, out->abstract, out->final);
    for (auto* m : c->modifiers) out->override = out->override || m->getStart()->getType() == L::OVERRIDE;
    if (c->result) out->returnType = returnType(c->result);
    for (auto* v : c->vars) out->vars.push_back(varBlock(v));
    stmtList(c->body, out->body);
    out->hasBody = !(inInterface || out->abstract);
    if (!out->hasBody && !out->body.empty()) {
        error(diag::E0009, out->body.front()->loc, inInterface ? "a method of an INTERFACE has no body (statements found in '" +
                                                        out->name + "')"
                                                  : "the ABSTRACT method '" + out->name + "' cannot have a body");
        out->body.clear();
    }
    out->endLoc = loc(c->end ? c->end : c->getStop());
    return out;
}

// An ACTION is a method without parameters or variables of its own.
std::unique_ptr<Pou> AstBuilder::action(P::ActionDeclContext* c, const std::string& nameSpace) {
    auto out = std::make_unique<Pou>();
    out->kind = PouKind::Method;
    out->isAction = true;
    out->loc = loc(c);
    out->nameSpace = nameSpace;
    out->pragmas = pragmasBefore(c->getStart());
    out->name = text(c->name);
    out->nameLoc = loc(c->name);
    stmtList(c->body, out->body);
    out->hasBody = true;
    out->endLoc = loc(c->end ? c->end : c->getStop());
    return out;
}

Property AstBuilder::property(P::PropertyDeclContext* c, const std::string& nameSpace, bool inInterface) {
    Property out;
    out.loc = loc(c);
    out.name = text(c->name);
    out.pragmas = pragmasBefore(c->getStart());
    modifiers(c->modifiers, out.access, out.abstract, out.final);
    if (c->type) out.type = typeSpec(c->type);
    const bool prototype = inInterface || out.abstract;

    auto accessor = [&](antlr4::ParserRuleContext* ctx, const char* name, const std::vector<P::VarBlockContext*>& vars,
                        P::StmtListContext* body, const antlr4::Token* end) {
        auto pou = std::make_unique<Pou>();
        pou->kind = PouKind::Method;
        pou->name = name;
        pou->loc = loc(ctx);
        pou->nameSpace = nameSpace;
        pou->access = out.access;
        pou->abstract = out.abstract;
        pou->final = out.final;
        for (auto* v : vars) pou->vars.push_back(varBlock(v));
        stmtList(body, pou->body);
        pou->hasBody = !prototype;
        if (prototype && !pou->body.empty()) {
            error(diag::E0009, pou->body.front()->loc, "the " + std::string(name) + " accessor of property '" + out.name +
                                              "' cannot have a body here (interface or ABSTRACT)");
            pou->body.clear();
        }
        pou->endLoc = loc(end ? end : ctx->getStop());
        return pou;
    };

    for (auto* a : c->accessors) {
        if (auto* g = exactly<P::PropertyGetterContext>(a)) {
            if (out.getter) error(diag::E0009, loc(g), "property '" + out.name + "' has more than one GET");
            out.getter = accessor(g, "GET", g->vars, g->body, g->end);
            modifiers(g->modifiers, out.getter->access, out.getter->abstract, out.getter->final);  // `GET PRIVATE`
        } else if (auto* s = exactly<P::PropertySetterContext>(a)) {
            if (out.setter) error(diag::E0009, loc(s), "property '" + out.name + "' has more than one SET");
            out.setter = accessor(s, "SET", s->vars, s->body, s->end);
            modifiers(s->modifiers, out.setter->access, out.setter->abstract, out.setter->final);  // `SET PROTECTED`
        }
    }
    // An interface property written without accessor sections is read/write.
    if (inInterface && !out.getter && !out.setter) {
        out.getter = accessor(c, "GET", {}, nullptr, nullptr);
        out.setter = accessor(c, "SET", {}, nullptr, nullptr);
    }
    return out;
}

// ---------------------------------------------------------------- TYPE

void AstBuilder::typeDecl(P::TypeDeclContext* c, const std::string& nameSpace, CompilationUnit& unit) {
    bool first = true;
    for (auto* e : c->entries) {
        TypeDecl decl;
        decl.loc = loc(e);
        decl.name = text(e->name);
        decl.nameLoc = loc(e->name);
        decl.nameSpace = nameSpace;
        if (e->base) decl.extends = text(e->base);
        // Pragmas in front of TYPE belong to its first entry.
        if (first) decl.pragmas = pragmasBefore(c->getStart());
        for (auto& p : pragmasBefore(e->getStart())) decl.pragmas.push_back(std::move(p));
        first = false;
        decl.spec = typeSpec(e->type);
        if (e->init) decl.init = initializer(e->init);
        if (!decl.extends.empty() && decl.spec && decl.spec->kind != TypeSpecKind::Struct)
            error(diag::E0407, decl.loc, "EXTENDS in a TYPE is only allowed for a STRUCT ('" + decl.name + "')");
        unit.types.push_back(std::move(decl));
    }
}

// ---------------------------------------------------------------- configuration

Configuration AstBuilder::configuration(P::ConfigurationContext* c) {
    Configuration out;
    out.loc = loc(c);
    out.name = text(c->name);
    for (auto* e : c->elements) {
        if (auto* v = e->vars) out.globals.push_back(varBlock(v));
        else if (auto* r = e->res) out.resources.push_back(resource(r));
        else if (auto* t = e->task) out.tasks.push_back(task(t));
        else if (auto* p = e->program) out.programs.push_back(programConfig(p));
    }
    return out;
}

Resource AstBuilder::resource(P::ResourceContext* c) {
    Resource out;
    out.loc = loc(c);
    out.name = text(c->name);
    out.on = text(c->target);
    for (auto* e : c->elements) {
        if (auto* v = e->vars) out.globals.push_back(varBlock(v));
        else if (auto* t = e->task) out.tasks.push_back(task(t));
        else if (auto* p = e->program) out.programs.push_back(programConfig(p));
    }
    return out;
}

TaskDecl AstBuilder::task(P::TaskDeclContext* c) {
    TaskDecl out;
    out.loc = loc(c);
    out.name = text(c->name);
    for (auto* p : c->params) {
        TaskParam param;
        param.loc = loc(p);
        param.name = text(p->name);
        param.value = p->value ? expr(p->value) : placeholder(param.loc);
        out.params.push_back(std::move(param));
    }
    return out;
}

ProgramConfig AstBuilder::programConfig(P::ProgramConfigContext* c) {
    ProgramConfig out;
    out.loc = loc(c);
    if (auto* p = exactly<P::ProgramInstanceContext>(c)) {
        out.isProgram = true;
        out.instance = text(p->name);
        out.task = text(p->task);
        out.typeName = text(p->type);
        out.args = args(p->args);
    } else if (auto* b = exactly<P::FbTaskBindingContext>(c)) {
        out.isProgram = false;
        out.instance = text(b->name);
        out.task = text(b->task);
    }
    return out;
}

}  // namespace strun::ast
