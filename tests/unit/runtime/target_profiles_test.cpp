// The target rows of runtime/plc_profile.cpp, their defaults and the M340
// system area (docs/targets.md has the rules; these pin the data behind them).
#include <catch2/catch.hpp>

#include "runtime/plc_profile.h"
#include "runtime/system_area.h"
#include "runtime/task_rules.h"
#include "fake_body.h"  // the test unit `ms`

using namespace strun::rt;
using strun::rt::test::ms;

namespace {
TaskSpec named(const char* name, TaskKind kind = TaskKind::Freewheeling) {
    TaskSpec spec;
    spec.name = name;
    spec.kind = kind;
    return spec;
}
}  // namespace

TEST_CASE("every target of the contract has a profile, found case-insensitively", "[targets]") {
    CHECK(profileIds() == "generic, baosky, ax3, m340, m241, xgi");
    for (const char* id : {"generic", "BAOSKY", "Ax3", "m340", "M241", "xgi"}) CHECK(findProfile(id) != nullptr);
    CHECK(findProfile("baosky-t3") == nullptr);
    CHECK(&defaultProfile() == findProfile("generic"));
    CHECK(profileWithSystemVariables() == findProfile("m340"));
    CHECK(profileWithTaskCycleFunctions() == findProfile("m241"));
}

TEST_CASE("M241 input aliases name bits of %I", "[targets]") {
    auto fi1 = findInputAlias(*findProfile("m241"), "fi1");
    REQUIRE(fi1);
    CHECK(fi1->byte == 0);
    CHECK(fi1->bit == 1);
    CHECK_FALSE(findInputAlias(*findProfile("m241"), "FI2"));
    CHECK_FALSE(findInputAlias(defaultProfile(), "FI0"));
}

TEST_CASE("defaults fill what a TASK leaves out", "[targets]") {
    const PlcProfile& baosky = *findProfile("baosky");
    TaskSpec cyclic = named("Cycle_1", TaskKind::Cyclic);
    CHECK(applyTaskDefaults(baosky, cyclic).empty());
    CHECK(cyclic.priority == 11);
    CHECK(cyclic.watchdog == 0);
    TaskSpec continuous = named("MainTask");
    applyTaskDefaults(baosky, continuous);
    CHECK(continuous.priority == 30);
    CHECK(continuous.watchdog == 200 * ms);

    const PlcProfile& m340 = *findProfile("m340");
    TaskSpec fast = named("Fast");
    CHECK(applyTaskDefaults(m340, fast).empty());
    CHECK(fast.kind == TaskKind::Cyclic);
    CHECK(fast.interval == 5 * ms);
    CHECK(fast.priority == 0);
    CHECK(fast.watchdog == 100 * ms);
    CHECK(fast.systemSlot == 1);
    TaskSpec mast = named("MAST");
    mast.priority = 7;
    mast.priorityGiven = true;
    CHECK(applyTaskDefaults(m340, mast) ==
          "the priority of task 'MAST' is fixed at 1 on Modicon M340; PRIORITY := 7 is ignored");
    CHECK(mast.kind == TaskKind::Freewheeling);  // cyclic mode
    CHECK(mast.priority == 1);
    CHECK(mast.watchdog == 250 * ms);
}

TEST_CASE("M340 rules: fixed names, AUX needs a periodic MAST", "[targets]") {
    const PlcProfile& m340 = *findProfile("m340");
    TaskSpec conveyor = named("Conveyor", TaskKind::Cyclic);
    conveyor.interval = 20 * ms;
    std::vector<TaskSpec> tasks{named("MAST"), named("AUX1"), conveyor};
    for (TaskSpec& t : tasks) applyTaskDefaults(m340, t);
    auto violations = checkTaskRules(m340, tasks);
    REQUIRE(violations.size() == 2);
    CHECK(violations[0].message == "task 'Conveyor': the tasks of Modicon M340 are MAST, FAST, AUX0, AUX1, AUX2, AUX3");
    CHECK(violations[1].message.find("task 'AUX1' needs a periodic MAST") == 0);
}

TEST_CASE("XGI allows 8 task programs in all, internal interrupts included (decision 0243)", "[targets]") {
    const PlcProfile& xgi = *findProfile("xgi");
    std::vector<TaskSpec> tasks;
    for (int i = 0; i < 9; ++i) {
        TaskSpec t = named(("E" + std::to_string(i)).c_str(), i % 2 ? TaskKind::Event : TaskKind::Status);
        applyTaskDefaults(xgi, t);
        tasks.push_back(t);
    }
    auto violations = checkTaskRules(xgi, tasks);
    REQUIRE(violations.size() == 1);
    // One message: the total (8 task programs) is reached with the group limit; not both.
    CHECK(violations[0].message == "task 'E8': at most 8 tasks are allowed on LS XGI");
}

TEST_CASE("the M340 system area keeps per-task words and bits", "[targets]") {
    ProcessImage image;
    SystemArea area(image, *findProfile("m340"));
    area.start({0, 5 * ms, 100 * ms, 200 * ms, 300 * ms, 400 * ms}, 250 * ms);
    auto word = [&](int n) { return int(image.systemWords[size_t(n) * 2] | (image.systemWords[size_t(n) * 2 + 1] << 8)); };
    auto bit = [&](int n) { return (image.systemBits[size_t(n) / 8] >> (n % 8)) & 1; };
    CHECK(word(0) == 0);
    CHECK(word(1) == 5);
    CHECK(word(2) == 10);  // AUX0: 100 ms in 10 ms units
    CHECK(word(5) == 40);
    CHECK(word(11) == 250);
    for (int n = 30; n <= 35; ++n) CHECK(bit(n) == 1);

    area.recordExecution(1, 3 * ms + 900 * kMicrosecond);
    area.recordExecution(1, 1 * ms);
    CHECK(word(33) == 1);  // current, truncated to ms
    CHECK(word(34) == 3);  // max
    CHECK(word(35) == 1);  // min

    // %S19: each task sees its own overrun bit.
    area.enter(1);
    area.setOverrun(1);
    CHECK(bit(19) == 1);
    area.leave(1);
    area.enter(0);
    CHECK(bit(19) == 0);
    area.leave(0);
    area.enter(1);
    CHECK(bit(19) == 1);

    // A period word outside the task's range is not taken into account.
    image.systemWords[2 * 2] = 0;  // AUX0 := 0
    CHECK(area.requestedPeriod(2, 100 * ms) == 100 * ms);
    image.systemWords[2 * 2] = 25;  // 250 ms
    CHECK(area.requestedPeriod(2, 100 * ms) == 250 * ms);
}
