// The checker: declarations -> types and storage layout -> checked, resolved
// tree. It reports every error with a location to the CompileLog and keeps
// going, so one run shows as many errors as possible.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "interpreter/ast/ast.h"
#include "interpreter/sema/builtin_registry.h"
#include "interpreter/sema/compile_options.h"
#include "interpreter/sema/program_model.h"
#include "interpreter/sema/symbols.h"
#include "interpreter/source/source_set.h"
#include "runtime/plc_profile.h"

namespace strun::sema {

// SIMATIC AX caller-information pragmas on an input (caller_info.cpp).
enum class CallerInfo { None, FilePath, LineNumber };
CallerInfo callerInfoOf(const VarSym* p);

class Checker;
class ExprObserver;

// What a standard-library binding sees of a call (interpreter/builtins/).
struct CallArgs {
    const ast::Expr* call = nullptr;
    std::string name;             // upper-case callee name
    std::vector<Checked> args;    // positional order (formal args placed by their name when known)
    std::vector<std::string> names;  // formal names as written (upper-case), "" if positional
    ast::Loc loc;
    std::vector<Checked> replaced;   // earlier values of an input named twice that call something (decision 0426)
};

class Checker {
public:
    Checker(ProgramModel& model, CompileLog& log);
    // Checks every unit; fills the model (program instances, tasks, code).
    void run(std::vector<ast::CompilationUnit>& units);
    // --target / --strict (set before run()).
    void setCompileOptions(const CompileOptions& options) {
        options_ = options;
        if (options.twincatDurations) types().makeDurationsUnsigned();  // decision 0367
        if (options.axStrings) types().setDefaultStringLength(254);     // SIMATIC AX (decision 0394)
    }
    const CompileOptions& compileOptions() const { return options_; }

    // ---- services for standard-library bindings
    exec::NodePool& pool() { return model_.pool; }
    TypeTable& types() { return *model_.types; }
    CompileLog& log() { return log_; }
    // The code first (decision 0298): error(diag::E0101, loc, "undeclared identifier 'x'").
    // In a generic block's specialisation the error says which one it is.
    Diagnostic& error(diag::Code code, const ast::Loc& loc, const std::string& message) {
        if (silent_) return silenced();
        const PouInfo* s = specialisationBeingChecked();
        // An error of a generic block's own code repeats in each specialisation:
        // reported for the first only, so that a self-nesting block with one bad
        // line gives one message, not one per level (fuzzing found 1 000).
        if (s && !specialisationErrors_.insert({loc.file, loc.line, loc.col, message}).second) {
            discarded_ = Diagnostic{};
            return discarded_;
        }
        Diagnostic& d = log_.error(code, loc, message);
        if (s) d.note("in the specialisation '" + s->name + "'");
        return d;
    }
    // A warning, unless `loc` is in strun's embedded library (its sources are
    // never shown to users) or in a generic block's specialisation (the block
    // itself was warned about).
    Diagnostic& warning(diag::Code code, const ast::Loc& loc, const std::string& message) {
        if (silent_) return silenced();
        if (!libraryFiles_.count(loc.file) && !specialisationBeingChecked()) return log_.warning(code, loc, message);
        discarded_ = Diagnostic{};
        return discarded_;
    }
    // What CODESYS accepts and IEC 61131-3 does not (implicit narrowing, a constant
    // expression that wraps): a warning by default, an error with --strict
    // (decision 0090). Returns false when it was an error. The embedded library
    // is always checked in the default mode.
    // The error keeps the warning's code (W0001, W0002).
    bool lenient(diag::Code code, const ast::Loc& loc, const std::string& message, const std::string& errorHint = "") {
        if (options_.strict && !libraryFiles_.count(loc.file)) { error(code, loc, message + errorHint); return false; }
        warning(code, loc, message);
        return true;
    }
    // A CODESYS/TwinCAT/AX form IEC 61131-3 does not have, which the default
    // mode accepts silently: with --strict an error (outside the embedded
    // library), and true. The message says what to write instead.
    bool refusedByStrict(diag::Code code, const ast::Loc& loc, const std::string& message) {
        if (!options_.strict || libraryFiles_.count(loc.file)) return false;
        error(code, loc, message);
        return true;
    }
    // Converts `e` implicitly to `target` (errors if the standard forbids it).
    Checked coerce(Checked e, const Type* target, const ast::Loc& loc, const char* what);
    // Explicit conversion (X_TO_Y / TO_Y): any elementary pair.
    Checked convert(Checked e, const Type* target, const ast::Loc& loc, bool truncate = false);
    // A POINTER's value as its address, a ULINT (TO_STRING(pValue), TO_DT(pValue);
    // decision 0326); anything else unchanged.
    static Checked pointerAsAddress(Checked e, const Type* ulint) {
        if (!e.ok || e.type->kind != TK::Pointer) return e;
        e.type = ulint;
        if (e.node) e.node->type = ulint;
        e.isPlace = false;
        e.var = nullptr;
        return e;
    }
    // The type two operands are brought to by an arithmetic/comparison operator; null if none.
    const Type* commonType(Checked& a, Checked& b, const ast::Loc& loc, bool reportError = true);
    // Fixes the type of an untyped literal (ANY_INT -> DINT/LINT, ANY_REAL -> LREAL).
    Checked settle(Checked e);
    Checked constInt(int64_t v, const Type* t, const ast::Loc& loc);
    Checked constantString(std::vector<uint8_t> bytes, size_t len, bool wide, const ast::Loc& loc);
    Checked constReal(double v, const Type* t, const ast::Loc& loc);
    Checked bad(const ast::Loc& loc) { Checked c; c.loc = loc; return c; }
    exec::Site site(const ast::Loc& loc);
    // A caller-frame temporary of `size` bytes for aggregate results; returns its offset.
    uint32_t allocTemp(uint32_t size);
    // The inferred temporaries of translated IL bodies (decision 0415).
    VarSym* inferredTemp(const ast::Expr& target);
    void fixInferredTemp(VarSym* v, const Type* t);
    // The value an inferred temporary gets first (decision 0415), typed for it.
    Checked inferredValue(const ast::Expr& value);
    // A temporary read before, in the text, its first assignment (an IL label
    // reached only by a backward jump): typed from that assignment (decision 0467).
    bool typeInferredTempAhead(VarSym* v);
    bool typingAhead_ = false;
    // A fresh aggregate place in the current frame's temporaries with the given type.
    exec::Expr* tempPlace(const Type* t, uint32_t* offsetOut = nullptr);
    // Bindings the operators `+` / `-` on dates and times of day delegate to.
    static constexpr const char* kDateAddOperator = "operator +";
    static constexpr const char* kDateSubOperator = "operator -";
    // Registry of built-in functions (name upper-case).
    void addBuiltin(std::string_view upperName, const BuiltinFn& fn) { builtins_.add(upperName, fn); }
    bool hasBuiltin(std::string_view upperName) const { return builtinTable().find(upperName) != nullptr; }
    // What fills the registry (addBuiltin for every built-in), run on the
    // first look-up of a built-in name rather than before checking: a
    // program that names none does not build the ~600 entries (decision 0478).
    void setBuiltinRegistrar(std::function<void(Checker&)> registrar) { builtinRegistrar_ = std::move(registrar); }
    // Another name for a parameter of a library POU (IEC `SR.S1` vs CODESYS `SR.SET1`).
    void addParameterAlias(const std::string& upperPou, const std::string& upperAlias, const std::string& upperParam) {
        parameterAliases_[upperPou][upperAlias] = upperParam;
    }
    // The parameter `upperName` stands for in `pou`, or `upperName` itself.
    std::string canonicalParameter(const PouInfo* pou, const std::string& upperName) const;
    // Makes a node yielding the value stored at `place` (a PlaceLoad of the right width).
    exec::Expr* loadFrom(exec::Expr* place, const Type* t);
    // Stores `value` (already of type t) into `place`.
    exec::Stmt* storeTo(exec::Expr* place, const Type* t, exec::Expr* value, int bit = -1);
    const std::string* currentPouName() const { return currentPouName_; }
    // "did you mean '...'?" on `d` when a name in `declared` is close to `typed` (checker_suggest.cpp).
    void suggestName(Diagnostic& d, const std::string& typed, const std::vector<std::string>& declared) const { suggest(d, typed, declared); }

private:
    friend struct CheckerAccess;
    CompileOptions options_;
    // ---- declarations (checker_declare.cpp)
    void collect(ast::CompilationUnit& unit);
    void declarePou(ast::Pou* pou, PouInfo* owner);
    const Type* resolveTypeSpec(const ast::TypeSpec* spec, const std::string& context);
    const Type* resolveNamedType(const std::string& name, const ast::Loc& loc);
    const Type* resolveTypeDecl(const std::string& upperName, const ast::Loc& loc);
    void layoutPou(PouInfo* pou);
    void layOutDeferredMethods();
    void declareVars(PouInfo* pou, const std::vector<ast::VarBlock>& blocks, uint32_t& instOff, uint32_t& frameOff,
                     std::vector<Field>* instanceFields, bool instOnly = false);
    void declareGlobals();
    void foldConstant(VarSym& v, const ast::VarDecl& decl);
    void foldStringConstant(VarSym& v, const ast::VarDecl& decl);  // checker_constant_strings.cpp
    VarSym* addGlobal(const ast::VarDecl& decl, size_t nameIndex, const ast::VarBlock& block, uint32_t& listSize);
    bool constIntExpr(const ast::Expr* e, int64_t& out, const char* what);
    bool isConstantInteger(const ast::Expr& e);
    bool isAddressInit(const VarSym* v) const;
    exec::Stmt* addressInitStmt(const RuntimeInit& init);
    std::vector<RuntimeInit> globalAddressInits_;
    std::vector<RuntimeInit> staticInits_;  // VAR_STAT parts initialised at run time, checked in their POU
    // ---- initial values computed at initialisation (checker_runtime_init.cpp)
    // While writing the initial value of `runtimeInitVar_`: where a part that is
    // not a compile-time constant goes (null: it is an error), and the path
    // from the variable to the part being written.
    struct InitPathStep {
        std::string member;       // a structure member, or
        const Type* array = nullptr;  // an element of this array type ...
        uint64_t element = 0;     // ... at this flat position
    };
    std::vector<RuntimeInit>* runtimeInits_ = nullptr;
    VarSym* runtimeInitVar_ = nullptr;
    std::vector<InitPathStep> initPath_;
    void writeVarInitial(uint8_t* p, VarSym* v, std::vector<RuntimeInit>* runtime);
    bool deferInitial(const ast::Expr& value);
    std::string qualifiedOnlyList_;   // while declaring a {attribute 'qualified_only'} global list: its name
    bool qualifiedAccess_ = false;    // while resolving the member of `LIST.name`
    std::string qualifiedList_;       // ... and LIST, upper-case
    std::string declaringList_;       // while declaring a named global list: its name
    std::map<std::string, VarSym*> listGlobals_;  // "LIST.NAME" (upper-case) of every named list's global
    void ambiguousGlobal(const VarSym* v, const ast::Loc& loc, const std::string& written);
    void writeInitial(uint8_t* base, const Type* t, const ast::Init* init, const ast::Loc& loc);
    void writeLocatedInitial(const VarSym& v, const ast::Init* init, const ast::Loc& loc);
    void writeDefault(uint8_t* base, const Type* t);
    void writeScalar(uint8_t* p, const Type* t, const Checked& v);
    uint8_t* mapAddress(const std::string& address, const Type* t, const ast::Loc& loc, int& bit);
    bool externalInput(const ast::Expr& value, rt::TaskSpec& spec);
    uint8_t* mapSystemAddress(const std::string& address, const Type* t, const ast::Loc& loc, int& bit);
    // %IW2.5.7, %QX1.2.3.4: IEC hierarchical addresses, one location per path (checker_hierarchical_address.cpp)
    uint8_t* mapHierarchicalAddress(rt::ImageArea& area, const std::string& address, const std::vector<uint64_t>& parts, uint64_t unit,
                                    const Type* t, const ast::Loc& loc, int& bit);
    struct HierarchicalSlot { size_t offset, size; };
    std::map<std::string, HierarchicalSlot> hierarchicalSlots_;  // "IW2.5.7" -> its place at the top of its area
    std::map<const rt::ImageArea*, size_t> hierarchicalUsed_, flatEnd_;  // bytes taken at the top / below

    // ---- cycles and depth of declarations (checker_cycles.cpp)
    void breakInheritanceCycles();
    bool rejectByValueCycle(const Type* t, const ast::Loc& loc);
    std::string cyclePath(const std::string& name) const;
    // Type declarations and POUs whose resolution is in progress, outermost first.
    std::vector<std::string> declStack_;
    bool declDepthExceeded_ = false;  // kMaxDeclarationDepth was reported
    friend class DeclDepthGuard;

    // ---- object orientation (checker_oop.cpp)
    int methodSlot(const std::string& upperName);
    void buildClasses();
    void collectInterfaces(PouInfo* itf, std::vector<PouInfo*>& out);
    PouInfo* findMethod(PouInfo* owner, const std::string& upperName);
    bool isSuiteBuiltinCall(const ast::Expr& callee);  // THIS^.AssertTrue(...) in a TcUnit suite (checker_call.cpp)
    Checked methodCall(Checked base, PouInfo* method, const ast::Expr& call);
    Checked checkThis(const ast::Expr& e, bool deref);
    Checked propertyAccess(Checked base, const std::string& upperName, const ast::Loc& loc, bool& found);
    // `x` inside a block that has a PROPERTY x: THIS^.x (decision 0440).
    Checked ownProperty(const std::string& upperName, const ast::Loc& loc, bool& found);
    bool hasOwnProperty(const std::string& upperName);
    exec::Stmt* assignProperty(Checked target, Checked value, const ast::Loc& loc);
    Checked autoDeref(Checked c);
    Checked derefReference(Checked c);
    Checked addressOf(const ast::Expr& e, const char* fn);
    std::map<std::string, int> methodSlots_;
    bool suppressAutoDeref_ = false;
    // Set while the operand of ADR()/REF() is checked: a CONSTANT named there
    // is its storage, not its folded value (decision 0475).
    bool addressOperand_ = false;

    // ---- configuration (checker_config.cpp)
    void buildConfiguration();
    void sizeTaskInfoToTasks();  // Tc2_System's _TaskInfo[] bound = task count (checker_task_info.cpp)
    void addTestProgram(const std::string& name);
    void declareMethodInstanceVars(PouInfo* fb, uint32_t& instOff, std::vector<Field>& fields);
    void buildDefaultConfiguration();
    void instantiateProgram(const std::string& name, PouInfo* pou, const ast::Loc& loc);
    // The program instance of that upper-case name, or null (hashed: a name is looked up per identifier).
    const ProgramInstance* findProgram(const std::string& upperName) const {
        auto it = programIndex_.find(upperName);
        return it == programIndex_.end() ? nullptr : &model_.programs[it->second];
    }

    // ---- bodies (checker_stmt.cpp / checker_expr.cpp / checker_call.cpp)
    void checkBodies();
    void checkBody(PouInfo* pou);
    exec::Block* checkBlock(const ast::StmtList& list);
    exec::Stmt* checkStmt(const ast::Stmt& s);
    exec::Stmt* checkAssign(const ast::Stmt& s);
    exec::Stmt* checkFor(const ast::Stmt& s);
    exec::Stmt* checkRefAssign(const ast::Stmt& s);
    exec::Stmt* checkConditionalReturn(const ast::Stmt& s);
    exec::Stmt* checkCase(const ast::Stmt& s);
    Checked checkExpr(const ast::Expr& e);
    Checked checkExprOfKind(const ast::Expr& e);
    Checked checkCondition(const ast::Expr& e, const char* what);
    Checked checkLiteral(const ast::Expr& e);
    Checked checkName(const ast::Expr& e);
    Checked checkMember(const ast::Expr& e);
    Checked checkMemberBase(const ast::Expr& base);
    Checked checkMethodBase(const ast::Expr& base);
    Checked checkIndex(const ast::Expr& e);
    // TwinCAT/CODESYS forms (checker_lang_forms.cpp): s[i] on a STRING, p[i] on a
    // POINTER, `(x := v)` used as a value.
    Checked checkStringOrPointerIndex(const ast::Expr& e, const Checked& base);
    // CASE on CHAR / STRING selectors (SIMATIC AX, checker_case_text.cpp).
    exec::Expr* caseTextSelector(const Checked& sel);
    bool caseTextLabel(exec::Expr* key, const Type* selector, Checked& label, const ast::Loc& loc, int64_t& out);
    exec::Expr* charAsString(const Checked& ch, const Type* target);
    Checked checkAssignmentValue(const ast::Expr& e);
    std::vector<std::unique_ptr<ast::Stmt>> assignmentValues_;  // statements made from expressions, kept with the checker
    // `fb.A_Act(in := v, out => x)` (checker_action_call.cpp): the block's inputs set, the action run, its outputs read.
    exec::Stmt* callActionWithArguments(const ast::Expr& call, PouInfo* block);
    Checked checkUnary(const ast::Expr& e);
    Checked checkBinary(const ast::Expr& e);
    Checked checkCall(const ast::Expr& e, bool statement);
    Checked checkConversionCall(const std::string& upperName, const ast::Expr& e, bool& handled);
    Checked callUserFunction(PouInfo* fn, const ast::Expr& e, exec::Expr* instance);
    exec::Stmt* bindConstantInOut(VarSym* p, const Checked& v, exec::Expr* slot, const ast::Loc& loc);
    exec::Stmt* bindInOut(VarSym* p, const Checked& v, exec::Expr* slot, const ast::Loc& loc);
    exec::Stmt* bindOutput(const ast::Arg& arg, VarSym* p, Checked src);
    exec::Stmt* bindReference(VarSym* p, const Checked& v, exec::Expr* slot, const ast::Loc& loc);
    exec::Stmt* callFunctionBlock(Checked inst, const ast::Expr& e);
    // Whether some block EXTENDS `fb` (known once every block is laid out).
    bool isExtended(const PouInfo* fb);
    // `inst.FB_init(...)` of a block that declares none: the implicit one (decision 0457).
    bool isImplicitFbInit(const Type* instance, const std::string& member);
    Checked implicitFbInitCall(const Checked& base, const ast::Expr& call);
    std::set<const PouInfo*> extendedBlocks_;
    bool extendedKnown_ = false;
    Checked varAccess(VarSym* v, const ast::Loc& loc, bool fromOutside);
    Checked memberOf(Checked base, const std::string& member, const ast::Loc& loc);
    Checked laterConstant(const std::string& upperName, const ast::Loc& loc);
    Checked earlyGlobalConstant(const std::string& key, const ast::Loc& loc);
    Checked earlyStructureConstant(const ast::VarDecl& decl, const Type* t, const std::string& key, const ast::Loc& loc);
    bool globalsDeclared_ = false;  // declareGlobals has run: global constants are variables from then on
    std::set<std::string> pendingConstants_;
    // Constants read by laterConstant before their VarSym existed: used, for warnUnused.
    std::set<std::pair<const PouInfo*, std::string>> constantsUsedEarly_;
    Checked partialAccess(Checked base, const std::string& key, const std::string& member, const ast::Loc& loc);
    VarSym* lookupVar(const std::string& upperName);
    const Enumerator* lookupEnumValue(const std::string& upperName, const Type** enumType, bool& ambiguous);
    // `e` where a value of `expected` is wanted (an assignment to it, a CASE label of
    // it, the right of a comparison with it): a bare name of one of its values is
    // that value, whatever else is called so (decision 0441); else checkExpr(e).
    Checked checkExprExpecting(const ast::Expr& e, const Type* expected);
    Checked makeArith(ast::Op op, Checked a, Checked b, const ast::Loc& loc);
    Checked makeCompare(ast::Op op, Checked a, Checked b, const ast::Loc& loc);
    Checked makeLogic(ast::Op op, Checked a, Checked b, const ast::Loc& loc);
    void warnConstantComparison(ast::Op op, const Checked& a, const Checked& b, const ast::Loc& loc);
    Checked foldIfConst(Checked r, std::initializer_list<const Checked*> operands);
    exec::Stmt* assignChecked(Checked target, Checked value, const ast::Loc& loc);
    // REF_TO ARRAY[*] (checker_flex_ref.cpp, decision 0402)
    Checked derefFlexibleRef(const Checked& ref, const ast::Loc& loc);
    exec::Stmt* assignFlexibleRef(const Checked& target, const Checked& value, const ast::Loc& loc);
    void markWritten(const Checked& target, const ast::Loc& loc);
    int labelId(const std::string& upperName);
    // True while checking the body or a method of `fb` (or of an FB derived from it).
    bool insideOwnInstance(const PouInfo* fb) const {
        const PouInfo* p = pou_ && pou_->owner ? pou_->owner : pou_;
        for (; p; p = p->parent)
            if (p == fb) return true;
        return false;
    }
    void warnUnused();
    // ---- suggestions and cascades of name errors (checker_suggest.cpp)
    std::string closestDeclared(const std::string& typed, const std::vector<std::string>& declared) const;
    // Adds "did you mean 'X'?" to `d` when a declared name is close to `typed`.
    void suggest(Diagnostic& d, const std::string& typed, const std::vector<std::string>& declared) const;
    // The same with the candidates listed only when `d` will be printed (a
    // list of every type or function name is long, and an error past the
    // log's cap or a repeated one is never shown).
    void suggest(Diagnostic& d, const std::string& typed, std::vector<std::string> (Checker::*candidates)() const) const;
    bool shown(const Diagnostic& d) const { return &d != &discarded_ && !log_.isDropped(d); }
    std::vector<std::string> visibleVariableNames() const;
    std::vector<std::string> typeNames() const;
    std::vector<std::string> globalNames() const;
    std::vector<std::string> functionNames() const;
    // Variables whose declaration failed (unknown type): their uses are not reported again.
    void markUnresolved(const std::string& upperName);
    bool isUnresolved(const std::string& upperName) const;
public:
    // A variable of `pou` (or of a block it extends) whose type was unknown: already
    // reported, so a call naming it as a parameter says nothing more.
    bool isUnresolvedParameter(const PouInfo* pou, const std::string& upperName) const {
        for (const PouInfo* p = pou; p != nullptr; p = p->parent)
            if (unresolvedVars_.count({p, upperName})) return true;
        return false;
    }
    // Whether some variable of `pou` (or of a block it extends) had an unknown type:
    // positional arguments cannot be matched to its inputs then, and are not reported.
    bool hasUnresolvedVariables(const PouInfo* pou) const {
        for (const PouInfo* p = pou; p != nullptr; p = p->parent) {
            auto it = unresolvedVars_.lower_bound({p, std::string()});
            if (it != unresolvedVars_.end() && it->first == p) return true;
        }
        return false;
    }
private:
    // "'X' is not a value of enumeration 'E'" with the values E has and the closest one.
    void enumValueError(const ast::Loc& loc, const std::string& written, const Type* enumType);
    // The instance name a suggestion declares for block type `typeName` (its first letter: t for TON).
    static std::string instanceNameFor(const std::string& typeName);
    std::set<std::pair<const PouInfo*, std::string>> unresolvedVars_;
    // Structure members whose type is unknown: declared for their uses, which
    // are not reported again (one missing type is one error).
    std::set<std::pair<const Type*, std::string>> unresolvedMembers_;
    // ---- CODESYS FB_init (checker_fb_init.cpp)
    void buildFbInitCalls();
    // `enclosing`/`enclosingAddr`: the instance that declares this one, whose
    // variables the FB_init arguments on the declaration may name.
    void collectFbInits(const Type* t, uint8_t* addr, const ast::TypeSpec* declSpec, int depth,
                        PouInfo* enclosing = nullptr, uint8_t* enclosingAddr = nullptr, const ast::Init* declInit = nullptr);
    std::vector<const VarSym*> membersDeclaredInLiterals(PouInfo* fb, const ast::Init& declInit);  // decision 0476
    bool isLiteralInit(const ast::Init& init);
    void collectArrayFbInits(const Type* t, uint8_t* addr, const ast::TypeSpec* declSpec, int depth, PouInfo* enclosing,
                             uint8_t* enclosingAddr);
    bool holdsFbInit(const Type* t);
    bool elementArgsAllowed_ = false;  // resolving the element type of an ARRAY (per-element FB_init arguments)
    static constexpr size_t kMaxFbInitCalls = 100000;
    std::map<const Type*, bool> holdsFbInit_;
    bool fbInitLimitReported_ = false;
    // ---- {attribute 'instance-path'} (checker_instance_path.cpp)
    void writeAllInstancePaths();
    void writeInstancePaths(const Type* t, uint8_t* addr, const std::string& path, int depth);
    bool holdsInstancePath(const Type* t);
    std::map<const Type*, bool> holdsInstancePath_;
    uint64_t instancePathWrites_ = 0;
    // ---- blocks with VAR_GENERIC CONSTANT (checker_generic.cpp)
    // The specialisation of block `name` for the values `args` (evaluated in
    // the current scope), declared on first use; null after an error.
    PouInfo* specialise(const std::string& name, const std::vector<ast::ExprPtr>& args, const ast::Loc& loc);
    const Type* specialisedInstanceType(const ast::TypeSpec& spec);
    static constexpr size_t kMaxSpecialisations = 4096;  // above the nesting limit: self-nesting ends there
    // A generic block's specialisation: only those have '<' in their name (`FB_X<6>`).
    static bool isSpecialisation(const PouInfo* p) { return p->name.find('<') != std::string::npos; }
    // The specialisation whose declarations or body are being checked, or null.
    const PouInfo* specialisationBeingChecked() const {
        const PouInfo* p = pou_ && pou_->owner ? pou_->owner : pou_;
        return p && !genericCopies_.empty() && isSpecialisation(p) ? p : nullptr;
    }
    std::vector<std::unique_ptr<ast::Pou>> genericCopies_;  // the specialisations' declarations
    bool specialisationLimitReported_ = false;
    // ---- small leaf FUNCTIONs, METHODs and block bodies inlined at their calls (checker_inline.cpp, decision 0317)
    struct InlineSite {
        exec::CallPou* call;        // a FUNCTION or METHOD call, or
        exec::CallFbStmt* fbCall;   // a function block's call statement
        PouInfo* callee;
        PouInfo* caller;
        bool onInstance;
        const ast::Expr* expr = nullptr;  // the call as written (its arguments: checker_inline_args.cpp)
    };
    // At the end of checkBody: whether `pou` may be inlined (a small FUNCTION, METHOD or block body,
    // checked without a diagnostic, that calls nothing).
    void noteInlinable(PouInfo* pou, size_t messagesBefore, uint64_t callsBefore);
    // At a FUNCTION call, or a METHOD call on an instance of exactly known
    // class (`onInstance`), in a body: remembered for inlineLeafCalls.
    void noteInlineSite(exec::CallPou* call, PouInfo* fn, bool onInstance, const ast::Expr& e);
    // At the call statement of an instance of exactly known type `fb`.
    void noteInlineSite(exec::CallFbStmt* call, PouInfo* fb);
    // After every body is checked: each remembered call of an inlinable FUNCTION
    // gets the callee's body checked again in an area of the caller's frame.
    void inlineLeafCalls();
    std::vector<InlineSite> inlineSites_;
    // ---- arguments substituted into an inlined body (checker_inline_args.cpp, decision 0403):
    // while the body is checked again, a parameter listed here reads as its
    // argument (a constant, or the caller's variable) instead of its slot.
    struct ArgSubstitute {
        const VarSym* param;
        exec::ArgBind bind;  // Const*: the stored bits; CopySelf* / CopyFrame*: the caller's variable
    };
    std::vector<ArgSubstitute> argSubstitutes_;
    std::vector<ArgSubstitute> argumentSubstitutes(const InlineSite& site);
    Checked substitutedArgument(const ArgSubstitute& s, const ast::Loc& loc);
    void chooseInlinedArgs(exec::InlinedCall& in, const PouInfo& fn, const std::vector<ArgSubstitute>& substitutes);
    bool touchesOnlyOwnFrame(const PouInfo& fn);
    bool writesOnlyOwnFrame(const PouInfo& fn, const ast::StmtList& list);
    bool ownFrameTarget(const PouInfo& fn, const ast::Expr& target);
    bool readsOnly(const ast::Expr& e, bool callerArgument, int depth);
    std::map<const PouInfo*, bool> touchesOnlyOwnFrame_;  // touchesOnlyOwnFrame, once per POU
    PouInfo* inlineCaller_ = nullptr;  // the POU whose body (not an initialiser) is being checked
    uint64_t userCallsMade_ = 0;       // call nodes of user POUs made so far: a body that adds none is a leaf
    uint32_t frameBias_ = 0;           // added to frame variables' offsets while a body is inlined
    bool silent_ = false;              // while a body is inlined: diagnostics are counted, not reported
    uint64_t silencedCount_ = 0;
    Diagnostic& silenced() {
        ++silencedCount_;
        discarded_ = Diagnostic{};
        return discarded_;
    }
    // ---- __NEW, __DELETE, __QUERYPOINTER (checker_heap.cpp); handled false for other names
    Checked heapCall(const std::string& key, const ast::Expr& e, bool& handled);
    void heapInitStmts(const Type* t, exec::Expr* place, const ast::TypeSpec* declSpec, int depth, std::vector<exec::Stmt*>& out);

    ProgramModel& model_;
    CompileLog& log_;

    // declarations by upper-case name
    std::map<std::string, ast::TypeDecl*> typeDecls_;
    std::map<std::string, const Type*> resolvedTypes_;
    std::set<std::string> resolvingTypes_;
    std::vector<PouInfo*> methodsDeferred_;  // blocks laid out during a TYPE's resolution (decision 0458)
    std::map<std::string, PouInfo*> pous_;  // owned by model_.pouStore
    std::vector<PouInfo*> pouOrder_;
    std::vector<ast::GlobalList*> globalLists_;
    std::vector<ast::Configuration*> configurations_;
    std::map<std::string, VarSym*> globals_;
    // The registry (names to BuiltinFn values, decision 0487), filled by
    // builtinRegistrar_ on the first call of builtinTable() (logically
    // const: the entries are the same whenever they are built).
    const BuiltinRegistry& builtinTable() const;
    BuiltinRegistry builtins_;
    mutable std::function<void(Checker&)> builtinRegistrar_;
    std::map<std::string, std::map<std::string, std::string>> parameterAliases_;
    std::set<std::string> namespaces_;  // upper-case NAMESPACE paths and their prefixes ("A", "A.B")
    bool isNamespace(const ast::Expr& e) const;
    // A POU by its name as written: `Lib.FB_Base` or `__SYSTEM.IQueryInterface`
    // is found by its own name (namespaces are flattened); null if none.
    PouInfo* pouNamed(const std::string& written) const;

    // Namespace scoping (checker_namespaces.cpp, decision 0325). A name declared
    // in two namespaces (or a namespaced library name that is also a builtin) is
    // contested: its declarations are keyed by their qualified name, and a name
    // written in code is found from the namespace of the code that writes it.
    // Every other name stays flattened, as before.
    std::map<std::string, std::set<std::string>> contested_;  // upper simple name -> namespaces keyed qualified
    std::map<int, std::vector<std::string>> usingsByFile_;     // upper-case USING paths of each file
    struct NameScope {
        std::string nameSpace;  // upper-case NAMESPACE path of the code being checked, "" at top level
        int file = -1;
    };
    NameScope nameScope_;
    class NameScopeGuard {
    public:
        NameScopeGuard(Checker& c, const std::string& nameSpace, int file);
        ~NameScopeGuard() { c_.nameScope_ = std::move(saved_); }
        NameScopeGuard(const NameScopeGuard&) = delete;
        NameScopeGuard& operator=(const NameScopeGuard&) = delete;
    private:
        Checker& c_;
        NameScope saved_;
    };
    void noteContestedNames(std::vector<ast::CompilationUnit>& units);
    // Overloading by parameter types (SIMATIC AX; checker_overloads.cpp,
    // decision 0362): FUNCTIONs of one name in one namespace with different
    // parameter types are renamed apart before they are declared; a call of
    // the name picks the one whose parameters fit the arguments best.
    struct OverloadSet {
        std::string nameSpace;             // upper case
        std::vector<ast::Pou*> members;    // renamed "Name(T1, T2)"
    };
    std::map<std::string, std::vector<OverloadSet>> overloads_;  // upper simple name -> sets
    std::map<const ast::Pou*, PouInfo*> overloadInfos_;          // filled at the first overloaded call
    void noteOverloads(std::vector<ast::CompilationUnit>& units);
    // {CallerFilePath} / {CallerLineNumber} inputs a call leaves out get the
    // call's file path and line (caller_info.cpp, decision 0363).
    void bindCallerInfo(const PouInfo* fn, const std::set<VarSym*>& connected, const ast::Loc& loc, std::vector<exec::Stmt*>& inputs);
    // A call of an overloaded name: true when `upperSimple` names an overload
    // set (then `out` is the call, or bad after an error naming the candidates).
    bool callOverloaded(const std::string& upperSimple, const ast::Expr& e, Checked& out);
    // The member of `all` that fits the call `e` best; null after an error
    // naming the candidates (or when an argument did not check).
    PouInfo* pickOverload(const std::vector<PouInfo*>& all, const ast::Expr& e);
    // METHODs overloaded in some class (decision 0362): upper simple name. Every
    // method of such a name is renamed "Name(T1, T2)" in every class and
    // interface, so that overrides keep sharing a dispatch slot.
    std::set<std::string> methodOverloads_;
    // The overloads of method `upperSimple` visible in `cls` (it and its bases).
    bool callOverloadedMethod(const Checked& base, PouInfo* cls, const std::string& upperSimple, const ast::Expr& e, Checked& out);
    // The declaration key (upper case) for a type or POU name as written in code.
    std::string scopedKey(const std::string& upperWritten) const;
    // "'A.X', 'B.X'" when a written simple name `X` is contested, declared in more
    // than one namespace and in none in scope ("" when it is not ambiguous).
    std::string ambiguityOf(const std::string& upperWritten) const;
    // "A.B.F" (upper case) for a name or a chain of members; "" for anything else.
    static std::string writtenPath(const ast::Expr& e);
    Checked inOutBinding(const VarSym* v, const ast::Loc& loc);
    // EN/ENO on a function call (checker_en_eno.cpp, decision 0333).
    static bool hasEnEno(const ast::Expr& call);
    Checked checkEnEnoCall(const ast::Expr& e, bool statement);
    std::vector<ast::ExprPtr> enEnoCalls_;
    // What a call with EN/ENO (function or block) becomes before its own call is
    // checked: the call without EN and ENO, EN (default TRUE) stored into a BOOL
    // temporary, and the ENO argument. False after an error (reported).
    struct EnEnoParts {
        const ast::Expr* call = nullptr;  // the call without EN/ENO (kept in enEnoCalls_)
        const ast::Arg* eno = nullptr;
        exec::Expr* temp = nullptr;       // the BOOL temporary EN was written to
        exec::Stmt* storeEn = nullptr;
    };
    static bool isEnArgument(const ast::Arg& a);
    static bool isEnoArgument(const ast::Arg& a);
    bool splitEnEno(const ast::Expr& e, EnEnoParts& out);
    // EN/ENO on a function-block call and `inst.ENO` (checker_fb_en_eno.cpp, decision 0358).
    VarSym* fbEnoSlot(const ast::Expr& instance);
    bool fbEnoSlotPath(const ast::Expr& instance, ast::Expr& slot);
    bool usesFbEnEno(const Checked& inst, const ast::Expr& call);
    bool checkFbEnoRead(const ast::Expr& member, Checked& out);
    exec::Stmt* callFunctionBlockEnEno(Checked inst, const ast::Expr& e);
    // `A` of `A.B.C`: a local variable named like it makes the chain a member access.
    static const ast::Expr& chainRoot(const ast::Expr& e);
    // Enumeration values named without their type (checker_enum_scope.cpp, decision 0441):
    // the global ones (named types, anonymous ones outside POUs), those of the
    // anonymous enumerations of each POU's declarations, and all of the latter
    // together (a value of another POU's anonymous enumeration, the last resort).
    struct EnumNames {
        std::map<std::string, std::pair<const Type*, const Enumerator*>> unique;
        std::set<std::string> ambiguous;
        void add(const std::string& upperName, const Type* t, const Enumerator* e) {
            if (!unique.emplace(upperName, std::make_pair(t, e)).second) ambiguous.insert(upperName);
        }
    };
    EnumNames enumValues_;
    std::map<const PouInfo*, EnumNames> pouEnumValues_;
    EnumNames anyPouEnumValues_;
    const PouInfo* inlineEnumScope_ = nullptr;  // the POU whose declarations are being resolved
    void registerEnumValues(const Type* created, bool inlineEnum);
    std::unordered_map<std::string, size_t> programIndex_;  // upper-case instance name -> model_.programs index

    // state while checking one body
    PouInfo* pou_ = nullptr;
    const std::string* currentPouName_ = nullptr;
    uint32_t frameTop_ = 0;
    int loopDepth_ = 0;
    std::map<std::string, int> labels_;
    std::vector<std::pair<ast::Loc, std::string>> pendingJumps_;
    std::set<std::string> definedLabels_;
    bool assignedResult_ = false;
    std::vector<std::unique_ptr<ast::TypeDecl>> inlineEnumDecls_;
    std::set<int> libraryFiles_;
    ExprObserver* observer_ = nullptr;
    Diagnostic discarded_;  // what warning() hands back for the library's own lines (never printed)
    std::set<std::tuple<int, int, int, std::string>> specialisationErrors_;  // file, line, column, message
    const rt::PlcProfile* profile_ = &rt::defaultProfile();

public:
    // Files whose POUs are the standard library (no unused-variable warnings).
    void setLibraryFiles(std::set<int> files) { libraryFiles_ = std::move(files); }
    // strun lsp: told about every checked expression (expr_observer.h).
    void setExprObserver(ExprObserver* observer) { observer_ = observer; }
    // strun debug: an expression typed in an editor, checked in the scope of
    // `pou` (null: globals only), for evaluation on a live frame
    // (checker_frame_expr.cpp). Errors go to the checker's log. `frameBytes`:
    // the frame the evaluation needs (the POU's own and the temporaries).
    Checked checkInScope(const ast::Expr& e, PouInfo* pou, uint32_t& frameBytes);
    // The POUs by upper-case name (the debugger finds a frame's POU here).
    const std::map<std::string, PouInfo*>& pous() const { return pous_; }
    // The --target whose task rules, defaults and system variables apply.
    void setProfile(const rt::PlcProfile& profile) { profile_ = &profile; }
    const rt::PlcProfile& profile() const { return *profile_; }
};

// Pushes a declaration onto Checker::declStack_ for the time it is resolved.
// Type resolution and layout recurse once per declaration nested by value,
// by alias or by EXTENDS; past kMaxDeclarationDepth that is a compile error
// (docs/limits.md), so hostile chains cannot exhaust the stack.
class DeclDepthGuard {
public:
    static constexpr size_t kMaxDeclarationDepth = 1000;
    DeclDepthGuard(Checker& checker, const std::string& name, const ast::Loc& loc);
    ~DeclDepthGuard();
    DeclDepthGuard(const DeclDepthGuard&) = delete;
    DeclDepthGuard& operator=(const DeclDepthGuard&) = delete;
    bool ok() const { return ok_; }

private:
    Checker& checker_;
    bool ok_ = false;
};

}  // namespace strun::sema
