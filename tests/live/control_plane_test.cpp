// The control plane (live/control_plane.h) without HTTP: snapshots are one
// consistent state even with preemption and a reader hammering them, forces
// and writes land at activation boundaries, step counts cycles.
#include <atomic>
#include <thread>

#include <catch2/catch.hpp>

#include "live/control_plane.h"
#include "tests/unit/interp/st_run.h"

using namespace strun;

namespace {

struct LiveRun {
    std::unique_ptr<test::Compiled> compiled;
    std::vector<rt::TaskSpec> specs;
    std::vector<std::unique_ptr<project::TaskRunner>> runners;
    std::vector<rt::TaskBody*> bodies;
    std::unique_ptr<live::ControlPlane> control;

    explicit LiveRun(const std::string& source) {
        compiled = test::compileSt(source);
        REQUIRE(compiled->ok());
        sema::ProgramModel& model = *compiled->model;
        for (const auto& t : model.tasks) specs.push_back(t.spec);
        for (const auto& t : model.tasks) {
            runners.push_back(std::make_unique<project::TaskRunner>(model, t));
            bodies.push_back(runners.back().get());
        }
        control = std::make_unique<live::ControlPlane>(model, rt::defaultProfile(), specs, specs.front().name);
    }
    rt::PlcState run(uint64_t cycles, const std::string& task = "") {
        rt::RunOptions options;
        options.virtualClock = true;
        options.cycles = cycles;
        options.cyclesTask = task.empty() ? specs.front().name : task;
        options.live = control.get();
        rt::Scheduler scheduler(compiled->model->machine, specs, bodies, options);
        rt::PlcState state = scheduler.run();
        control->runEnded(scheduler);
        return state;
    }
    nlohmann::ordered_json value(const std::string& path) {
        const live::LiveVariable* v = control->findVariable(path);
        REQUIRE(v);
        return live::ControlPlane::valueJson(*control->latest(), *v);
    }
};

// Fast preempts Slow in the middle of its long activation; both keep a pair
// of variables equal at their activation's end only.
const char* kPreempting = R"(
PROGRAM FastP
VAR a : DINT; b : DINT; END_VAR
a := a + 1;
b := a;
END_PROGRAM
PROGRAM SlowP
VAR c : DINT; d : DINT; i : DINT; END_VAR
c := c + 1;
FOR i := 1 TO 3000 DO
    d := d;
END_FOR
d := c;
END_PROGRAM
CONFIGURATION Cfg
    RESOURCE R ON PLC
        TASK Fast (INTERVAL := T#1ms, PRIORITY := 1);
        TASK Slow (INTERVAL := T#20ms, PRIORITY := 5);
        PROGRAM F WITH Fast : FastP;
        PROGRAM S WITH Slow : SlowP;
    END_RESOURCE
END_CONFIGURATION
)";

}  // namespace

TEST_CASE("a snapshot is one consistent state, never two activations mixed") {
    LiveRun run(kPreempting);
    const live::LiveVariable* a = run.control->findVariable("F.a");
    const live::LiveVariable* b = run.control->findVariable("f.B");
    const live::LiveVariable* c = run.control->findVariable("S.c");
    const live::LiveVariable* d = run.control->findVariable("S.d");
    REQUIRE((a && b && c && d));
    std::atomic<bool> done{false};
    std::atomic<uint64_t> checked{0}, mixed{0};
    std::atomic<bool> started{false};
    std::thread reader([&] {
        uint64_t seen = 0;
        started.store(true);
        while (!done.load() || checked.load() == 0) {
            run.control->waitForSnapshot(seen, std::chrono::milliseconds(5));
            auto snap = run.control->latest();
            seen = snap->sequence;
            if (live::ControlPlane::valueJson(*snap, *a) != live::ControlPlane::valueJson(*snap, *b) ||
                live::ControlPlane::valueJson(*snap, *c) != live::ControlPlane::valueJson(*snap, *d))
                ++mixed;
            ++checked;
        }
    });
    while (!started.load()) std::this_thread::yield();
    run.run(600, "Slow");
    done.store(true);
    reader.join();
    CHECK(mixed.load() == 0);
    CHECK(checked.load() > 0);
    CHECK(run.control->latest()->ended);
    CHECK(run.value("S.c") == 600);
    CHECK(run.value("S.d") == 600);
    // The timeline saw Slow preempted by Fast: Slow resumed more often than it started.
    uint64_t slowRuns = 0;
    for (const live::TimelineEvent& e : run.control->timeline(0)) slowRuns += e.task == 1 && e.running;
    CHECK(slowRuns > 600);
}

TEST_CASE("forces hold at activation boundaries; writes land once") {
    LiveRun run(R"(
PROGRAM Main
VAR x : INT; seen : INT; level : REAL; copy : BOOL; inp AT %IX0.0 : BOOL; out AT %QX0.1 : BOOL; END_VAR
x := x + 1;
seen := x;
copy := inp;
out := FALSE;
END_PROGRAM)");
    std::string error;
    REQUIRE(run.control->forceAtStart("Main.x", "7", error));
    REQUIRE(run.control->forceAtStart("%IX0.0", "TRUE", error));
    REQUIRE(run.control->forceAtStart("%qx0.1", "1", error));
    REQUIRE(run.control->write("Main.level", "2.5", error));
    CHECK_FALSE(run.control->write("Main.nothing", "1", error));
    CHECK(error.find("no variable 'nothing'") != std::string::npos);
    CHECK_FALSE(run.control->force("Main.x", "70000", error));
    CHECK(error.find("does not fit INT") != std::string::npos);
    run.run(5);
    CHECK(run.value("Main.x") == 7);
    CHECK(run.value("Main.seen") == 8);
    CHECK(run.value("Main.copy") == true);
    CHECK(run.value("Main.out") == true);
    CHECK(run.value("Main.level") == 2.5);
    auto snap = run.control->latest();
    CHECK((snap->outputs.at(0) & 2) == 2);  // the image: %QX0.1 as the outputs got it
    CHECK(run.control->forcesJson() == nlohmann::ordered_json::parse(R"({"Main.x": 7, "%IX0.0": true, "%QX0.1": true})"));
    CHECK(run.control->unforce("main.X", error));
    CHECK(run.control->forcesJson().size() == 2);
}

TEST_CASE("step on the virtual clock: K cycles of the task, then paused with time standing still") {
    LiveRun run(kPreempting);
    run.control->startPaused();
    // Catch2 assertions are not thread-safe: the driver records, the test checks.
    bool pausedAtStart = false, pausedAfterStep = false, timeStill = false, refusedTask = false, refusedZero = false;
    uint64_t firstSequence = 99, slowCycles = 0;
    std::thread driver([&] {
        std::string error;
        pausedAtStart = run.control->waitUntilPaused(std::chrono::milliseconds(10000));
        firstSequence = run.control->latest()->sequence;
        run.control->startStep("Slow", 2, error);
        pausedAfterStep = run.control->waitUntilPaused(std::chrono::milliseconds(10000));
        auto snap = run.control->latest();
        slowCycles = snap->tasks[1].cycles;
        rt::PlcTime at = snap->time;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        timeStill = run.control->latest()->time == at;
        refusedTask = !run.control->startStep("Nope", 1, error);
        refusedZero = !run.control->startStep("", 0, error);
        run.control->resume();
    });
    run.run(5, "Slow");
    driver.join();
    CHECK(pausedAtStart);
    CHECK(firstSequence == 0);
    CHECK(pausedAfterStep);
    CHECK(slowCycles == 2);
    CHECK(timeStill);
    CHECK(refusedTask);
    CHECK(refusedZero);
    CHECK(run.value("S.c") == 5);
}

TEST_CASE("writes queued together land in the same activation, or none when one is refused") {
    LiveRun run(R"(
PROGRAM Main
VAR a : INT; b : INT; sum : INT; END_VAR
sum := a + b;
END_PROGRAM)");
    std::string error;
    // One refused item: nothing of the batch is queued.
    CHECK_FALSE(run.control->writeTogether({{"Main.a", "1"}, {"Main.nothing", "2"}}, error));
    CHECK(error.find("no variable 'nothing'") != std::string::npos);
    CHECK_FALSE(run.control->writeTogether({{"Main.a", "5"}, {"Main.b", "99999"}}, error));
    CHECK(error.find("does not fit INT") != std::string::npos);
    REQUIRE(run.control->writeTogether({{"Main.a", "20"}, {"%MW3", "4"}, {"Main.b", "22"}}, error));
    run.run(1);
    CHECK(run.value("Main.a") == 20);
    CHECK(run.value("Main.b") == 22);
    CHECK(run.value("Main.sum") == 42);  // both in place when the first activation ran
}
