// One compile of an editor's project and what the language server answers
// from it: the declarations (symbols) with their positions, and every place
// that names one (occurrences). Declarations come from the AST; what a name
// in a body refers to comes from the checker itself (sema::ExprObserver:
// the variable or the type it resolved), so hover, definition, references,
// document symbols and completion all read one model, the one `check` builds.
//
// Positions here are those of the compiled text (1-based line, code-point
// column); for TwinCAT and PLCopen files the server converts them to and from
// the XML file's own (SourceFile::original, userPosition).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "interpreter/ast/ast.h"
#include "interpreter/project/compile.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/compile_options.h"
#include "interpreter/sema/expr_observer.h"
#include "interpreter/sema/program_model.h"
#include "interpreter/source/source_set.h"

namespace strun::editors::lsp {

enum class SymbolKind {
    Program, Function, FunctionBlock, Method, Action, Property, Interface,
    Struct, Enum, Alias, EnumValue, Variable, Field, GlobalList, Configuration,
};

struct Symbol {
    SymbolKind kind = SymbolKind::Variable;
    std::string name;
    ast::Loc loc;        // where the name is written
    ast::Loc start;      // the whole declaration (document symbols)
    ast::Loc end;
    int parent = -1;     // enclosing symbol (POU of a variable, FB of a method)
    std::string detail;  // a variable's type, a POU's signature
    ast::VarSection section = ast::VarSection::Var;
    const ast::Pou* pou = nullptr;         // POU symbols
    const ast::TypeSpec* typeSpec = nullptr;  // variables and fields: the declared type
    std::vector<std::string> params;       // POU symbols: "name : TYPE" of the inputs, in-outs, outputs
};

struct Occurrence {
    int line = 0, col = 0, length = 0;  // compiled-text position of the name
    int symbol = -1;
    bool declaration = false;
};

class ProjectIndex : private sema::ExprObserver {
public:
    // Compiles `sources` (the user's files `userFiles`, parsed already:
    // `userUnits`, their syntax diagnostics in `log`) and indexes them.
    // `sources` starts with a copy of `library`'s files, whose parsed units
    // are lent to the compile (parse_cache.h, decision 0270).
    ProjectIndex(std::unique_ptr<SourceSet> sources, std::vector<int> userFiles, CompileLog log, const sema::CompileOptions& options,
                 project::ParsedLibrary& library, std::map<int, std::shared_ptr<ast::CompilationUnit>> userUnits);
    ~ProjectIndex() override;

    const SourceSet& sources() const { return *sources_; }
    const CompileLog& log() const { return log_; }
    const std::vector<Symbol>& symbols() const { return symbols_; }
    const std::vector<int>& userFiles() const { return userFiles_; }
    // True when the checker ran (false after syntax errors it cannot check past).
    bool checked() const { return model_ != nullptr; }

    // The occurrence at a compiled-text position of `file`, if any.
    const Occurrence* occurrenceAt(int file, int line, int col) const;
    // Every occurrence of `symbol` as (file, occurrence).
    std::vector<std::pair<int, Occurrence>> occurrencesOf(int symbol) const;
    // The innermost POU symbol whose declaration spans the position; -1 if none.
    int pouAt(int file, int line) const;
    // The symbols a name visible at the position may refer to (variables in
    // scope, globals, POUs, types): for completion.
    std::vector<int> visibleAt(int file, int line) const;
    // Resolves a dotted chain written at the position ("fb.inner" of
    // "fb.inner.") to the members of its type; empty if unknown.
    std::vector<int> membersOfChain(int file, int line, const std::vector<std::string>& chain) const;
    // The POU (function, FB type or method) a call written as `chain(` at the
    // position calls; -1 if unknown.
    int calleeOfChain(int file, int line, const std::vector<std::string>& chain) const;
    // The symbol declared at `loc` (a name position), -1 if none.
    int symbolAt(const ast::Loc& loc) const;
    // The compiled-text position of a position in the file the user has.
    std::pair<int, int> compiledPosition(int file, int line, int col) const;

private:
    void checked(const ast::Expr& e, const sema::Checked& c, const sema::PouInfo* pou) override;
    // ---- declarations
    int add(Symbol s, bool occurrence = true);
    void collectUnit(const ast::CompilationUnit& unit);
    void collectPou(const ast::Pou& pou, int parent, bool isMethod);
    void collectVars(const std::vector<ast::VarBlock>& blocks, int parent);
    void collectType(const ast::TypeDecl& decl);
    // ---- references
    void resolveUnit(const ast::CompilationUnit& unit);
    void resolvePou(const ast::Pou& pou);
    void resolveStmts(const ast::StmtList& list, const sema::PouInfo* pou);
    void resolveStmt(const ast::Stmt& s, const sema::PouInfo* pou);
    void resolveExpr(const ast::Expr& e, const sema::PouInfo* pou);
    void resolveInit(const ast::Init* init, const sema::PouInfo* pou);
    void resolveTypeSpec(const ast::TypeSpec* spec);
    void addReference(const ast::Loc& at, const std::string& name, int symbol);
    int symbolOfVar(const sema::VarSym* v) const;
    int memberOfType(const sema::Type* t, const std::string& upperName) const;
    int byName(const std::string& upperName, const sema::PouInfo* pou) const;
    int typeSymbol(const std::string& upperName) const;
    const sema::Type* typeOfName(const std::string& upperName, const sema::PouInfo* scope) const;
    const sema::Type* typeOfChain(int file, int line, const std::vector<std::string>& chain) const;
    void membersOfType(const sema::Type* t, bool inside, std::vector<int>& out) const;
    const sema::PouInfo* pouInfoAt(int file, int line) const;
    const sema::PouInfo* pouInfoOf(const ast::Pou* pou) const;
    sema::VarSym* lookupVar(const sema::PouInfo* pou, const std::string& upperName) const;

    std::unique_ptr<SourceSet> sources_;
    std::vector<int> userFiles_;
    std::set<int> userFileSet_;
    CompileLog log_;
    std::map<int, std::shared_ptr<ast::CompilationUnit>> userUnits_;  // shared with the parse cache
    std::unique_ptr<sema::ProgramModel> model_;
    struct Seen {
        const sema::Type* type = nullptr;
        const sema::VarSym* var = nullptr;
    };
    std::unordered_map<const ast::Expr*, Seen> seen_;
    std::vector<Symbol> symbols_;
    std::map<std::tuple<int, int, int>, int> byLoc_;          // name position -> symbol
    std::multimap<std::string, int> globalNames_;             // upper-case name -> POU, type, global, program instance
    std::map<std::string, int> enumValues_;                   // "TYPE.VALUE" upper-case -> symbol
    std::map<const ast::Pou*, const sema::PouInfo*> pouInfos_;
    std::unordered_map<std::string, const sema::PouInfo*> topPous_;  // upper-case name -> POU (not methods)
    std::unordered_map<std::string, sema::VarSym*> globalVars_;      // upper-case name -> global
    std::map<int, std::vector<Occurrence>> occurrences_;      // file -> sorted by position
};

}  // namespace strun::editors::lsp
