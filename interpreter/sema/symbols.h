// What the checker knows about declared names: variables with their storage
// location, POUs with their layout, and the typed result of checking an
// expression.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "interpreter/ast/ast.h"
#include "interpreter/exec/call_nodes.h"
#include "interpreter/sema/types.h"

namespace strun::sema {

// Where a variable lives at run time.
enum class Storage : uint8_t {
    Self,   // offset in the current PROGRAM / FB instance
    Frame,  // offset in the current call frame
    Abs,    // absolute address (globals, process image)
};

struct PouInfo;
struct VarSym;

// A declaration initialiser that is not known at compile time: an address
// (`p : POINTER TO INT := ADR(x)`), an earlier variable (`b : INT := a * 2`)
// or a function call. It becomes the assignment `target := value` (REF= for
// a whole REFERENCE), run at initialisation in declaration order
// (docs/decisions/0275).
struct RuntimeInit {
    VarSym* var = nullptr;
    ast::ExprPtr target;              // an element or member of var; null: var itself
    const ast::Expr* value = nullptr;
};

struct VarSym {
    std::string name;  // as declared
    ast::Loc loc;
    const Type* type = nullptr;
    ast::VarSection section = ast::VarSection::Var;
    ast::Access access = ast::Access::Default;  // `VAR PUBLIC` ... of an Ed.3 CLASS or FB
    bool constant = false;
    bool retain = false;
    Storage storage = Storage::Self;
    uint32_t offset = 0;
    uint8_t* abs = nullptr;      // Storage::Abs
    int bit = -1;                // BOOL at a bit address (%IX0.3)
    bool byRef = false;          // VAR_IN_OUT / REFERENCE: the slot holds an address
    const ast::VarDecl* decl = nullptr;
    PouInfo* owner = nullptr;    // POU the variable belongs to (null for globals)
    VarSym* global = nullptr;    // VAR_EXTERNAL: the global it names
    bool used = false;
    // {attribute 'strun_hidden'}: a variable a graphical body's translation
    // needs for itself; --dump, --vcd, --watch and the live API leave it out.
    bool hidden = false;
    // {attribute 'strun_inferred_temp'}: a temporary of a translated body (the
    // current result of IL, decision 0415) whose type is that of the first
    // value assigned to it; until then `inferredPending` and no storage. It
    // lives in the frame of the body that assigns it (Checker::fixInferredTemp).
    bool inferred = false;
    bool inferredPending = false;
    bool inferredConflict = false;  // a value of another type was assigned (reported there): reads say nothing more
    // Global of a list with {attribute 'qualified_only'}: only `LIST.name` names it.
    std::string qualifiedOnlyList;
    // Global of a named global list (GVL): the list's name. `sharedName` when
    // another named list declares the same name: then only `LIST.name` names
    // it, and --dump, --set and --vcd call it that (decision 0096).
    std::string listName;
    bool sharedName = false;
    std::string globalKey() const { return sharedName ? listName + "." + name : name; }
    // CONSTANT with a constant initial value: folded into uses.
    bool hasConstValue = false;
    int64_t constInt = 0;
    double constReal = 0;
    // A STRING/WSTRING CONSTANT whose initial value is known at compile time:
    // that value (an exec::ConstBytes of the variable's type). Uses still read
    // the variable; only the string functions fold over it (decision 0331).
    exec::Expr* constText = nullptr;
};

struct PouInfo {
    ast::Pou* ast = nullptr;
    ast::PouKind kind = ast::PouKind::Program;
    std::string name;
    PouInfo* owner = nullptr;                 // METHOD: the FB / PROGRAM it belongs to
    PouInfo* parent = nullptr;                // FB EXTENDS
    std::vector<VarSym*> params;              // inputs, outputs, in-outs in declaration order
    std::map<std::string, VarSym*> vars;      // upper-case name -> variable (own, not inherited)
    std::vector<std::unique_ptr<VarSym>> ownedVars;
    VarSym* result = nullptr;                 // FUNCTION / METHOD result variable
    const Type* resultType = nullptr;
    Type* instanceType = nullptr;             // PROGRAM / FB: the instance layout as a struct-like type
    std::map<std::string, PouInfo*> methods;  // upper-case name -> method
    bool instanceVarsDeclared = false;         // a method whose VAR_INST live in its block's instance
    exec::PouCode* code = nullptr;
    bool laidOut = false;
    bool layingOut = false;
    bool bodyChecked = false;
    uint32_t frameSize = 0;
    std::vector<uint8_t> instanceInit;        // initial image of an instance
    exec::ClassDesc* classDesc = nullptr;     // FUNCTION_BLOCK: its run-time class
    std::vector<PouInfo*> interfaces;         // FB: INTERFACEs it implements (incl. inherited, extended)
    const ast::Property* property = nullptr;  // property accessor (METHOD): the property
    bool isSetter = false;
    int slot = -1;                            // METHOD: project-wide method slot of its name
    // FUNCTION: small, checked without any diagnostic and calling no POU, so
    // that its calls may run its body inlined (decision 0317).
    bool inlinable = false;
    const std::string* bodyName = nullptr;    // the name fault sites in its body carry
    // Instance variables initialised at run time (an address, an earlier variable,
    // a call): assigned once per instance before the first cycle (checker_fb_init.cpp).
    std::vector<RuntimeInit> addressInits;
    exec::Stmt* addressInitCode = nullptr;
    // FUNCTION / METHOD locals initialised at run time: assigned at the
    // start of every call, as CODESYS does (checkBody).
    std::vector<RuntimeInit> frameAddressInits;
};

// An expression after checking: its node, type, and what the checker knows
// statically about it.
struct Checked {
    exec::Expr* node = nullptr;
    const Type* type = nullptr;
    bool ok = false;           // false after an error (already reported)
    bool isConst = false;      // value known at compile time (constInt / constReal / node is ConstBytes)
    int64_t constInt = 0;
    double constReal = 0;
    bool untypedInt = false;   // integer literal not yet given a type (ANY_INT)
    bool untypedReal = false;  // real literal not yet given a type (ANY_REAL)
    bool foldedExpr = false;   // an untyped constant computed by an operator (127 + 1), not a literal
    bool flexibleLiteral = false;  // not constant, but computed from untyped literals only
                                   // (SEL(g, 1, 2), 10 / 0): converts to any numeric type it meets
    bool isPlace = false;      // designates storage (can be assigned / passed by reference)
    bool readOnly = false;     // CONSTANT, or an input seen from outside its POU
    std::string readOnlyWhy;
    VarSym* var = nullptr;     // the variable, when the expression is a plain variable
    bool hasCall = false;
    ast::Loc loc;
    bool superRef = false;            // SUPER^: methods bind statically to the parent's
    PouInfo* propertySetter = nullptr;  // a property read; assigning it calls this setter
    exec::Expr* propertyInstance = nullptr;
    bool writeOnlyProperty = false;   // a property with only a SET accessor
    std::string propertyName;         // a property access: the property's declared name (messages)
    exec::Expr* flexDesc = nullptr;   // ARRAY[*] parameter: place of its descriptor
    // A variable place at a statically known location (member accesses fold into it).
    enum class Direct : uint8_t { None, Self, Frame, Abs, Pending } direct = Direct::None;
    uint32_t directOffset = 0;
    uint8_t* directAbs = nullptr;
};

}  // namespace strun::sema
