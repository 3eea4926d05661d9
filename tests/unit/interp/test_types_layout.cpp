// The type system: storage size and alignment of every elementary type,
// strings, arrays, structures, and the initial images of enumerations,
// subranges, structures with member initialisers and FB instances.
#include <catch2/catch.hpp>

#include "interpreter/sema/types.h"
#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;
using sema::TK;

namespace {

struct Elementary {
    TK kind;
    const char* name;
    uint32_t size;
    uint32_t align;
};

const Elementary kElementary[] = {
    {TK::Bool, "BOOL", 1, 1},       {TK::SInt, "SINT", 1, 1},         {TK::Int, "INT", 2, 2},
    {TK::DInt, "DINT", 4, 4},       {TK::LInt, "LINT", 8, 8},         {TK::USInt, "USINT", 1, 1},
    {TK::UInt, "UINT", 2, 2},       {TK::UDInt, "UDINT", 4, 4},       {TK::ULInt, "ULINT", 8, 8},
    {TK::Byte, "BYTE", 1, 1},       {TK::Word, "WORD", 2, 2},         {TK::DWord, "DWORD", 4, 4},
    {TK::LWord, "LWORD", 8, 8},     {TK::Real, "REAL", 4, 4},         {TK::LReal, "LREAL", 8, 8},
    {TK::Time, "TIME", 4, 4},       {TK::LTime, "LTIME", 8, 8},       {TK::Date, "DATE", 4, 4},
    {TK::Tod, "TIME_OF_DAY", 4, 4}, {TK::Dt, "DATE_AND_TIME", 4, 4},  {TK::LDate, "LDATE", 8, 8},
    {TK::LTod, "LTIME_OF_DAY", 8, 8}, {TK::LDt, "LDATE_AND_TIME", 8, 8}, {TK::Char, "CHAR", 1, 1},
    {TK::WChar, "WCHAR", 2, 2},     {TK::String, "STRING", 81, 1},    {TK::WString, "WSTRING", 162, 2},
};

const sema::Field& field(const sema::Type* t, const std::string& name) {
    const sema::Field* f = t->findField(sema::upper(name));
    REQUIRE(f != nullptr);
    return *f;
}

}  // namespace

TEST_CASE("every elementary type has its IEC storage size and natural alignment", "[types]") {
    sema::TypeTable table;
    for (const auto& e : kElementary) {
        INFO(e.name);
        const sema::Type* t = table.elementary(e.kind);
        REQUIRE(t != nullptr);
        CHECK(t->kind == e.kind);
        CHECK(t->name == e.name);
        CHECK(t->size == e.size);
        CHECK(t->align == e.align);
        CHECK(table.byName(e.name) == t);
    }
}

TEST_CASE("short names of the date and time types name the same types", "[types]") {
    sema::TypeTable table;
    CHECK(table.byName("TOD") == table.elementary(TK::Tod));
    CHECK(table.byName("DT") == table.elementary(TK::Dt));
    CHECK(table.byName("LTOD") == table.elementary(TK::LTod));
    CHECK(table.byName("LDT") == table.elementary(TK::LDt));
    CHECK(table.byName("ARRAY") == nullptr);
    CHECK(table.byName("VOID") == nullptr);
}

TEST_CASE("STRING of n characters stores n bytes plus a terminator", "[types]") {
    sema::TypeTable table;
    const sema::Type* s10 = table.string(10, false);
    CHECK(s10->kind == TK::String);
    CHECK(s10->size == 11);
    CHECK(s10->maxLen == 10);
    CHECK(s10->name == "STRING[10]");
    CHECK(table.string(10, false) == s10);  // interned
    const sema::Type* w10 = table.string(10, true);
    CHECK(w10->size == 22);
    CHECK(w10->align == 2);
    CHECK(table.string(80, false) == table.elementary(TK::String));
    CHECK(table.string(1, false)->size == 2);
}

TEST_CASE("array types multiply their element size and keep its alignment", "[types]") {
    sema::TypeTable table;
    const sema::Type* a = table.array(table.elementary(TK::Int), {{1, 3}}, false);
    CHECK(a->size == 6);
    CHECK(a->elemCount == 3);
    CHECK(a->align == 2);
    CHECK(a->name == "ARRAY[1..3] OF INT");
    const sema::Type* m = table.array(table.elementary(TK::DInt), {{0, 1}, {-2, 2}}, false);
    CHECK(m->size == 40);
    CHECK(m->elemCount == 10);
    CHECK(m->name == "ARRAY[0..1,-2..2] OF DINT");
    const sema::Type* flex = table.array(table.elementary(TK::Int), {{0, -1}}, true);
    CHECK(flex->size == 0);
    CHECK(flex->flexible);
}

TEST_CASE("typeName and sameType", "[types]") {
    sema::TypeTable table;
    CHECK(sema::typeName(nullptr) == "?");
    CHECK(sema::typeName(table.elementary(TK::LReal)) == "LREAL");
    // Strings of any length are the same type for assignment.
    CHECK(sema::sameType(table.string(10, false), table.string(20, false)));
    CHECK_FALSE(sema::sameType(table.string(10, false), table.string(10, true)));
    CHECK_FALSE(sema::sameType(table.elementary(TK::Int), table.elementary(TK::DInt)));
    CHECK(sema::sameType(table.pointer(table.elementary(TK::Int)), table.pointer(table.elementary(TK::Int))));
    CHECK_FALSE(sema::sameType(table.pointer(table.elementary(TK::Int)), table.pointer(table.elementary(TK::UInt))));
    // Arrays: same element type and element count.
    const sema::Type* a = table.array(table.elementary(TK::Int), {{1, 3}}, false);
    const sema::Type* b = table.array(table.elementary(TK::Int), {{0, 2}}, false);
    const sema::Type* c = table.array(table.elementary(TK::Int), {{0, 3}}, false);
    CHECK(sema::sameType(a, b));
    CHECK_FALSE(sema::sameType(a, c));
    CHECK_FALSE(sema::sameType(a, nullptr));
}

TEST_CASE("classification helpers and bit widths", "[types]") {
    CHECK(sema::isSignedInt(TK::LInt));
    CHECK_FALSE(sema::isSignedInt(TK::UDInt));
    CHECK(sema::isUnsignedInt(TK::USInt));
    CHECK(sema::isBitString(TK::LWord));
    CHECK_FALSE(sema::isBitString(TK::Bool));
    CHECK(sema::isAnyBit(TK::Bool));
    CHECK(sema::bitWidth(TK::Bool) == 1);
    CHECK(sema::bitWidth(TK::SInt) == 8);
    CHECK(sema::bitWidth(TK::WChar) == 16);
    CHECK(sema::bitWidth(TK::Time) == 32);
    CHECK(sema::bitWidth(TK::LTime) == 64);
    CHECK(sema::integerView(TK::Word) == TK::UInt);
    CHECK(sema::integerView(TK::Time) == TK::DInt);
}

TEST_CASE("structure members are aligned to their size and the size is padded", "[types]") {
    auto c = compileSt(R"(
TYPE Mixed : STRUCT
    a : BYTE;
    b : DINT;
    c : INT;
END_STRUCT; END_TYPE
TYPE Wide : STRUCT
    flag : BOOL;
    value : LREAL;
END_STRUCT; END_TYPE
PROGRAM Main
VAR m : Mixed; w : Wide; s : STRUCT_HOLDER; END_VAR
m.a := 1; w.flag := TRUE; s.inner.c := 2;
END_PROGRAM
TYPE STRUCT_HOLDER : STRUCT
    tag : CHAR;
    inner : Mixed;
    text : STRING[3];
END_STRUCT; END_TYPE
)");
    INFO(c->printed());
    REQUIRE(c->ok());
    const sema::Type* mixed = c->typeOf("Main", "m");
    REQUIRE(mixed != nullptr);
    CHECK(mixed->kind == TK::Struct);
    CHECK(field(mixed, "a").offset == 0);
    CHECK(field(mixed, "b").offset == 4);
    CHECK(field(mixed, "c").offset == 8);
    CHECK(mixed->size == 12);
    CHECK(mixed->align == 4);
    const sema::Type* wide = c->typeOf("Main", "w");
    CHECK(field(wide, "value").offset == 8);
    CHECK(wide->size == 16);
    CHECK(wide->align == 8);
    const sema::Type* holder = c->typeOf("Main", "s");
    CHECK(field(holder, "inner").offset == 4);
    CHECK(field(holder, "text").offset == 16);
    CHECK(holder->size == 20);  // 16 + 4 bytes of STRING[3], padded to 4
}

TEST_CASE("arrays declared in a program have the declared bounds and size", "[types]") {
    auto c = compileMain("a : ARRAY[1..10] OF INT; m : ARRAY[0..2, 1..4] OF LREAL; s : ARRAY[-1..1] OF STRING[5];",
                         "a[1] := 1; m[0, 1] := 1.0; s[0] := 'x';");
    INFO(c->printed());
    REQUIRE(c->ok());
    const sema::Type* a = c->typeOf("Main", "a");
    CHECK(a->size == 20);
    CHECK(a->dims.size() == 1);
    CHECK(a->dims[0].lo == 1);
    CHECK(a->dims[0].hi == 10);
    const sema::Type* m = c->typeOf("Main", "m");
    CHECK(m->size == 96);
    CHECK(m->align == 8);
    const sema::Type* s = c->typeOf("Main", "s");
    CHECK(s->size == 18);
    CHECK(s->elem->maxLen == 5);
}

TEST_CASE("program variables are laid out in declaration order with alignment", "[types]") {
    auto c = compileMain("b : BOOL; d : DINT; i : INT; l : LINT;", "b := TRUE; d := 1; i := 2; l := 3;");
    INFO(c->printed());
    REQUIRE(c->ok());
    const auto* b = c->var("Main", "b");
    const auto* d = c->var("Main", "d");
    const auto* i = c->var("Main", "i");
    const auto* l = c->var("Main", "l");
    REQUIRE((b && d && i && l));
    CHECK(b->storage == sema::Storage::Self);
    CHECK(d->offset % 4 == 0);
    CHECK(d->offset > b->offset);
    CHECK(i->offset > d->offset);
    CHECK(l->offset % 8 == 0);
    CHECK(l->offset > i->offset);
}

TEST_CASE("elementary variables start at zero values", "[types]") {
    auto r = runMain(R"(
b : BOOL; si : SINT; ud : UDINT; w : WORD; re : REAL; lr : LREAL; t : TIME; lt : LTIME;
d : DATE; tod1 : TOD; dt1 : DT; c : CHAR; s : STRING; ws : WSTRING;)",
                     "");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "b") == false);
    CHECK(r.var("Main", "si") == 0);
    CHECK(r.var("Main", "ud") == 0);
    CHECK(r.var("Main", "w") == 0);
    CHECK(r.var("Main", "re") == 0.0);
    CHECK(r.var("Main", "lr") == 0.0);
    CHECK(r.var("Main", "t") == "T#0s");
    CHECK(r.var("Main", "lt") == "T#0s");
    CHECK(r.var("Main", "d") == "D#1970-01-01");
    CHECK(r.var("Main", "tod1") == "TOD#00:00:00");
    CHECK(r.var("Main", "dt1") == "DT#1970-01-01-00:00:00");
    CHECK(r.var("Main", "c") == "");
    CHECK(r.var("Main", "s") == "");
    CHECK(r.var("Main", "ws") == "");
}

TEST_CASE("an enumeration defaults to its first value or to the declared initial value", "[types]") {
    auto r = runSt(R"(
TYPE Color : (RED, GREEN, BLUE); END_TYPE
TYPE Level : (LOW := 10, MID := 20, HIGH := 30) := MID; END_TYPE
TYPE Code : DINT (A := -5, B := 7); END_TYPE
PROGRAM Main
VAR c : Color; l : Level; k : Code; inline : (ONE, TWO); e : Color := BLUE; END_VAR
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "c") == "RED");
    CHECK(r.var("Main", "l") == "MID");
    CHECK(r.var("Main", "k") == "A");
    CHECK(r.var("Main", "inline") == "ONE");
    CHECK(r.var("Main", "e") == "BLUE");
    const sema::Type* level = r.compiled->typeOf("Main", "l");
    REQUIRE(level != nullptr);
    CHECK(level->kind == TK::Enum);
    CHECK(level->enumDefault == 20);
    CHECK(level->base->kind == TK::Int);
    const sema::Type* code = r.compiled->typeOf("Main", "k");
    CHECK(code->base->kind == TK::DInt);
    CHECK(code->size == 4);
}

TEST_CASE("a subrange that excludes zero starts at its lower bound", "[types]") {
    auto r = runSt(R"(
TYPE Percent : USINT(0..100); END_TYPE
TYPE Gear : INT(1..6); END_TYPE
PROGRAM Main
VAR p : Percent; g : Gear; neg : INT(-10..-3); named : Gear := 4; END_VAR
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "p") == 0);
    CHECK(r.var("Main", "g") == 1);
    CHECK(r.var("Main", "neg") == -10);
    CHECK(r.var("Main", "named") == 4);
    const sema::Type* gear = r.compiled->typeOf("Main", "g");
    CHECK(gear->isSubrange);
    CHECK(gear->rangeLo == 1);
    CHECK(gear->rangeHi == 6);
    CHECK(gear->size == 2);
}

TEST_CASE("structure member initialisers give the default and a variable initialiser overrides some", "[types]") {
    auto r = runSt(R"(
TYPE Point : STRUCT
    x : INT := 7;
    y : REAL := 1.5;
    name : STRING[8] := 'origin';
END_STRUCT; END_TYPE
TYPE Point3 EXTENDS Point : STRUCT
    z : DINT := -1;
END_STRUCT; END_TYPE
PROGRAM Main
VAR
    p : Point;
    q : Point := (y := 2.5);
    r3 : Point3;
    arr : ARRAY[1..2] OF Point;
END_VAR
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "p") == nlohmann::ordered_json::parse(R"({"x":7,"y":1.5,"name":"origin"})"));
    CHECK(r.var("Main", "q") == nlohmann::ordered_json::parse(R"({"x":7,"y":2.5,"name":"origin"})"));
    CHECK(r.var("Main", "r3") == nlohmann::ordered_json::parse(R"({"x":7,"y":1.5,"name":"origin","z":-1})"));
    CHECK(r.var("Main", "arr")[1]["x"] == 7);
}

TEST_CASE("FB instances start from the FB image including nested instances", "[types]") {
    auto r = runSt(R"(
FUNCTION_BLOCK Inner
VAR_INPUT start : INT := 3; END_VAR
VAR_OUTPUT doubled : INT; END_VAR
VAR count : INT := 5; END_VAR
doubled := start * 2;
END_FUNCTION_BLOCK
FUNCTION_BLOCK Outer
VAR_OUTPUT total : INT := 100; END_VAR
VAR a : Inner; b : Inner := (start := 9); END_VAR
END_FUNCTION_BLOCK
PROGRAM Main
VAR o : Outer; list : ARRAY[0..1] OF Inner; END_VAR
END_PROGRAM
)");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    // Never called: the dump shows the initial images.
    const auto& o = r.var("Main", "o");
    CHECK(o["total"] == 100);
    CHECK(o["a"]["start"] == 3);
    CHECK(o["a"]["count"] == 5);
    CHECK(o["a"]["doubled"] == 0);
    CHECK(o["b"]["start"] == 9);
    CHECK(o["b"]["count"] == 5);
    CHECK(r.var("Main", "list")[1]["count"] == 5);
    const sema::Type* outer = r.compiled->typeOf("Main", "o");
    REQUIRE(outer != nullptr);
    CHECK(outer->kind == TK::FunctionBlock);
    CHECK(outer->align == 8);
    CHECK(outer->size % 8 == 0);
    // Every instance starts with its class pointer: the first member comes after it.
    CHECK(field(outer, "total").offset >= 8);
}
