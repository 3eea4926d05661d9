// Parse (generated from grammar/STParser.g4) -> AST (ast.h).
// Walks the typed contexts of the generated parser through their labels and
// start/stop tokens only (the parser keeps no child lists: decision 0159);
// every node gets the location of its first character. Robust against the
// partial contexts ANTLR leaves behind after a syntax error (any label may
// be null): it then builds what it can, the error has already been reported.
//
// Also the place for checks the grammar keeps permissive on purpose so that
// the message can be specific: `x S= 1` with an operator other than S/R/REF,
// an expression used as a statement, a body in an interface method, ...
#pragma once

#include <string>
#include <typeinfo>
#include <vector>

#include "grammar/STParser.h"
#include "interpreter/ast/ast.h"
#include "interpreter/ast/syntax_errors.h"
#include "interpreter/source/source_set.h"

namespace strun::ast {

// Deepest expression tree the builder produces (left-deep chains such as
// `a + b + c ...` are parsed iteratively, so this is where they are capped).
inline constexpr int kMaxExpressionDepth = 2000;

// `c` as a T if it is exactly a T, else null. The contexts the generated
// parser makes for labelled alternatives and plain rules have no subclasses,
// so comparing the dynamic type is enough, and far cheaper than dynamic_cast's
// walk of the class hierarchy (which compares type names with strcmp on every
// miss; it was a fifth of the AST builder). Not for a rule's base context
// with labelled alternatives (StatementContext, TypeSpecContext, ...).
template <typename T, typename C>
T* exactly(C* c) {
    return c != nullptr && typeid(*c) == typeid(T) ? static_cast<T*>(c) : nullptr;
}

class AstBuilder {
public:
    using P = strun_grammar::STParser;

    // `tokens`: the stream the tree was parsed from (pragmas are read from
    // its PRAGMAS channel). Errors go through `errors`, which keeps one
    // message per line, so a statement the parser already complained about
    // gets no second message from the builder.
    AstBuilder(antlr4::BufferedTokenStream& tokens, SyntaxErrorReporter& errors, int fileIndex)
        : tokens_(tokens), errors_(errors), file_(fileIndex) {}

    CompilationUnit build(P::CompilationUnitContext* tree);

private:
    // ---- declarations (ast_builder.cpp)
    void topLevelItem(P::TopLevelItemContext* c, const std::string& nameSpace, CompilationUnit& unit);
    std::unique_ptr<Pou> pou(P::PouDeclContext* c, const std::string& nameSpace);
    std::unique_ptr<Pou> method(P::MethodDeclContext* c, const std::string& nameSpace, bool inInterface);
    std::unique_ptr<Pou> action(P::ActionDeclContext* c, const std::string& nameSpace);
    Property property(P::PropertyDeclContext* c, const std::string& nameSpace, bool inInterface);
    void member(P::MemberDeclContext* c, Pou& owner, bool inInterface);
    void typeDecl(P::TypeDeclContext* c, const std::string& nameSpace, CompilationUnit& unit);
    Configuration configuration(P::ConfigurationContext* c);
    Resource resource(P::ResourceContext* c);
    TaskDecl task(P::TaskDeclContext* c);
    ProgramConfig programConfig(P::ProgramConfigContext* c);
    void modifiers(const std::vector<P::ModifierContext*>& mods, Access& access, bool& isAbstract, bool& isFinal);

    // ---- variables, types, initial values (ast_builder_types.cpp)
    VarBlock varBlock(P::VarBlockContext* c);
    VarDecl varDecl(P::VarDeclContext* c, VarSection section);
    VarDecl accessDecl(P::AccessDeclContext* c);
    TypeSpecPtr typeSpec(P::TypeSpecContext* c);
    TypeSpecPtr returnType(P::ReturnTypeContext* c);
    std::vector<Range> arrayRanges(const std::vector<P::ArrayRangeContext*>& ranges);
    template <typename ArrayForm, typename PointerForm, typename ReferenceForm, typename StringForm, typename Context,
              typename Element>
    bool sharedTypeForm(Context* c, TypeSpec& out, Element&& element);
    TypeSpecPtr namedType(P::QualifiedNameContext* c);
    std::vector<ExprPtr> genericArguments(P::GenericArgumentsContext* c);
    EnumValue enumValue(P::EnumValueContext* c);
    InitPtr initializer(P::InitializerContext* c);
    static void repetitionByName(ArrayInitItem& item);

    // ---- statements (ast_builder_stmt.cpp)
    void stmtList(P::StmtListContext* c, StmtList& out);
    void statements(const std::vector<P::StatementContext*>& list, StmtList& out);
    StmtPtr stmt(P::StatementContext* c);
    StmtPtr exprStmt(P::ExprStmtContext* c);
    // The inner assignments of a chain `a := b := c := 1;`, innermost first,
    // waiting to be put before the statement exprStmt returns.
    void flushChained(StmtList& out);
    StmtList chained_;
    void caseBranches(const std::vector<P::StatementContext*>& items, Stmt& out);
    CaseLabel caseLabel(P::ExpressionContext* lo, const antlr4::Token* dots, P::ExpressionContext* hi, const Loc& at);

    // ---- expressions (ast_builder_expr.cpp)
    ExprPtr expr(P::ExpressionContext* c);
    ExprPtr unary(P::UnaryExprContext* c);
    // The name token if the expression is just a name, else null.
    static const antlr4::Token* bareName(P::ExpressionContext* c);
    static const antlr4::Token* bareName(P::UnaryExprContext* c);
    ExprPtr postfix(P::PostfixExpressionContext* c);
    ExprPtr primary(P::PostfixExpressionContext* c);  // the part before the postfix operators
    ExprPtr literal(const antlr4::Token* token);
    std::vector<Arg> args(P::ArgListContext* c);
    ExprPtr placeholder(const Loc& at);  // stands in for what a syntax error left out
    ExprPtr tooComplex(const Loc& at);  // an expression deeper than kMaxExpressionDepth: reported once

    // ---- helpers
    Loc loc(const antlr4::Token* token) const;
    Loc loc(antlr4::ParserRuleContext* c) const;
    std::string text(antlr4::ParserRuleContext* c) const;  // its tokens' text; "" for a missing node
    static std::string sourceText(antlr4::ParserRuleContext* c);  // as written, shortened for messages
    std::vector<Pragma> pragmasBefore(const antlr4::Token* token);
    const antlr4::Token* previousOnChannel(const antlr4::Token* token) const;  // null at the start
    Diagnostic& error(diag::Code code, const Loc& at, const std::string& message);

    antlr4::BufferedTokenStream& tokens_;
    SyntaxErrorReporter& errors_;
    int file_;
    int exprDepth_ = 0;
    bool depthReported_ = false;
};

}  // namespace strun::ast
