// The generated parser's ATN, built from its serialized form at start-up
// without ANTLR's run-time type tests (decision 0468).
//
// ANTLR 4.9's ATNDeserializer asks `dynamic_cast` about every state and
// every transition (is it a block start? a rule stop? a rule transition?),
// about 8 500 times for our grammar's 1 113 states, and then verifies the
// result with as many more. GCC's dynamic_cast compares type names with
// strcmp at every level of the class hierarchy: half of the instructions
// of a one-line `strun run` went there. The states and transitions know
// their kind (getStateType(), getSerializationType()), so this builds the
// same ATN asking them, and reserves each state's transitions before
// adding them. It is used only for the format it knows (version 3, the
// UUID of ANTLR 4.7-4.9, a parser grammar); anything else goes to ANTLR's
// own. tests/unit/ast/typed_atn_test.cpp compares the two, state by state
// and edge by edge, on the generated parser's ATN; that test is the
// verification ANTLR's verifyATN would run at every start.
#pragma once

#include <cstdint>
#include <vector>

#include <atn/ATN.h>
#include <atn/ATNDeserializer.h>

namespace strun_grammar {

class TypedAtnDeserializer : public antlr4::atn::ATNDeserializer {
public:
    antlr4::atn::ATN deserialize(const std::vector<uint16_t>& input) override;
    // Whether `input` is in the one form read here (else ANTLR's reads it).
    static bool readsForm(const std::vector<uint16_t>& input);
};

}  // namespace strun_grammar
