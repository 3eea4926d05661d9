// The generated parser's ATN as grammar/typed_atn_deserializer.h builds it
// (without dynamic_cast or verification, decision 0468) against ANTLR's own
// ATNDeserializer with its verifyATN: the same states, kinds, links and
// transitions, one by one. This is the check ANTLR would otherwise repeat at
// every start of strun.
#include <catch2/catch.hpp>

// The generated parser's contexts have methods THEN() and AND_THEN(), which
// are Catch2 macros (and Catch2 may come first in a unity batch).
#pragma push_macro("THEN")
#pragma push_macro("AND_THEN")
#undef THEN
#undef AND_THEN
#include "grammar/STLexer.h"
#include "grammar/STParser.h"
#pragma pop_macro("AND_THEN")
#pragma pop_macro("THEN")
#include "grammar/typed_atn_deserializer.h"

#include <antlr4-runtime.h>
#include <atn/ActionTransition.h>
#include <atn/BlockEndState.h>
#include <atn/BlockStartState.h>
#include <atn/EpsilonTransition.h>
#include <atn/LoopEndState.h>
#include <atn/PlusBlockStartState.h>
#include <atn/PrecedencePredicateTransition.h>
#include <atn/PredicateTransition.h>
#include <atn/RuleStartState.h>
#include <atn/RuleTransition.h>
#include <atn/StarLoopEntryState.h>

#include <string>
#include <vector>

using namespace antlr4::atn;

namespace {

long number(const ATNState* state) { return state ? long(state->stateNumber) : -1; }

std::string describe(Transition* t) {
    std::string out = std::to_string(int(t->getSerializationType())) + "->" + std::to_string(number(t->target));
    out += t->isEpsilon() ? " eps" : " " + t->label().toString();
    if (auto* rule = dynamic_cast<RuleTransition*>(t))
        out += " rule " + std::to_string(rule->ruleIndex) + " prec " + std::to_string(rule->precedence) + " follow " +
               std::to_string(number(rule->followState));
    if (auto* eps = dynamic_cast<EpsilonTransition*>(t))
        out += " outermost " + std::to_string(long(eps->outermostPrecedenceReturn()));
    if (auto* pred = dynamic_cast<PredicateTransition*>(t))
        out += " pred " + std::to_string(pred->ruleIndex) + "/" + std::to_string(pred->predIndex) +
               (pred->isCtxDependent ? " ctx" : "");
    if (auto* prec = dynamic_cast<PrecedencePredicateTransition*>(t)) out += " precpred " + std::to_string(prec->precedence);
    if (auto* action = dynamic_cast<ActionTransition*>(t))
        out += " action " + std::to_string(action->ruleIndex) + "/" + std::to_string(action->actionIndex);
    return out;
}

// One line per state (its kind, links and transitions), then the ATN's tables.
std::vector<std::string> describe(const ATN& atn) {
    std::vector<std::string> lines;
    lines.push_back("type " + std::to_string(int(atn.grammarType)) + " max " + std::to_string(atn.maxTokenType));
    for (ATNState* s : atn.states) {
        if (s == nullptr) {
            lines.push_back("null");
            continue;
        }
        std::string line = std::to_string(s->stateNumber) + " kind " + std::to_string(s->getStateType()) + " rule " +
                           std::to_string(long(s->ruleIndex)) + (s->epsilonOnlyTransitions ? " epsonly" : "");
        if (auto* d = dynamic_cast<DecisionState*>(s))
            line += " decision " + std::to_string(d->decision) + (d->nonGreedy ? " nongreedy" : "");
        if (auto* b = dynamic_cast<BlockStartState*>(s)) line += " end " + std::to_string(number(b->endState));
        if (auto* e = dynamic_cast<BlockEndState*>(s)) line += " start " + std::to_string(number(e->startState));
        if (auto* l = dynamic_cast<LoopEndState*>(s)) line += " loopback " + std::to_string(number(l->loopBackState));
        if (auto* p = dynamic_cast<PlusBlockStartState*>(s)) line += " plusloop " + std::to_string(number(p->loopBackState));
        if (auto* e = dynamic_cast<StarLoopEntryState*>(s))
            line += " starloop " + std::to_string(number(e->loopBackState)) + (e->isPrecedenceDecision ? " precedence" : "");
        if (auto* r = dynamic_cast<RuleStartState*>(s))
            line += " stop " + std::to_string(number(r->stopState)) + (r->isLeftRecursiveRule ? " leftrec" : "");
        for (Transition* t : s->transitions) line += " | " + describe(t);
        lines.push_back(line);
    }
    auto table = [&](const char* name, const auto& states) {
        std::string line = name;
        for (const auto* s : states) line += " " + std::to_string(number(s));
        lines.push_back(line);
    };
    table("decisions", atn.decisionToState);
    table("rulestart", atn.ruleToStartState);
    table("rulestop", atn.ruleToStopState);
    table("modes", atn.modeToStartState);
    return lines;
}

}  // namespace

TEST_CASE("the parser's ATN built by kind equals ANTLR's deserialized and verified ATN") {
    const std::vector<uint16_t>& serialized = strun_grammar::STParser::serializedATN();
    REQUIRE(strun_grammar::TypedAtnDeserializer::readsForm(serialized));

    ATNDeserializationOptions verify;
    verify.setVerifyATN(true);
    ATN reference = ATNDeserializer(verify).deserialize(serialized);
    ATN typed = strun_grammar::TypedAtnDeserializer().deserialize(serialized);

    const std::vector<std::string> expected = describe(reference);
    const std::vector<std::string> actual = describe(typed);
    REQUIRE(expected.size() > 1000);  // the grammar's 1 100-odd states and the tables
    REQUIRE(actual.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        INFO("line " << i);
        CHECK(actual[i] == expected[i]);
    }
    // And the ATN the parser runs on (built at static initialisation by the
    // generated code that grammar/typed_atn.cmake points at the typed reader).
    antlr4::ANTLRInputStream input("");
    strun_grammar::STLexer lexer(&input);
    antlr4::CommonTokenStream tokens(&lexer);
    strun_grammar::STParser parser(&tokens);
    CHECK(describe(parser.getATN()) == expected);
}

TEST_CASE("a serialized ATN in another form goes to ANTLR's deserializer") {
    std::vector<uint16_t> other = strun_grammar::STParser::serializedATN();
    other[0] = uint16_t(other[0] + 1);  // another format version
    CHECK_FALSE(strun_grammar::TypedAtnDeserializer::readsForm(other));
    CHECK_THROWS(strun_grammar::TypedAtnDeserializer().deserialize(other));  // ANTLR rejects the version
}
