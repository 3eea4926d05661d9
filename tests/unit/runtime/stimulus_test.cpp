// The scheduler's side of --set / --stimulus (runtime/stimulus.h): variable
// writes at the start of the first activation at or after their time,
// physical-input writes at their time exactly (also in the middle of an
// activation, and when nothing runs), the listener for input changes, and
// stable order for equal times.
#include <catch2/catch.hpp>

#include "tests/unit/runtime/fake_body.h"

using namespace strun::rt;
using namespace strun::rt::test;

namespace {

StimulusWrite variableWrite(PlcTime at, uint8_t* dest, uint8_t value, std::string text) {
    StimulusWrite w;
    w.at = at;
    w.dest = dest;
    w.bytes = {value};
    w.text = std::move(text);
    return w;
}

StimulusWrite inputWrite(Machine& machine, PlcTime at, size_t offset, int bit, uint8_t value, std::string text) {
    StimulusWrite w;
    w.at = at;
    w.kind = StimulusWrite::Kind::PhysicalInput;
    w.dest = machine.image.physicalInputs.data() + offset;
    w.inputOffset = offset;
    w.bit = bit;
    w.bytes = {value};
    w.text = std::move(text);
    return w;
}

}  // namespace

TEST_CASE("a variable write waits for the next activation start; equal times keep their order", "[stimulus]") {
    Scenario s;
    uint8_t variable = 0;
    std::vector<uint8_t> seen;
    FakeBody& body = s.add(cyclic("Cyc", 1, 10 * us), 3);
    body.onStatement = [&](int, int statement) {
        if (statement == 0) seen.push_back(variable);
    };
    Stimulus stimulus;
    stimulus.add(variableWrite(15 * us, &variable, 9, "v := 9"));
    stimulus.add(variableWrite(12 * us, &variable, 7, "v := 7"));
    stimulus.add(variableWrite(12 * us, &variable, 8, "v := 8"));
    RunOptions options = virtualFor(30 * us);
    options.stimulus = &stimulus;
    std::string trace = s.run(options);
    // 12 and 15 us fall between activations: all three apply at 20 us, in time order, equal times as added.
    CHECK(seen == std::vector<uint8_t>{0, 0, 9});
    CHECK(trace.find("T#20us Cyc start\nT#20us set v := 7\nT#20us set v := 8\nT#20us set v := 9\n") != std::string::npos);
}

TEST_CASE("a physical input changes at its time, mid-activation, and the next input phase shows it", "[stimulus]") {
    Scenario s;
    std::vector<int> inputAtStart, physicalMid;
    FakeBody& body = s.add(cyclic("Cyc", 1, 10 * us), 5);
    s.machine.image.inputExtent = 1;
    body.onStatement = [&](int, int statement) {
        if (statement == 0) inputAtStart.push_back(s.machine.image.inputs[0]);
        if (statement == 4) physicalMid.push_back(s.machine.image.physicalInputs[0]);
    };
    Stimulus stimulus;
    stimulus.add(inputWrite(s.machine, 2 * us, 0, 3, 1, "%IX0.3 := TRUE"));
    std::vector<PlcTime> changes;
    stimulus.setInputListener([&](const StimulusWrite& w, PlcTime at) { changes.push_back(at); });
    RunOptions options = virtualFor(20 * us);
    options.stimulus = &stimulus;
    std::string trace = s.run(options);
    CHECK(inputAtStart == std::vector<int>{0, 8});  // bit 3
    CHECK(physicalMid == std::vector<int>{8, 8});   // changed inside the first activation
    CHECK(changes == std::vector<PlcTime>{2 * us});
    CHECK(trace.find("T#0s Cyc start\nT#2us set %IX0.3 := TRUE\n") != std::string::npos);
}

TEST_CASE("an input write wakes the idle virtual clock at its time; an unchanged input tells no listener", "[stimulus]") {
    Scenario s;
    s.add(cyclic("Cyc", 1, 100 * us), 1);
    Stimulus stimulus;
    stimulus.add(inputWrite(s.machine, 37 * us, 4, -1, 0, "%IB4 := 0"));    // already 0: no change
    stimulus.add(inputWrite(s.machine, 41 * us, 4, -1, 200, "%IB4 := 200"));
    int told = 0;
    stimulus.setInputListener([&](const StimulusWrite&, PlcTime) { ++told; });
    RunOptions options = virtualFor(50 * us);
    options.stimulus = &stimulus;
    std::string trace = s.run(options);
    CHECK(s.machine.image.physicalInputs[4] == 200);
    CHECK(told == 1);
    CHECK(trace.find("T#37us set %IB4 := 0\nT#41us set %IB4 := 200\n") != std::string::npos);
    CHECK(stimulus.nextInputAt() == kNever);
}
