// The input stage (interpreter/source): TwinCAT and PLCopen XML become ST
// whose every line knows where it came from in the XML file.
#include <catch2/catch.hpp>

#include "interpreter/source/st_assembler.h"
#include "interpreter/source/st_textual_il.h"
#include "interpreter/source/xml_inputs.h"

using namespace strun;
using namespace strun::source;

TEST_CASE("text positions: offsets to 1-based line and column", "[source]") {
    TextPositions p("ab\ncd\n\nx");
    CHECK(p.at(0) == std::pair<int, int>{1, 1});
    CHECK(p.at(4) == std::pair<int, int>{2, 2});
    CHECK(p.at(7) == std::pair<int, int>{4, 1});
}

TEST_CASE("assembled ST maps copied and written lines back to the original", "[source]") {
    StAssembler a;
    a.written("PROGRAM P", 3, 5);
    a.verbatim("x := 1;\ny := 2;", 7, 20);
    SourceFile f{"p.xml", a.text(), a.origins()};
    CHECK(f.text == "PROGRAM P\nx := 1;\ny := 2;\n");
    CHECK(f.original(1, 9) == std::pair<int, int>{3, 5});    // written: the element's position
    CHECK(f.original(2, 1) == std::pair<int, int>{7, 20});   // first copied line: shifted by the CDATA column
    CHECK(f.original(3, 6) == std::pair<int, int>{8, 6});    // later lines: the same column
}

TEST_CASE("a TwinCAT POU gets its END keyword, methods and actions", "[source][twincat]") {
    const std::string xml =
        "<?xml version=\"1.0\"?>\n<TcPlcObject><POU Name=\"FB\"><Declaration><![CDATA[FUNCTION_BLOCK FB\nVAR x : INT; END_VAR]]></Declaration>"
        "<Implementation><ST><![CDATA[x := x + 1;]]></ST></Implementation>"
        "<Method Name=\"M\"><Declaration><![CDATA[METHOD M : INT]]></Declaration><Implementation><ST><![CDATA[M := x;]]></ST></Implementation></Method>"
        "<Action Name=\"A\"><Implementation><ST><![CDATA[x := 0;]]></ST></Implementation></Action></POU></TcPlcObject>";
    Converted c = readTwinCat(xml);
    REQUIRE(c.errors.empty());
    CHECK(c.text == "FUNCTION_BLOCK FB\nVAR x : INT; END_VAR\nx := x + 1;\nMETHOD M : INT\nM := x;\nEND_METHOD\nACTION A:\nx := 0;\nEND_ACTION\nEND_FUNCTION_BLOCK\n");
    REQUIRE(c.origins.size() == 10);
    CHECK(c.origins[0].line == 2);
}

TEST_CASE("XML that is not well-formed, and bodies in other languages, are errors", "[source]") {
    Converted broken = readTwinCat("<TcPlcObject><POU>");
    REQUIRE(broken.errors.size() == 1);
    CHECK(broken.errors[0].message.find("not well-formed XML") != std::string::npos);
    Converted fbd = readTwinCat("<TcPlcObject><POU Name=\"B\"><Declaration>PROGRAM B</Declaration><Implementation><SFC/></Implementation></POU></TcPlcObject>");
    REQUIRE(fbd.errors.size() == 1);
    CHECK(fbd.errors[0].message == "'B' has a body in SFC; strun runs Structured Text (ST) bodies only");
}

TEST_CASE("PLCopen: the namespace decides, variables and tasks become ST", "[source][plcopen]") {
    CHECK_FALSE(isPlcOpenProject("<project/>"));
    CHECK_FALSE(isPlcOpenProject("not xml"));
    const std::string xml =
        "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"><types><pous><pou name=\"P\" pouType=\"program\">"
        "<interface><localVars constant=\"true\"><variable name=\"n\"><type><INT/></type><initialValue><simpleValue value=\"3\"/></initialValue></variable></localVars></interface>"
        "<body><ST><xhtml>n := n;</xhtml></ST></body></pou></pous></types>"
        "<instances><configurations><configuration name=\"C\"><resource name=\"R\"><task name=\"T\" interval=\"PT0.05S\" priority=\"2\">"
        "<pouInstance name=\"p1\" typeName=\"P\"/></task></resource></configuration></configurations></instances></project>";
    REQUIRE(isPlcOpenProject(xml));
    Converted c = readPlcOpen(xml);
    REQUIRE(c.errors.empty());
    CHECK(c.text.find("VAR CONSTANT\n    n : INT := 3;\nEND_VAR") != std::string::npos);
    CHECK(c.text.find("TASK T (INTERVAL := T#0.05s, PRIORITY := 2);") != std::string::npos);
    CHECK(c.text.find("PROGRAM p1 WITH T : P;") != std::string::npos);
}

TEST_CASE("PLCopen: CODESYS's tc6_0200 form with the POUs in the resource's addData", "[source][plcopen]") {
    CHECK_FALSE(isPlcOpenProject("<project xmlns=\"http://www.plcopen.org/xml/tc6_0199\"/>"));
    const std::string xml =
        "<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\"><types><dataTypes/><pous/></types>"
        "<instances><configurations><configuration name=\"Device\"><resource name=\"App\">"
        "<task name=\"T\" interval=\"PT0.02S\" priority=\"1\"><pouInstance name=\"PLC_PRG\" typeName=\"\"/></task>"
        "<addData><data name=\"http://www.3s-software.com/plcopenxml/pou\" handleUnknown=\"implementation\">"
        "<pou name=\"PLC_PRG\" pouType=\"program\"><interface><localVars><variable name=\"x\"><type><INT/></type></variable></localVars></interface>"
        "<body><ST><xhtml>x := x + 1;</xhtml></ST></body></pou></data></addData>"
        "</resource></configuration></configurations></instances></project>";
    REQUIRE(isPlcOpenProject(xml));
    Converted c = readPlcOpen(xml);
    REQUIRE(c.errors.empty());
    CHECK(c.text.find("PROGRAM PLC_PRG\n") != std::string::npos);
    CHECK(c.text.find("x := x + 1;") != std::string::npos);
    CHECK(c.text.find("PROGRAM PLC_PRG WITH T : PLC_PRG;") != std::string::npos);
}

// Decisions 0464, 0493: which ST files may hold IL bodies (and are then read
// with the IL reader); the operator after END_VAR (or a label) decides.
TEST_CASE("an IL operator after END_VAR, END_METHOD or an ACTION marks a file as holding IL", "[source][il]") {
    using strun::source::mayHoldTextualIl;
    CHECK(mayHoldTextualIl("FUNCTION F : INT VAR_INPUT x : INT; END_VAR LD x ST F END_FUNCTION"));
    CHECK(mayHoldTextualIl("PROGRAM P VAR b : BOOL; END_VAR\n  (* c *) JMPCN done\ndone: RET END_PROGRAM"));
    CHECK(mayHoldTextualIl("PROGRAM P VAR END_VAR start: CALCN f END_PROGRAM"));  // a label, then the longest operators
    CHECK(mayHoldTextualIl("program p var c : CTU; end_var cu c END_PROGRAM"));     // any case; a block input operator
    CHECK(mayHoldTextualIl("METHOD M END_VAR RETCN END_METHOD"));
    CHECK(mayHoldTextualIl("ACTION Reset: LD FALSE ST x END_ACTION"));
    CHECK_FALSE(mayHoldTextualIl("PROGRAM P VAR x : INT; END_VAR x := x + 1; END_PROGRAM"));
    CHECK_FALSE(mayHoldTextualIl("PROGRAM P VAR END_VAR IF TRUE THEN END_IF; END_PROGRAM"));
    CHECK_FALSE(mayHoldTextualIl("PROGRAM P VAR END_VAR LDX := 1; END_PROGRAM"));         // a word longer than LD
    CHECK_FALSE(mayHoldTextualIl("PROGRAM P VAR END_VAR JMPCNX(); END_PROGRAM"));          // longer than any operator
    // The scan reads eight bytes at a time: END_VAR at every offset, bytes
    // that differ from E and A only in bit 5 or 6 around it, text ending in E.
    for (size_t pad = 0; pad < 20; ++pad) {
        const std::string before(pad, pad % 2 ? 'x' : '\xC5');
        INFO("pad " << pad);
        CHECK(mayHoldTextualIl(before + "END_VAR LD x"));
        CHECK(mayHoldTextualIl(before + "end_var\tst y"));
        CHECK_FALSE(mayHoldTextualIl(before + "END_VAR x := 1; %eE"));
        CHECK_FALSE(mayHoldTextualIl(before + "\x45\x65\x41\x61\x05\x25\x01\x21 END_IF ACTIONS"));
    }
}
