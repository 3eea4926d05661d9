// Declarations: POUs, methods, properties, interfaces, namespaces, TYPE
// blocks, VAR sections, global lists, configurations, pragmas.
#include <catch2/catch.hpp>

#include "parse_test_support.h"

using namespace strun::ast;
using strun::ast::test::parse;

namespace {

std::string names(const VarDecl& d) {
    std::string out;
    for (const auto& n : d.names) out += (out.empty() ? "" : ",") + n;
    return out;
}

}  // namespace

TEST_CASE("declarations: PROGRAM, FUNCTION, FUNCTION_BLOCK", "[parser][decl]") {
    auto p = parse(R"(
PROGRAM Main
VAR x : INT; END_VAR
x := Add(1, 2);
END_PROGRAM

FUNCTION Add : INT
VAR_INPUT a, b : INT; END_VAR
Add := a + b;
END_FUNCTION

function NoResult
end_function

FUNCTION_BLOCK PUBLIC ABSTRACT Motor EXTENDS Base IMPLEMENTS IRun, IStop
VAR_OUTPUT running : BOOL; END_VAR
running := TRUE;
END_FUNCTION_BLOCK

FUNCTION_BLOCK FINAL Leaf EXTENDS Motor
END_FUNCTION_BLOCK
)");
    REQUIRE(p->errors() == "");
    auto& pous = p->unit.pous;
    REQUIRE(pous.size() == 5);
    CHECK(pous[0]->kind == PouKind::Program);
    CHECK(pous[0]->name == "Main");
    CHECK(pous[0]->hasBody);
    CHECK(pous[0]->vars.size() == 1);
    CHECK(dump(pous[0]->body) == "{(:= x (call Add 1 2))}");
    CHECK(pous[0]->loc.line == 2);
    CHECK(pous[0]->endLoc.line == 5);

    CHECK(pous[1]->kind == PouKind::Function);
    REQUIRE(pous[1]->returnType);
    CHECK(dump(*pous[1]->returnType) == "INT");
    CHECK(pous[1]->vars.at(0).section == VarSection::Input);
    CHECK(names(pous[1]->vars.at(0).vars.at(0)) == "a,b");

    CHECK(pous[2]->kind == PouKind::Function);
    CHECK(pous[2]->returnType == nullptr);

    const Pou& motor = *pous[3];
    CHECK(motor.kind == PouKind::FunctionBlock);
    CHECK(motor.access == Access::Public);
    CHECK(motor.abstract);
    CHECK_FALSE(motor.final);
    CHECK(motor.extends == "Base");
    CHECK(motor.implements == std::vector<std::string>{"IRun", "IStop"});
    CHECK(pous[4]->final);
    CHECK(pous[4]->extends == "Motor");
}

TEST_CASE("declarations: methods and properties", "[parser][decl]") {
    auto p = parse(R"(
FUNCTION_BLOCK Fb
VAR v : INT; END_VAR
METHOD PUBLIC Before : BOOL
VAR_INPUT a : INT; END_VAR
Before := a > 0;
END_METHOD
v := v + 1;
METHOD PRIVATE FINAL After
END_METHOD
METHOD PROTECTED ABSTRACT Todo : INT
END_METHOD
PROPERTY PUBLIC Value : INT
GET
  VAR tmp : INT; END_VAR
  Value := v;
END_GET
SET
  v := Value;
END_SET
END_PROPERTY
PROPERTY ReadOnly : BOOL
GET ReadOnly := TRUE; END_GET
END_PROPERTY
END_FUNCTION_BLOCK

PROGRAM Prg
METHOD Helper : INT
Helper := 1;
END_METHOD
END_PROGRAM
)");
    REQUIRE(p->errors() == "");
    const Pou& fb = *p->unit.pous.at(0);
    CHECK(dump(fb.body) == "{(:= v (+ v 1))}");
    REQUIRE(fb.methods.size() == 3);
    CHECK(fb.methods[0]->name == "Before");
    CHECK(fb.methods[0]->kind == PouKind::Method);
    CHECK(fb.methods[0]->access == Access::Public);
    CHECK(dump(*fb.methods[0]->returnType) == "BOOL");
    CHECK(fb.methods[0]->hasBody);
    CHECK(dump(fb.methods[0]->body) == "{(:= Before (> a 0))}");
    CHECK(fb.methods[1]->access == Access::Private);
    CHECK(fb.methods[1]->final);
    CHECK(fb.methods[1]->returnType == nullptr);
    CHECK(fb.methods[2]->abstract);
    CHECK_FALSE(fb.methods[2]->hasBody);

    REQUIRE(fb.properties.size() == 2);
    const Property& value = fb.properties[0];
    CHECK(value.name == "Value");
    CHECK(value.access == Access::Public);
    CHECK(dump(*value.type) == "INT");
    REQUIRE(value.getter);
    REQUIRE(value.setter);
    CHECK(value.getter->name == "GET");
    CHECK(value.getter->kind == PouKind::Method);
    CHECK(value.getter->vars.size() == 1);
    CHECK(dump(value.getter->body) == "{(:= Value v)}");
    CHECK(dump(value.setter->body) == "{(:= v Value)}");
    CHECK(fb.properties[1].getter);
    CHECK(fb.properties[1].setter == nullptr);

    const Pou& prg = *p->unit.pous.at(1);
    REQUIRE(prg.methods.size() == 1);
    CHECK(prg.methods[0]->name == "Helper");
}

TEST_CASE("declarations: interfaces", "[parser][decl]") {
    auto p = parse(R"(
INTERFACE IRun EXTENDS IBase, IOther
METHOD Start : BOOL
VAR_INPUT speed : REAL; END_VAR
END_METHOD
METHOD Stop
END_METHOD
PROPERTY Speed : REAL
GET END_GET
END_PROPERTY
PROPERTY Mode : INT
END_PROPERTY
END_INTERFACE
INTERFACE IEmpty
END_INTERFACE
)");
    REQUIRE(p->errors() == "");
    const Pou& itf = *p->unit.pous.at(0);
    CHECK(itf.kind == PouKind::Interface);
    CHECK_FALSE(itf.hasBody);
    CHECK(itf.extends == "IBase");
    CHECK(itf.extendsList == std::vector<std::string>{"IBase", "IOther"});
    REQUIRE(itf.methods.size() == 2);
    CHECK_FALSE(itf.methods[0]->hasBody);
    CHECK(itf.methods[0]->vars.at(0).section == VarSection::Input);
    REQUIRE(itf.properties.size() == 2);
    CHECK(itf.properties[0].getter);
    CHECK_FALSE(itf.properties[0].getter->hasBody);
    CHECK(itf.properties[0].setter == nullptr);
    // Without accessor sections an interface property is read/write.
    CHECK(itf.properties[1].getter);
    CHECK(itf.properties[1].setter);
    CHECK(p->unit.pous.at(1)->name == "IEmpty");

    auto bad = parse("INTERFACE I\nMETHOD M\n  x := 1;\nEND_METHOD\nEND_INTERFACE");
    CHECK(bad->errors() == "3:3: syntax error: a method of an INTERFACE has no body (statements found in 'M')\n");
}

TEST_CASE("declarations: namespaces and USING", "[parser][decl]") {
    auto p = parse(R"(
USING Lib.Util;
NAMESPACE A.B
  TYPE T : INT; END_TYPE
  NAMESPACE C
    FUNCTION F : INT
    END_FUNCTION
  END_NAMESPACE
  VAR_GLOBAL g : INT; END_VAR
END_NAMESPACE
PROGRAM Top
END_PROGRAM
)");
    REQUIRE(p->errors() == "");
    REQUIRE(p->unit.usings.size() == 1);
    CHECK(p->unit.usings[0].nameSpace == "Lib.Util");
    CHECK(p->unit.types.at(0).nameSpace == "A.B");
    CHECK(p->unit.pous.at(0)->name == "F");
    CHECK(p->unit.pous.at(0)->nameSpace == "A.B.C");
    CHECK(p->unit.globals.at(0).nameSpace == "A.B");
    CHECK(p->unit.pous.at(1)->nameSpace == "");
}

TEST_CASE("declarations: enumerations", "[parser][decl][types]") {
    auto p = parse(R"(
TYPE
  Color : (Red, Green, Blue);
  Valued : (a := 1, b := 5);
  CodesysTyped : (x := 1, y := 5) INT;
  IecTyped : INT (p := 1, q := 5);
  WithDefault : (Idle, Busy) := Busy;
  Range : INT(0..100);
  Neg : DINT(-10..10);
  IecTypedPlain : UINT (m, n);
END_TYPE
)");
    REQUIRE(p->errors() == "");
    auto& t = p->unit.types;
    REQUIRE(t.size() == 8);
    CHECK(t[0].name == "Color");
    CHECK(dump(*t[0].spec) == "(Red,Green,Blue)");
    CHECK(t[0].spec->kind == TypeSpecKind::Enum);
    CHECK(dump(*t[1].spec) == "(a:=1,b:=5)");
    CHECK(dump(*t[2].spec) == "(x:=1,y:=5) INT");
    CHECK(t[3].spec->kind == TypeSpecKind::Enum);
    CHECK(dump(*t[3].spec) == "(p:=1,q:=5) INT");
    REQUIRE(t[4].init);
    CHECK(dump(*t[4].init) == "Busy");
    CHECK(t[5].spec->kind == TypeSpecKind::Subrange);
    CHECK(dump(*t[5].spec) == "INT(0..100)");
    CHECK(dump(*t[6].spec) == "DINT((neg 10)..10)");
    CHECK(dump(*t[7].spec) == "(m,n) UINT");
}

TEST_CASE("declarations: structures, arrays, strings, pointers, aliases", "[parser][decl][types]") {
    auto p = parse(R"(
TYPE
  Base : STRUCT
    id : DINT;
  END_STRUCT
  Derived EXTENDS Base : STRUCT
    a, b : INT := 5;
    arr : ARRAY[1..3] OF REAL := [1.0, 2.0, 3.0];
  END_STRUCT;
  Alias : INT;
  AliasInit : INT := 7;
  Matrix : ARRAY[1..3, -2..2, 0..N-1] OF ARRAY[1..2] OF INT;
  Name : STRING[20];
  Name2 : STRING(30);
  WName : WSTRING[10];
  Plain : STRING;
  PInt : POINTER TO INT;
  RInt : REFERENCE TO Derived;
  Qualified : Lib.Types.Thing;
END_TYPE
)");
    REQUIRE(p->errors() == "");
    auto& t = p->unit.types;
    REQUIRE(t.size() == 12);
    CHECK(t[1].extends == "Base");
    CHECK(t[1].spec->kind == TypeSpecKind::Struct);
    CHECK(dump(*t[1].spec) == "STRUCT(a,b:INT:=5;arr:ARRAY[1..3] OF REAL:=[1.0,2.0,3.0])");
    CHECK(dump(*t[2].spec) == "INT");
    CHECK(dump(*t[3].init) == "7");
    CHECK(dump(*t[4].spec) == "ARRAY[1..3,(neg 2)..2,0..(- N 1)] OF ARRAY[1..2] OF INT");
    CHECK(dump(*t[5].spec) == "STRING[20]");
    CHECK(dump(*t[6].spec) == "STRING[30]");
    CHECK(dump(*t[7].spec) == "WSTRING[10]");
    CHECK(t[7].spec->wide);
    CHECK(dump(*t[8].spec) == "STRING");
    CHECK(t[8].spec->length == nullptr);
    CHECK(dump(*t[9].spec) == "POINTER TO INT");
    CHECK(dump(*t[10].spec) == "REFERENCE TO Derived");
    CHECK(dump(*t[11].spec) == "Lib.Types.Thing");
}

TEST_CASE("declarations: VAR sections, qualifiers, addresses, initial values", "[parser][decl][vars]") {
    auto p = parse(R"(
FUNCTION_BLOCK Fb
VAR_INPUT in1 : BOOL; END_VAR
VAR_OUTPUT out1 : BOOL; END_VAR
VAR_IN_OUT io : ARRAY[*] OF INT; io2 : ARRAY[*, *] OF REAL; END_VAR
VAR_TEMP t : INT; END_VAR
VAR_STAT s : INT; END_VAR
VAR_INST i : INT; END_VAR
VAR_EXTERNAL e : INT; END_VAR
VAR CONSTANT c : INT := 3; END_VAR
VAR RETAIN PERSISTENT r : INT; END_VAR
VAR PERSISTENT RETAIN r2 : INT; END_VAR
VAR NON_RETAIN nr : INT; END_VAR
VAR
  a, b, c2 : INT := 5;
  x AT %IX0.0 : BOOL;
  w AT %QW2 : WORD;
  d AT %MD10 : DINT;
  bb AT %IB3 : BYTE;
  q AT %QX1.7 : BOOL;
  anyIn AT %I* : BOOL;
  anyOut AT %Q* : WORD;
  state : (Idle, Running) := Idle;
  st : MyStruct := (a := 1, b := [1, 2]);
  arr : ARRAY[0..9] OF INT := [3(0), 1, 6(2)];
  arr2 : ARRAY[0..9] OF INT := [10(0)];
  nested : ARRAY[1..2] OF Pt := [(x := 1, y := 2), (x := 3, y := 4)];
  timer : TON := (PT := T#1s);
  str : STRING[10] := 'abc';
  pragmaFree : INT;
END_VAR
END_FUNCTION_BLOCK
)");
    REQUIRE(p->errors() == "");
    const auto& vars = p->unit.pous.at(0)->vars;
    REQUIRE(vars.size() == 12);
    std::vector<VarSection> sections;
    for (const auto& b : vars) sections.push_back(b.section);
    CHECK(sections == std::vector<VarSection>{VarSection::Input, VarSection::Output, VarSection::InOut,
                                              VarSection::Temp, VarSection::Stat, VarSection::Inst,
                                              VarSection::External, VarSection::Var, VarSection::Var,
                                              VarSection::Var, VarSection::Var, VarSection::Var});
    CHECK(dump(*vars[2].vars[0].type) == "ARRAY[*] OF INT");
    CHECK(vars[2].vars[0].type->dims[0].star);
    CHECK(dump(*vars[2].vars[1].type) == "ARRAY[*,*] OF REAL");
    CHECK(vars[7].constant);
    CHECK(vars[8].retain);
    CHECK(vars[8].persistent);
    CHECK(vars[9].retain);
    CHECK(vars[9].persistent);
    CHECK(vars[10].nonRetain);
    CHECK_FALSE(vars[10].retain);

    const auto& v = vars[11].vars;
    CHECK(names(v[0]) == "a,b,c2");
    CHECK(v[0].nameLocs.size() == 3);
    CHECK(v[0].nameLocs[1].col == 6);
    CHECK(dump(*v[0].init) == "5");
    std::vector<std::string> addresses;
    for (size_t i = 1; i <= 7; ++i) addresses.push_back(v[i].address);
    CHECK(addresses == std::vector<std::string>{"%IX0.0", "%QW2", "%MD10", "%IB3", "%QX1.7", "%I*", "%Q*"});
    CHECK(dump(*v[8].type) == "(Idle,Running)");
    CHECK(dump(*v[8].init) == "Idle");
    CHECK(v[9].init->kind == InitKind::Struct);
    CHECK(dump(*v[9].init) == "(a:=1,b:=[1,2])");
    CHECK(v[10].init->kind == InitKind::Array);
    CHECK(dump(*v[10].init) == "[3(0),1,6(2)]");
    CHECK(dump(*v[11].init) == "[10(0)]");
    CHECK(dump(*v[12].init) == "[(x:=1,y:=2),(x:=3,y:=4)]");
    CHECK(dump(*v[13].init) == "(PT:=T#1s)");
    CHECK(dump(*v[14].type) == "STRING[10]");
}

TEST_CASE("declarations: global lists", "[parser][decl]") {
    auto p = parse(R"(
VAR_GLOBAL
  gCount : INT;
END_VAR
VAR_GLOBAL CONSTANT
  gMax : INT := 10;
END_VAR
VAR_GLOBAL RETAIN PERSISTENT
  gKeep : INT;
END_VAR
)");
    REQUIRE(p->errors() == "");
    REQUIRE(p->unit.globals.size() == 3);
    CHECK(p->unit.globals[0].blocks.at(0).section == VarSection::Global);
    CHECK(p->unit.globals[1].blocks.at(0).constant);
    CHECK(p->unit.globals[2].blocks.at(0).retain);
    CHECK(p->unit.globals[2].blocks.at(0).persistent);

    auto bad = parse("VAR_INPUT x : INT; END_VAR");
    CHECK(bad->errors() == "1:1: syntax error: only VAR_GLOBAL is allowed outside a POU, found VAR_INPUT\n");
}

TEST_CASE("declarations: the configuration example", "[parser][config]") {
    auto p = parse(R"(
CONFIGURATION Plant
  VAR_GLOBAL gStart : BOOL; gAlarm : BOOL; END_VAR
  RESOURCE Cpu ON PLC
    TASK Fast   (INTERVAL := T#10ms, PRIORITY := 1, WATCHDOG := T#20ms);
    TASK Main   (PRIORITY := 30);
    TASK OnEdge (SINGLE := gStart, PRIORITY := 2);
    TASK While  (STATUS := gAlarm, PRIORITY := 20);
    TASK Boot   (EVENT := STARTUP, PRIORITY := 0);
    TASK OnErr  (EVENT := PROGRAM_ERROR, PRIORITY := 3);
    TASK OnLate (EVENT := EXEC_TIMEOUT, PRIORITY := 4);
    TASK Night  (AT := DT#2026-01-01-02:00:00, REPEAT := DAILY, PRIORITY := 10);
    PROGRAM Ctl WITH Fast : Controller (Setpoint := gSp, Out => gOut);
    PROGRAM Log WITH Main : Logger;
    fbInst WITH Fast;
  END_RESOURCE
END_CONFIGURATION
)");
    REQUIRE(p->errors() == "");
    REQUIRE(p->unit.configurations.size() == 1);
    const Configuration& cfg = p->unit.configurations[0];
    CHECK(cfg.name == "Plant");
    REQUIRE(cfg.globals.size() == 1);
    CHECK(cfg.globals[0].vars.size() == 2);
    REQUIRE(cfg.resources.size() == 1);
    const Resource& r = cfg.resources[0];
    CHECK(r.name == "Cpu");
    CHECK(r.on == "PLC");
    REQUIRE(r.tasks.size() == 8);
    auto params = [](const TaskDecl& t) {
        std::string out = t.name + "(";
        for (const auto& p : t.params) out += p.name + "=" + dump(*p.value) + ";";
        return out + ")";
    };
    CHECK(params(r.tasks[0]) == "Fast(INTERVAL=T#10ms;PRIORITY=1;WATCHDOG=T#20ms;)");
    CHECK(params(r.tasks[1]) == "Main(PRIORITY=30;)");
    CHECK(params(r.tasks[2]) == "OnEdge(SINGLE=gStart;PRIORITY=2;)");
    CHECK(params(r.tasks[3]) == "While(STATUS=gAlarm;PRIORITY=20;)");
    CHECK(params(r.tasks[4]) == "Boot(EVENT=STARTUP;PRIORITY=0;)");
    CHECK(r.tasks[4].params[0].value->kind == ExprKind::Name);
    CHECK(params(r.tasks[5]) == "OnErr(EVENT=PROGRAM_ERROR;PRIORITY=3;)");
    CHECK(params(r.tasks[6]) == "OnLate(EVENT=EXEC_TIMEOUT;PRIORITY=4;)");
    CHECK(params(r.tasks[7]) == "Night(AT=DT#2026-01-01-02:00:00;REPEAT=DAILY;PRIORITY=10;)");
    CHECK(r.tasks[7].params[1].value->kind == ExprKind::Name);
    CHECK(r.tasks[0].loc.line == 5);
    CHECK(r.tasks[0].loc.col == 5);

    REQUIRE(r.programs.size() == 3);
    const ProgramConfig& ctl = r.programs[0];
    CHECK(ctl.isProgram);
    CHECK(ctl.instance == "Ctl");
    CHECK(ctl.task == "Fast");
    CHECK(ctl.typeName == "Controller");
    REQUIRE(ctl.args.size() == 2);
    CHECK(ctl.args[0].name == "Setpoint");
    CHECK_FALSE(ctl.args[0].output);
    CHECK(ctl.args[1].name == "Out");
    CHECK(ctl.args[1].output);
    CHECK(dump(*ctl.args[1].value) == "gOut");
    CHECK(r.programs[1].typeName == "Logger");
    CHECK(r.programs[1].args.empty());
    CHECK_FALSE(r.programs[2].isProgram);
    CHECK(r.programs[2].instance == "fbInst");
    CHECK(r.programs[2].task == "Fast");
}

TEST_CASE("declarations: tasks and programs directly in a configuration", "[parser][config]") {
    auto p = parse(R"(
CONFIGURATION C
  TASK T1 (INTERVAL := T#100ms, PRIORITY := 5);
  PROGRAM p1 : Prog;
  PROGRAM p2 WITH T1 : Prog;
  VAR_ACCESS
    acc : p1.counter : INT READ_ONLY;
    acc2 : p2.x : BOOL READ_WRITE;
  END_VAR
  VAR_CONFIG
    p1.out AT %QW1 : INT;
    p2.fb.x AT %QX0.0 : BOOL := TRUE;
  END_VAR
END_CONFIGURATION
)");
    REQUIRE(p->errors() == "");
    const Configuration& cfg = p->unit.configurations.at(0);
    REQUIRE(cfg.tasks.size() == 1);
    CHECK(cfg.tasks[0].name == "T1");
    REQUIRE(cfg.programs.size() == 2);
    CHECK(cfg.programs[0].task == "");
    CHECK(cfg.programs[0].typeName == "Prog");
    CHECK(cfg.programs[1].task == "T1");
    REQUIRE(cfg.globals.size() == 2);
    const VarBlock& access = cfg.globals[0];
    CHECK(access.section == VarSection::Access);
    CHECK(access.vars[0].names == std::vector<std::string>{"acc"});
    CHECK(access.vars[0].accessPath == "p1.counter");
    CHECK(access.vars[0].readOnly);
    CHECK_FALSE(access.vars[1].readOnly);
    const VarBlock& config = cfg.globals[1];
    CHECK(config.section == VarSection::Config);
    CHECK(config.vars[0].names == std::vector<std::string>{"p1.out"});
    CHECK(config.vars[0].address == "%QW1");
    CHECK(config.vars[1].names == std::vector<std::string>{"p2.fb.x"});
    CHECK(dump(*config.vars[1].init) == "TRUE");
}

TEST_CASE("declarations: pragmas attach to the declaration they precede", "[parser][pragma]") {
    auto p = parse(R"(
{attribute 'qualified_only'}
VAR_GLOBAL
  {attribute 'hide'}
  g : INT;
  h : INT; {this one belongs to nothing}
END_VAR

{attribute 'strict'}
TYPE
  E1 : (a, b);
  {attribute 'flags'}
  E2 : (c, d);
END_TYPE

{attribute 'call_after_init'} {attribute 'no_check'}
FUNCTION_BLOCK Fb
VAR
  {attribute 'instance-path'} {noinit}
  path : STRING;
END_VAR
{attribute 'm'}
METHOD M
END_METHOD
{attribute 'monitoring' := 'call'}
PROPERTY P : INT
END_PROPERTY
x := 1; {comment-like pragma in code is ignored}
END_FUNCTION_BLOCK
)");
    REQUIRE(p->errors() == "");
    auto texts = [](const std::vector<Pragma>& ps) {
        std::string out;
        for (const auto& pr : ps) out += "[" + pr.text + "]";
        return out;
    };
    const GlobalList& gvl = p->unit.globals.at(0);
    CHECK(texts(gvl.pragmas) == "[attribute 'qualified_only']");
    CHECK(texts(gvl.blocks[0].vars[0].pragmas) == "[attribute 'hide']");
    CHECK(texts(gvl.blocks[0].vars[1].pragmas) == "");
    CHECK(texts(p->unit.types.at(0).pragmas) == "[attribute 'strict']");
    CHECK(texts(p->unit.types.at(1).pragmas) == "[attribute 'flags']");
    const Pou& fb = *p->unit.pous.at(0);
    CHECK(texts(fb.pragmas) == "[attribute 'call_after_init'][attribute 'no_check']");
    CHECK(fb.pragmas[0].loc.line == 16);
    CHECK(fb.pragmas[1].loc.col == 31);
    CHECK(texts(fb.vars.at(0).vars.at(0).pragmas) == "[attribute 'instance-path'][noinit]");
    CHECK(texts(fb.methods.at(0)->pragmas) == "[attribute 'm']");
    CHECK(texts(fb.properties.at(0).pragmas) == "[attribute 'monitoring' := 'call']");
}

TEST_CASE("declarations: everything is case-insensitive", "[parser][decl]") {
    auto p = parse(R"(
function_block fb extends base
var_input In1 : bool; end_var
method public m : int
m := 1;
end_method
if In1 then In1 := false; elsif not In1 then ; else ; end_if
case 1 of 1: ; end_case
for i := 1 to 2 by 1 do exit; end_for
while false do continue; end_while
repeat return; until true end_repeat
end_function_block
type e : (a, b); end_type
)");
    CHECK(p->errors() == "");
    CHECK(p->unit.pous.size() == 1);
    CHECK(p->unit.pous.at(0)->body.size() == 5);
}

TEST_CASE("declarations: element order inside a FUNCTION_BLOCK, top-level methods", "[parser][decl]") {
    auto p = parse(R"(
FUNCTION_BLOCK F
METHOD First
END_METHOD
VAR x : INT; END_VAR
PROPERTY P : INT
GET P := x; END_GET
END_PROPERTY
VAR_OUTPUT y : INT; END_VAR
x := 1;
METHOD Last : INT
Last := x;
END_METHOD
END_FUNCTION_BLOCK
METHOD Loose : BOOL
Loose := TRUE;
END_METHOD
)");
    REQUIRE(p->errors() == "");
    REQUIRE(p->unit.pous.size() == 2);
    const Pou& fb = *p->unit.pous[0];
    CHECK(fb.vars.size() == 2);
    CHECK(fb.methods.size() == 2);
    CHECK(fb.properties.size() == 1);
    CHECK(dump(fb.body) == "{(:= x 1)}");
    CHECK(p->unit.pous[1]->kind == PouKind::Method);
    CHECK(p->unit.pous[1]->name == "Loose");
}
