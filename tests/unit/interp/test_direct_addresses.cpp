// Direct addresses (AT %I / %Q / %M) map onto the process image with the
// CODESYS addressing of runtime/machine.h: %IX0.3 is bit 3 of byte 0, %QW1 is
// bytes 2..3, %MD2 is bytes 8..11 (the index counts units of the access size).
#include <catch2/catch.hpp>

#include "tests/unit/interp/st_run.h"

using namespace strun;
using namespace strun::test;

TEST_CASE("direct addresses map onto the bytes of the process image", "[checker][address]") {
    RunSettings settings;
    settings.cycles = 1;
    settings.beforeRun = [](sema::ProgramModel& model) {
        model.machine.image.physicalInputs[0] = 0x08;  // only %IX0.3 set
        model.machine.image.physicalInputs[4] = 0x34;  // %IW2 = bytes 4..5
        model.machine.image.physicalInputs[5] = 0x12;
    };
    auto r = runSt(R"(
PROGRAM Main
VAR
    bit3 AT %IX0.3 : BOOL;
    bit2 AT %IX0.2 : BOOL;
    inWord AT %IW2 : WORD;
    outWord AT %QW1 : WORD;
    outBit AT %QX4.5 : BOOL;
    lowByte AT %QB2 : BYTE;
    mem AT %MD2 : DWORD;
    copyBit3, copyBit2 : BOOL;
    copyWord : WORD;
    copyLow : BYTE;
END_VAR
copyBit3 := bit3;
copyBit2 := bit2;
copyWord := inWord;
outWord := 16#1234;
outBit := TRUE;
copyLow := lowByte;
mem := 16#AABBCCDD;
END_PROGRAM
)", settings);
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "copyBit3") == true);
    CHECK(r.var("Main", "copyBit2") == false);
    CHECK(r.var("Main", "copyWord") == 0x1234);
    CHECK(r.var("Main", "bit3") == true);
    CHECK(r.var("Main", "outBit") == true);
    CHECK(r.var("Main", "copyLow") == 0x34);  // %QB2 is the low byte of %QW1
    const rt::ProcessImage& img = r.image();
    // %QW1 = bytes 2..3, little-endian.
    CHECK(img.outputs[2] == 0x34);
    CHECK(img.outputs[3] == 0x12);
    CHECK(img.outputs[0] == 0);
    CHECK(img.outputs[1] == 0);
    CHECK(img.outputs[4] == 0x20);  // %QX4.5
    // %MD2 = bytes 8..11.
    CHECK(img.memory[8] == 0xDD);
    CHECK(img.memory[9] == 0xCC);
    CHECK(img.memory[10] == 0xBB);
    CHECK(img.memory[11] == 0xAA);
    CHECK(img.memory[7] == 0);
    CHECK(img.memory[12] == 0);
    // The task end copies %Q to the field.
    CHECK(img.physicalOutputs[2] == 0x34);
    CHECK(img.physicalOutputs[3] == 0x12);
    CHECK(img.physicalOutputs[4] == 0x20);
}

TEST_CASE("two variables at the same address share storage", "[checker][address]") {
    auto r = runMain("a AT %MW10 : WORD; b AT %MW10 : WORD; hi AT %MB21 : BYTE; seen : WORD;",
                     "a := 16#BEEF; seen := b;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.var("Main", "seen") == 0xBEEF);
    CHECK(r.var("Main", "hi") == 0xBE);  // %MW10 = bytes 20..21
    CHECK(r.image().memory[20] == 0xEF);
}

TEST_CASE("a written BOOL bit leaves the other bits of its byte alone", "[checker][address]") {
    auto r = runMain("whole AT %QB0 : BYTE; b1 AT %QX0.1 : BOOL; b7 AT %QX0.7 : BOOL;",
                     "whole := 16#0F; b1 := FALSE; b7 := TRUE;");
    INFO(r.compiled->printed());
    REQUIRE(r.ok());
    CHECK(r.image().outputs[0] == 0x8D);
    CHECK(r.var("Main", "whole") == 0x8D);
}

TEST_CASE("malformed direct addresses are errors", "[checker][address]") {
    auto badBit = compileMain("x AT %IX0.8 : BOOL;", "");
    INFO(badBit->printed());
    CHECK(badBit->hasError("bad direct address '%IX0.8': bit number above 7"));
    auto notBool = compileMain("x AT %IX0.1 : INT;", "");
    INFO(notBool->printed());
    CHECK(notBool->hasError("a bit address needs a BOOL variable"));
    auto wordBit = compileMain("x AT %MW1.3 : BOOL;", "");
    INFO(wordBit->printed());
    CHECK(wordBit->hasError("a bit number only goes with X addresses"));
    auto area = compileMain("x AT %ZX0.0 : BOOL;", "");
    INFO(area->printed());
    CHECK_FALSE(area->ok());
    auto outside = compileMain("x AT %QD70000 : DWORD;", "");
    INFO(outside->printed());
    CHECK(outside->hasError("address outside the process image"));
}

TEST_CASE("a variable larger than its address unit is a warning", "[checker][address]") {
    auto c = compileMain("x AT %MW4 : DINT;", "x := 1;");
    INFO(c->printed());
    REQUIRE(c->ok());
    CHECK(c->hasWarning("DINT is larger than the 2-byte address '%MW4'"));
}
