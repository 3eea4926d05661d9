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

Diagnostic& AstBuilder::error(const Loc& at, const std::string& message) {
    return errors_.report(static_cast<size_t>(at.line), at.col > 0 ? static_cast<size_t>(at.col - 1) : 0, message);
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
    for (auto* item : tree->topLevelItem()) topLevelItem(item, "", unit);
    return unit;
}

void AstBuilder::topLevelItem(P::TopLevelItemContext* c, const std::string& nameSpace, CompilationUnit& unit) {
    if (auto* p = c->pouDecl()) {
        if (auto built = pou(p, nameSpace)) unit.pous.push_back(std::move(built));
    } else if (auto* m = c->methodDecl()) {
        unit.pous.push_back(method(m, nameSpace, false));
    } else if (auto* a = c->actionDecl()) {
        // CODESYS writes an ACTION after the POU it belongs to.
        Pou* owner = unit.pous.empty() ? nullptr : unit.pous.back().get();
        if (!owner || (owner->kind != PouKind::Program && owner->kind != PouKind::FunctionBlock)) {
            error(loc(a), "ACTION '" + text(a->identifier()) + "' must follow the PROGRAM or FUNCTION_BLOCK it belongs to");
            return;
        }
        owner->methods.push_back(action(a, owner->nameSpace));
    } else if (auto* t = c->typeDecl()) {
        typeDecl(t, nameSpace, unit);
    } else if (auto* v = c->varBlock()) {
        VarBlock block = varBlock(v);
        if (block.section != VarSection::Global) {
            error(block.loc, "only VAR_GLOBAL is allowed outside a POU, found " + v->getStart()->getText());
            return;
        }
        GlobalList list;
        list.loc = block.loc;
        list.nameSpace = nameSpace;
        list.pragmas = pragmasBefore(v->getStart());
        list.blocks.push_back(std::move(block));
        unit.globals.push_back(std::move(list));
    } else if (auto* cfg = c->configuration()) {
        unit.configurations.push_back(configuration(cfg));
    } else if (auto* ns = c->namespaceDecl()) {
        const std::string inner = text(ns->qualifiedName());
        const std::string path = nameSpace.empty() ? inner : nameSpace + "." + inner;
        for (auto* item : ns->topLevelItem()) topLevelItem(item, path, unit);
    } else if (auto* u = c->usingDirective()) {
        for (auto* name : u->qualifiedName()) unit.usings.push_back(UsingDirective{loc(name), text(name)});
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
            if (auto* v = e->varBlock()) out->vars.push_back(varBlock(v));
            else if (auto* m = e->memberDecl()) member(m, *out, false);
        }
    };

    if (auto* prog = exactly<P::ProgramDeclContext>(c)) {
        out->kind = PouKind::Program;
        out->name = text(prog->identifier());
        out->nameLoc = loc(prog->identifier());
        addElements(prog->pouElement());
        stmtList(prog->stmtList(), out->body);
        for (auto* m : prog->memberDecl()) member(m, *out, false);
        out->endLoc = loc(prog->END_PROGRAM() ? prog->END_PROGRAM()->getSymbol() : c->getStop());
    } else if (auto* fn = exactly<P::FunctionDeclContext>(c)) {
        out->kind = PouKind::Function;
        out->name = text(fn->identifier());
        out->nameLoc = loc(fn->identifier());
        if (fn->returnType()) out->returnType = returnType(fn->returnType());
        for (auto* v : fn->varBlock()) out->vars.push_back(varBlock(v));
        stmtList(fn->stmtList(), out->body);
        out->endLoc = loc(fn->END_FUNCTION() ? fn->END_FUNCTION()->getSymbol() : c->getStop());
    } else if (auto* fb = exactly<P::FunctionBlockDeclContext>(c)) {
        out->kind = PouKind::FunctionBlock;
        out->name = text(fb->identifier());
        out->nameLoc = loc(fb->identifier());
        modifiers(fb->modifier(), out->access, out->abstract, out->final);
        auto names = fb->qualifiedName();
        size_t next = 0;
        if (fb->EXTENDS() && next < names.size()) out->extends = text(names[next++]);
        for (; next < names.size(); ++next) out->implements.push_back(text(names[next]));
        addElements(fb->pouElement());
        stmtList(fb->stmtList(), out->body);
        for (auto* m : fb->memberDecl()) member(m, *out, false);
        out->endLoc = loc(fb->END_FUNCTION_BLOCK() ? fb->END_FUNCTION_BLOCK()->getSymbol() : c->getStop());
    } else if (auto* itf = exactly<P::InterfaceDeclContext>(c)) {
        out->kind = PouKind::Interface;
        out->name = text(itf->identifier());
        out->nameLoc = loc(itf->identifier());
        out->hasBody = false;
        for (auto* base : itf->qualifiedName()) out->extendsList.push_back(text(base));
        if (!out->extendsList.empty()) out->extends = out->extendsList.front();
        for (auto* m : itf->memberDecl()) member(m, *out, true);
        out->endLoc = loc(itf->END_INTERFACE() ? itf->END_INTERFACE()->getSymbol() : c->getStop());
    } else {
        return nullptr;  // nothing recognisable; the syntax error is reported
    }
    return out;
}

void AstBuilder::member(P::MemberDeclContext* c, Pou& owner, bool inInterface) {
    if (auto* m = c->methodDecl()) owner.methods.push_back(method(m, owner.nameSpace, inInterface));
    else if (auto* a = c->actionDecl()) {
        if (inInterface) error(loc(a), "an INTERFACE cannot have an ACTION");
        else owner.methods.push_back(action(a, owner.nameSpace));
    }
    else if (auto* p = c->propertyDecl()) owner.properties.push_back(property(p, owner.nameSpace, inInterface));
}

std::unique_ptr<Pou> AstBuilder::method(P::MethodDeclContext* c, const std::string& nameSpace, bool inInterface) {
    auto out = std::make_unique<Pou>();
    out->kind = PouKind::Method;
    out->loc = loc(c);
    out->nameSpace = nameSpace;
    out->pragmas = pragmasBefore(c->getStart());
    out->name = text(c->identifier());
    out->nameLoc = loc(c->identifier());
    modifiers(c->modifier(), out->access, out->abstract, out->final);
    if (c->returnType()) out->returnType = returnType(c->returnType());
    for (auto* v : c->varBlock()) out->vars.push_back(varBlock(v));
    stmtList(c->stmtList(), out->body);
    out->hasBody = !(inInterface || out->abstract);
    if (!out->hasBody && !out->body.empty()) {
        error(out->body.front()->loc, inInterface ? "a method of an INTERFACE has no body (statements found in '" +
                                                        out->name + "')"
                                                  : "the ABSTRACT method '" + out->name + "' cannot have a body");
        out->body.clear();
    }
    out->endLoc = loc(c->END_METHOD() ? c->END_METHOD()->getSymbol() : c->getStop());
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
    out->name = text(c->identifier());
    out->nameLoc = loc(c->identifier());
    stmtList(c->stmtList(), out->body);
    out->hasBody = true;
    out->endLoc = loc(c->END_ACTION() ? c->END_ACTION()->getSymbol() : c->getStop());
    return out;
}

Property AstBuilder::property(P::PropertyDeclContext* c, const std::string& nameSpace, bool inInterface) {
    Property out;
    out.loc = loc(c);
    out.name = text(c->identifier());
    out.pragmas = pragmasBefore(c->getStart());
    modifiers(c->modifier(), out.access, out.abstract, out.final);
    if (c->typeSpec()) out.type = typeSpec(c->typeSpec());
    const bool prototype = inInterface || out.abstract;

    auto accessor = [&](antlr4::ParserRuleContext* ctx, const char* name, const std::vector<P::VarBlockContext*>& vars,
                        P::StmtListContext* body, antlr4::tree::TerminalNode* end) {
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
            error(pou->body.front()->loc, "the " + std::string(name) + " accessor of property '" + out.name +
                                              "' cannot have a body here (interface or ABSTRACT)");
            pou->body.clear();
        }
        pou->endLoc = loc(end ? end->getSymbol() : ctx->getStop());
        return pou;
    };

    for (auto* a : c->propertyAccessor()) {
        if (auto* g = exactly<P::PropertyGetterContext>(a)) {
            if (out.getter) error(loc(g), "property '" + out.name + "' has more than one GET");
            out.getter = accessor(g, "GET", g->varBlock(), g->stmtList(), g->END_GET());
        } else if (auto* s = exactly<P::PropertySetterContext>(a)) {
            if (out.setter) error(loc(s), "property '" + out.name + "' has more than one SET");
            out.setter = accessor(s, "SET", s->varBlock(), s->stmtList(), s->END_SET());
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
    for (auto* e : c->typeEntry()) {
        TypeDecl decl;
        decl.loc = loc(e);
        decl.name = text(e->identifier());
        decl.nameLoc = loc(e->identifier());
        decl.nameSpace = nameSpace;
        if (e->qualifiedName()) decl.extends = text(e->qualifiedName());
        // Pragmas in front of TYPE belong to its first entry.
        if (first) decl.pragmas = pragmasBefore(c->getStart());
        for (auto& p : pragmasBefore(e->getStart())) decl.pragmas.push_back(std::move(p));
        first = false;
        decl.spec = typeSpec(e->typeSpec());
        if (e->initializer()) decl.init = initializer(e->initializer());
        if (!decl.extends.empty() && decl.spec && decl.spec->kind != TypeSpecKind::Struct)
            error(decl.loc, "EXTENDS in a TYPE is only allowed for a STRUCT ('" + decl.name + "')");
        unit.types.push_back(std::move(decl));
    }
}

// ---------------------------------------------------------------- configuration

Configuration AstBuilder::configuration(P::ConfigurationContext* c) {
    Configuration out;
    out.loc = loc(c);
    out.name = text(c->identifier());
    for (auto* e : c->configElement()) {
        if (auto* v = e->varBlock()) out.globals.push_back(varBlock(v));
        else if (auto* r = e->resource()) out.resources.push_back(resource(r));
        else if (auto* t = e->taskDecl()) out.tasks.push_back(task(t));
        else if (auto* p = e->programConfig()) out.programs.push_back(programConfig(p));
    }
    return out;
}

Resource AstBuilder::resource(P::ResourceContext* c) {
    Resource out;
    out.loc = loc(c);
    out.name = text(c->identifier());
    out.on = text(c->qualifiedName());
    for (auto* e : c->resourceElement()) {
        if (auto* v = e->varBlock()) out.globals.push_back(varBlock(v));
        else if (auto* t = e->taskDecl()) out.tasks.push_back(task(t));
        else if (auto* p = e->programConfig()) out.programs.push_back(programConfig(p));
    }
    return out;
}

TaskDecl AstBuilder::task(P::TaskDeclContext* c) {
    TaskDecl out;
    out.loc = loc(c);
    out.name = text(c->anyName());
    for (auto* p : c->taskParam()) {
        TaskParam param;
        param.loc = loc(p);
        param.name = text(p->anyName());
        param.value = p->expression() ? expr(p->expression()) : placeholder(param.loc);
        out.params.push_back(std::move(param));
    }
    return out;
}

ProgramConfig AstBuilder::programConfig(P::ProgramConfigContext* c) {
    ProgramConfig out;
    out.loc = loc(c);
    if (auto* p = exactly<P::ProgramInstanceContext>(c)) {
        out.isProgram = true;
        out.instance = text(p->identifier());
        out.task = text(p->anyName());
        out.typeName = text(p->qualifiedName());
        out.args = args(p->argList());
    } else if (auto* b = exactly<P::FbTaskBindingContext>(c)) {
        out.isProgram = false;
        out.instance = text(b->identifier());
        out.task = text(b->anyName());
    }
    return out;
}

}  // namespace strun::ast
