// See typed_atn_deserializer.h: ANTLR's serialized ATN (format version 3)
// read into the same objects as ANTLR's deserializer makes, with the state
// and transition kinds read from the objects instead of dynamic_cast.
#include "grammar/typed_atn_deserializer.h"

#include "grammar/atn_heap.h"

#include <Exceptions.h>
#include <atn/ATNState.h>
#include <atn/ATNType.h>
#include <atn/BlockEndState.h>
#include <atn/BlockStartState.h>
#include <atn/DecisionState.h>
#include <atn/LoopEndState.h>
#include <atn/PlusBlockStartState.h>
#include <atn/PlusLoopbackState.h>
#include <atn/RuleStartState.h>
#include <atn/RuleStopState.h>
#include <atn/RuleTransition.h>
#include <atn/EpsilonTransition.h>
#include <atn/StarLoopEntryState.h>
#include <atn/StarLoopbackState.h>
#include <atn/TokensStartState.h>
#include <atn/Transition.h>
#include <misc/IntervalSet.h>
#include <support/guid.h>

namespace strun_grammar {

using namespace antlr4::atn;

namespace {

bool isBlockStart(std::size_t type) {
    return type == ATNState::BLOCK_START || type == ATNState::PLUS_BLOCK_START || type == ATNState::STAR_BLOCK_START;
}

bool isDecision(std::size_t type) {
    return isBlockStart(type) || type == ATNState::TOKEN_START || type == ATNState::STAR_LOOP_ENTRY ||
           type == ATNState::PLUS_LOOP_BACK;
}

// The serialized words after the first (the version) are stored shifted by
// 2 (so that no word is 0 or 0xFFFF in a Java string); the reader undoes
// that word by word.
class Words {
public:
    explicit Words(const std::vector<uint16_t>& input) : input_(input) {}
    std::size_t next() { return uint16_t(input_[p_++] - 2); }
    std::size_t next32() {  // a code point above U+FFFF: low word, then high word
        std::size_t low = next();
        return low | (next() << 16);
    }
    std::size_t at(std::size_t offset) const { return uint16_t(input_[p_ + offset] - 2); }
    void skip(std::size_t n) { p_ += n; }

private:
    const std::vector<uint16_t>& input_;
    std::size_t p_ = 0;
};

// Version 3 with the UUID of the Unicode SMP sets (what ANTLR 4.7-4.9
// write) and a parser grammar: the only form read here.
bool knownForm(const std::vector<uint16_t>& input) {
    // The version word is the one stored without the shift.
    if (input.size() < 12 || input[0] != ATNDeserializer::SERIALIZED_VERSION) return false;
    uint16_t uuid[9];
    for (std::size_t i = 0; i < 9; ++i) uuid[i] = uint16_t(input[i] - 2);
    return ATNDeserializer::toUUID(uuid, 1) == ATNDeserializer::SERIALIZED_UUID() &&
           uint16_t(input[9] - 2) == std::size_t(ATNType::PARSER);
}

void readSets(Words& in, std::vector<antlr4::misc::IntervalSet>& sets, bool wide) {
    std::size_t count = in.next();
    for (std::size_t i = 0; i < count; ++i) {
        std::size_t intervals = in.next();
        antlr4::misc::IntervalSet set;
        if (in.next() != 0) set.add(-1);  // contains EOF
        for (std::size_t j = 0; j < intervals; ++j) {
            std::size_t a = wide ? in.next32() : in.next();
            std::size_t b = wide ? in.next32() : in.next();
            set.add(ssize_t(a), ssize_t(b));
        }
        sets.push_back(std::move(set));
    }
}

}  // namespace

bool TypedAtnDeserializer::readsForm(const std::vector<uint16_t>& input) { return knownForm(input); }

ATN TypedAtnDeserializer::deserialize(const std::vector<uint16_t>& input) {
    if (!knownForm(input)) return ATNDeserializer::deserialize(input);
    AtnHeap::Scope heap;  // the ATN's objects live until exit: bumped, not malloc'd
    Words in(input);
    in.skip(9);  // version, UUID
    ATNType grammarType = ATNType(in.next());
    std::size_t maxTokenType = in.next();
    ATN atn(grammarType, maxTokenType);

    // States; the loop-back and end states they name come later in the list.
    std::vector<std::pair<LoopEndState*, std::size_t>> loopBacks;
    std::vector<std::pair<BlockStartState*, std::size_t>> blockEnds;
    std::size_t stateCount = in.next();
    atn.states.reserve(stateCount);
    for (std::size_t i = 0; i < stateCount; ++i) {
        std::size_t type = in.next();
        if (type == ATNState::ATN_INVALID_TYPE) {
            atn.addState(nullptr);
            continue;
        }
        std::size_t ruleIndex = in.next();
        if (ruleIndex == 0xFFFF) ruleIndex = INVALID_INDEX;
        ATNState* state = stateFactory(type, ruleIndex);
        if (type == ATNState::LOOP_END)
            loopBacks.emplace_back(static_cast<LoopEndState*>(state), in.next());
        else if (isBlockStart(type))
            blockEnds.emplace_back(static_cast<BlockStartState*>(state), in.next());
        atn.addState(state);
    }
    for (auto& [state, number] : loopBacks) state->loopBackState = atn.states[number];
    for (auto& [state, number] : blockEnds) state->endState = static_cast<BlockEndState*>(atn.states[number]);

    std::size_t nonGreedy = in.next();
    for (std::size_t i = 0; i < nonGreedy; ++i) static_cast<DecisionState*>(atn.states[in.next()])->nonGreedy = true;
    std::size_t precedence = in.next();
    for (std::size_t i = 0; i < precedence; ++i)
        static_cast<RuleStartState*>(atn.states[in.next()])->isLeftRecursiveRule = true;

    // Rules (a parser's: start states only) and their stop states.
    std::size_t ruleCount = in.next();
    atn.ruleToStartState.reserve(ruleCount);
    for (std::size_t i = 0; i < ruleCount; ++i)
        atn.ruleToStartState.push_back(static_cast<RuleStartState*>(atn.states[in.next()]));
    atn.ruleToStopState.resize(ruleCount);
    for (ATNState* state : atn.states) {
        if (state == nullptr || state->getStateType() != ATNState::RULE_STOP) continue;
        auto* stop = static_cast<RuleStopState*>(state);
        atn.ruleToStopState[state->ruleIndex] = stop;
        atn.ruleToStartState[state->ruleIndex]->stopState = stop;
    }

    std::size_t modes = in.next();
    for (std::size_t i = 0; i < modes; ++i)
        atn.modeToStartState.push_back(static_cast<TokensStartState*>(atn.states[in.next()]));

    std::vector<antlr4::misc::IntervalSet> sets;
    readSets(in, sets, false);
    readSets(in, sets, true);

    // Edges: each state's transitions reserved first (one allocation per
    // state instead of a vector growing one transition at a time).
    std::size_t edgeCount = in.next();
    std::vector<uint32_t> outgoing(atn.states.size());
    for (std::size_t i = 0; i < edgeCount; ++i) ++outgoing[in.at(6 * i)];
    for (std::size_t i = 0; i < edgeCount; ++i) {
        std::size_t src = in.at(0);
        if (atn.states[src]->transitions.empty()) atn.states[src]->transitions.reserve(outgoing[src]);
        Transition* edge = edgeFactory(atn, in.at(2), src, in.at(1), in.at(3), in.at(4), in.at(5), sets);
        atn.states[src]->addTransition(edge);
        in.skip(6);
    }

    // The return edges of the rule stop states, derived from the rule transitions.
    for (ATNState* state : atn.states) {
        if (state == nullptr) continue;
        for (Transition* t : state->transitions) {
            if (t->getSerializationType() != Transition::RULE) continue;
            auto* call = static_cast<RuleTransition*>(t);
            std::size_t rule = call->target->ruleIndex;
            int outermostPrecedenceReturn = -1;
            if (atn.ruleToStartState[rule]->isLeftRecursiveRule && call->precedence == 0)
                outermostPrecedenceReturn = int(rule);
            atn.ruleToStopState[rule]->addTransition(new EpsilonTransition(call->followState, outermostPrecedenceReturn));
        }
    }

    for (ATNState* state : atn.states) {
        if (state == nullptr) continue;
        std::size_t type = state->getStateType();
        if (isBlockStart(type)) {
            auto* start = static_cast<BlockStartState*>(state);
            if (start->endState == nullptr || start->endState->startState != nullptr)
                throw antlr4::IllegalStateException();
            start->endState->startState = start;
        }
        if (type == ATNState::PLUS_LOOP_BACK) {
            for (Transition* t : state->transitions)
                if (t->target->getStateType() == ATNState::PLUS_BLOCK_START)
                    static_cast<PlusBlockStartState*>(t->target)->loopBackState = static_cast<PlusLoopbackState*>(state);
        } else if (type == ATNState::STAR_LOOP_BACK) {
            for (Transition* t : state->transitions)
                if (t->target->getStateType() == ATNState::STAR_LOOP_ENTRY)
                    static_cast<StarLoopEntryState*>(t->target)->loopBackState = static_cast<StarLoopbackState*>(state);
        }
    }

    std::size_t decisions = in.next();
    atn.decisionToState.reserve(decisions);
    for (std::size_t i = 0; i < decisions; ++i) {
        ATNState* state = atn.states[in.next()];
        if (state == nullptr || !isDecision(state->getStateType())) throw antlr4::IllegalStateException();
        auto* decision = static_cast<DecisionState*>(state);
        atn.decisionToState.push_back(decision);
        decision->decision = int(i);
    }

    // A precedence decision: the star loop of a left-recursive rule whose
    // loop end leads straight to the rule's stop state.
    for (ATNState* state : atn.states) {
        if (state == nullptr || state->getStateType() != ATNState::STAR_LOOP_ENTRY) continue;
        if (!atn.ruleToStartState[state->ruleIndex]->isLeftRecursiveRule) continue;
        ATNState* loopEnd = state->transitions.back()->target;
        if (loopEnd->getStateType() != ATNState::LOOP_END) continue;
        if (loopEnd->epsilonOnlyTransitions && loopEnd->transitions[0]->target->getStateType() == ATNState::RULE_STOP)
            static_cast<StarLoopEntryState*>(state)->isPrecedenceDecision = true;
    }
    return atn;
}

}  // namespace strun_grammar
