// The abstract syntax tree: what the parser recognised, with source locations,
// before any name resolution or typing. Built from the ANTLR parse tree by
// ast_builder, consumed by sema. Plain data, owned by unique_ptr; no semantics.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/source_location.h"

namespace strun::ast {

// 1-based line and column; file is an index into the SourceSet (source_set.h).
using Loc = rt::SourceLoc;

// `{attribute 'x'}` / `{text}` pragma: kept verbatim (without braces) on the
// declaration it precedes.
struct Pragma {
    Loc loc;
    std::string text;
};

struct Expr;
struct TypeSpec;
struct Init;
struct Stmt;
using ExprPtr = std::unique_ptr<Expr>;
using TypeSpecPtr = std::unique_ptr<TypeSpec>;
using InitPtr = std::unique_ptr<Init>;
using StmtPtr = std::unique_ptr<Stmt>;
using StmtList = std::vector<StmtPtr>;

// ---------------------------------------------------------------- expressions

enum class LitKind {
    Integer,   // text: "123", "16#FF", "2#1010_1010", "8#17", "1_000" (no sign; unary minus is an Expr)
    Real,      // text: "1.5E-3", "1.0", "3e5"
    Bool,      // text: "TRUE"/"FALSE" (as written)
    String,    // text: the raw literal with quotes, e.g. "'a$Nb'" (escapes undecoded)
    WString,   // text: "\"abc\""
    Duration,  // text: "T#1h2m3s4ms", "TIME#-5s", "LT#1us", "LTIME#1.5s" (whole literal)
    Date,      // text: "D#2026-01-31", "DATE#...", "LD#...", "LDATE#..."
    TimeOfDay, // text: "TOD#13:05:00.25", "TIME_OF_DAY#...", "LTOD#..."
    DateTime,  // text: "DT#2026-01-31-13:05:00", "DATE_AND_TIME#...", "LDT#..."
    Typed,     // typed literal: typePrefix "INT", valueText "-5"; "WORD" + "16#FFFF";
               // "BOOL" + "1"; "REAL" + "1.0"; enum "Color" + "Red"; "STRING" + "'x'"
};

enum class Op {
    // binary
    Add, Sub, Mul, Div, Mod, Pow,
    Eq, Ne, Lt, Le, Gt, Ge,
    And, Or, Xor, AndThen, OrElse,
    // unary
    Neg, Plus, Not,
};

enum class ExprKind {
    Literal,  // lit, text, typePrefix, valueText
    Name,     // name (may be namespace-qualified "NS.x" only when written so: builder keeps simple names; qualification appears as Member)
    Member,   // kids[0].name   (also bit access `x.3`: name = "3"; and `x.%X3`: name = "%X3")
    Index,    // kids[0] [ kids[1], kids[2], ... ]
    Deref,    // kids[0]^
    Call,     // kids[0] ( args )   — kids[0] is Name, Member (method/instance) or Deref/Index
    Unary,    // op kids[0]
    Binary,   // kids[0] op kids[1]
    This,     // THIS   (THIS^ is Deref(This))
    Super,    // SUPER  (SUPER^ is Deref(Super))
    Assign,   // (kids[0] := kids[1]) used as a value (CODESYS): the value assigned
};

// A call argument: positional (name empty), input `name := value`,
// output `name => value` (output = true), `NOT name => value` (negated = true).
// `name :=` with no value (CODESYS allows it for unconnected inputs) has value null.
struct Arg {
    Loc loc;
    std::string name;
    bool output = false;
    bool negated = false;
    ExprPtr value;
};

struct Expr {
    ExprKind kind = ExprKind::Literal;
    Loc loc;
    // Literal
    LitKind lit = LitKind::Integer;
    std::string text;        // Literal: whole literal as written
    std::string typePrefix;  // Literal Typed: "INT", "Color"
    std::string valueText;   // Literal Typed: text after the '#'
    // Name / Member
    std::string name;
    Loc nameLoc;  // Member: the member name after the dot (errors about the member point here)
    bool pointerTo = false;  // Name: `POINTER TO name`, a type only __NEW and SIZEOF take
    // Unary / Binary
    Op op = Op::Add;
    std::vector<ExprPtr> kids;
    // Call
    std::vector<Arg> args;
};

// ---------------------------------------------------------------- types

enum class TypeSpecKind {
    Named,      // name: "INT", "MyStruct", "NS.MyType" (elementary types by name too)
    String,     // wide? STRING[n] / STRING(n) / WSTRING[n]; length may be null (default)
    Array,      // ARRAY [dims] OF elem
    Pointer,    // POINTER TO target
    Reference,  // REFERENCE TO target
    Subrange,   // base (Named) (lo .. hi)
    Enum,       // (a, b := 5, c) [base]  — only inside TYPE or inline in a VAR decl
    Struct,     // STRUCT fields END_STRUCT [EXTENDS in TypeDecl]
};

struct Range {
    ExprPtr lo, hi;     // both null when star
    bool star = false;  // ARRAY[*]
};

struct EnumValue {
    Loc loc;
    std::string name;
    ExprPtr value;  // may be null
};

struct VarDecl;

struct TypeSpec {
    TypeSpecKind kind = TypeSpecKind::Named;
    Loc loc;
    std::string name;                  // Named
    bool wide = false;                 // String
    ExprPtr length;                    // String (null = default length)
    std::vector<Range> dims;           // Array
    TypeSpecPtr elem;                  // Array element; Pointer/Reference target; Subrange/Enum base (may be null for Enum)
    ExprPtr lo, hi;                    // Subrange bounds
    std::vector<EnumValue> enumValues; // Enum
    std::vector<VarDecl> fields;       // Struct
    std::vector<Arg> initArgs;         // Named: CODESYS `fb : FB(1, x := 2)` — arguments of FB_init
    std::vector<std::vector<Arg>> elementInitArgs;  // Named, as an array's element: `ARRAY[1..2] OF FB[(a := 1), (a := 2)]`
    std::vector<ExprPtr> genericArgs;  // Named: `FB_X<6, (2 * c)>` — values of the block's VAR_GENERIC CONSTANTs
    bool isUnion = false;              // Struct written UNION ... END_UNION (CODESYS): members overlap
    bool refTo = false;                // Pointer written REF_TO (not POINTER TO): messages name it so
};

enum class InitKind {
    Expr,    // expr
    Array,   // [ items ]  each item: optional repeat count, value  —  [3(0), 1, 2(5)]
    Struct,  // ( name := init, ... )
};

struct ArrayInitItem {
    ExprPtr repeat;  // null = 1; `3(0)` → repeat 3, value 0; `3()` → value null
    InitPtr value;
    // `[N(x)]` with a name N: repeat N and value x, and here the same item
    // read as one element initialised by the call N(x); the checker takes the
    // call when N is not a constant. Null for every other item.
    InitPtr callForm;
};

struct StructInitItem {
    Loc loc;
    std::string name;
    InitPtr value;
};

struct Init {
    InitKind kind = InitKind::Expr;
    Loc loc;
    ExprPtr expr;
    std::vector<ArrayInitItem> items;
    std::vector<StructInitItem> fields;
};

// `a, b AT %IX0.0 : INT := 5;` — one VarDecl per declaration line, several names.
struct VarDecl {
    Loc loc;
    std::vector<std::string> names;
    std::vector<Loc> nameLocs;
    std::string address;  // "%IX0.0", "%QW2", "%MD10", "%I*", "" if none (text as written)
    TypeSpecPtr type;
    InitPtr init;
    std::vector<Pragma> pragmas;
    // VAR_ACCESS only: `name : path : TYPE READ_ONLY;` — the path text as
    // written (e.g. "prog.var") and whether the access is READ_ONLY.
    std::string accessPath;
    bool readOnly = false;
    // `x : BOOL R_EDGE;` / `F_EDGE` (IEC 61131-3 edge-detecting input; decision 0339).
    enum class Edge { None, Rising, Falling };
    Edge edge = Edge::None;
};

enum class VarSection {
    Var, Input, Output, InOut, Temp, Stat, Inst, Global, External, Access, Config,
};

enum class Access { Default, Public, Private, Protected, Internal };

struct VarBlock {
    Loc loc;
    VarSection section = VarSection::Var;
    Access access = Access::Default;  // Ed.3 `VAR PUBLIC` / `VAR PRIVATE` ... (decision 0278)
    bool constant = false;
    bool generic = false;  // VAR_GENERIC CONSTANT (TwinCAT 4026 / CODESYS): constants each instance's type sets
    bool retain = false;
    bool nonRetain = false;
    bool persistent = false;
    std::vector<VarDecl> vars;
};

// ---------------------------------------------------------------- statements

enum class StmtKind {
    Assign,     // target := value
    SetAssign,  // target S= value
    ResetAssign,// target R= value
    TryAssign,  // target ?= value
    RefAssign,  // target REF= value
    Call,       // call (expr is a Call expression) — also a bare name `fb;`? no: must be a call
    If,         // conds[i] / blocks[i]; elseBlock
    Case,       // expr; cases; elseBlock
    For,        // name (control var), from, to, by (may be null), body
    While,      // expr, body
    Repeat,     // body, expr (UNTIL)
    Exit,
    Continue,
    Return,
    Jmp,        // name (label)
    Label,      // name:  (a label before a statement is its own Label stmt)
    Empty,      // ;
};

// A CASE label: single value (lo) or range (lo..hi).
struct CaseLabel {
    ExprPtr lo, hi;  // hi null for a single value
};

struct CaseBranch {
    Loc loc;
    std::vector<CaseLabel> labels;
    StmtList body;
};

struct Stmt {
    StmtKind kind = StmtKind::Empty;
    Loc loc;
    ExprPtr target;  // assignments
    ExprPtr expr;    // assignment value; call; CASE selector; WHILE / REPEAT condition; RETURN's condition (CODESYS)
    std::string name;  // FOR control variable; JMP / Label name
    Loc nameLoc;       // where `name` is written
    ExprPtr from, to, by;
    std::vector<ExprPtr> conds;       // IF / ELSIF conditions
    std::vector<StmtList> blocks;     // IF / ELSIF blocks (same size as conds)
    std::vector<CaseBranch> cases;
    StmtList body;                    // FOR / WHILE / REPEAT body
    // (FOR: `target` is the control variable when it is not a plain name, e.g. `FOR a[1] := ...`.)
    std::optional<StmtList> elseBlock;
};

// ---------------------------------------------------------------- POUs

enum class PouKind { Program, Function, FunctionBlock, Method, Interface };

struct Pou;

struct Property {
    Loc loc;
    std::string name;
    Access access = Access::Default;
    bool abstract = false;
    bool final = false;
    TypeSpecPtr type;
    std::unique_ptr<Pou> getter;  // kind Method, name "GET"; has its own VAR blocks and body
    std::unique_ptr<Pou> setter;  // kind Method, name "SET"
    std::vector<Pragma> pragmas;
};

struct Pou {
    PouKind kind = PouKind::Program;
    Loc loc;
    Loc endLoc;  // location of the END_xxx keyword
    std::string name;
    Loc nameLoc;  // where the name is written
    std::string nameSpace;        // enclosing NAMESPACE path "A.B", "" at top level
    TypeSpecPtr returnType;       // FUNCTION / METHOD / interface method (null if none)
    Access access = Access::Default;
    bool abstract = false;
    bool final = false;
    bool override = false;        // METHOD ... OVERRIDE (Ed.3 / SIMATIC AX): must override a base method
    std::string extends;          // FB EXTENDS base; INTERFACE: first of extendsList
    std::vector<ExprPtr> extendsGenericArgs;  // FB EXTENDS FB_Base<1000>: the base's VAR_GENERIC values
    std::vector<std::string> extendsList;  // INTERFACE EXTENDS I1, I2
    std::vector<std::string> implements;
    std::vector<VarBlock> vars;
    StmtList body;                // empty for interfaces / abstract methods
    bool hasBody = false;         // false for interface / abstract method prototypes
    bool isAction = false;        // METHOD that is a CODESYS ACTION (no parameters, no variables of its own)
    std::vector<std::unique_ptr<Pou>> methods;
    std::vector<Property> properties;
    std::vector<Pragma> pragmas;
};

struct TypeDecl {
    Loc loc;
    std::string name;
    Loc nameLoc;
    std::string nameSpace;
    std::string extends;  // STRUCT EXTENDS base
    TypeSpecPtr spec;
    InitPtr init;          // `TYPE T : INT := 5; END_TYPE`, enum default `(a,b) := b`
    std::vector<Pragma> pragmas;
};

// VAR_GLOBAL list at top level (outside any CONFIGURATION), CODESYS GVL style.
struct GlobalList {
    Loc loc;
    std::string nameSpace;
    std::vector<VarBlock> blocks;
    std::vector<Pragma> pragmas;
};

// TASK name (INTERVAL := T#10ms, PRIORITY := 1, SINGLE := gStart, EVENT := STARTUP, ...);
struct TaskParam {
    Loc loc;
    std::string name;  // INTERVAL, PRIORITY, SINGLE, STATUS, EVENT, WATCHDOG, AT, REPEAT, ...
    ExprPtr value;     // identifiers like STARTUP / DAILY arrive as Name exprs
};

struct TaskDecl {
    Loc loc;
    std::string name;
    std::vector<TaskParam> params;
};

// PROGRAM inst [WITH task] : Type (args);  and  fbInst WITH task;
struct ProgramConfig {
    Loc loc;
    bool isProgram = true;  // false for `fbInst WITH task;`
    std::string instance;
    std::string task;       // "" when no WITH
    std::string typeName;   // "" for an FB binding
    std::vector<Arg> args;
};

struct Resource {
    Loc loc;
    std::string name;
    std::string on;  // ON xxx
    std::vector<VarBlock> globals;
    std::vector<TaskDecl> tasks;
    std::vector<ProgramConfig> programs;
};

struct Configuration {
    Loc loc;
    std::string name;
    std::vector<VarBlock> globals;
    std::vector<Resource> resources;
    // tasks/programs written directly in the configuration (single-resource shorthand)
    std::vector<TaskDecl> tasks;
    std::vector<ProgramConfig> programs;
};

struct UsingDirective {
    Loc loc;
    std::string nameSpace;
};

// One source file.
struct CompilationUnit {
    int file = 0;
    std::vector<std::unique_ptr<Pou>> pous;      // PROGRAM / FUNCTION / FUNCTION_BLOCK / INTERFACE (and top-level METHODs, if any)
    std::vector<TypeDecl> types;
    std::vector<GlobalList> globals;
    std::vector<Configuration> configurations;
    std::vector<UsingDirective> usings;
};

}  // namespace strun::ast
