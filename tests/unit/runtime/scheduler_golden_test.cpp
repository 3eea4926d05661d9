// Golden traces of small scheduling scenarios on the virtual clock. Every
// expected trace below was derived by hand from the rules in
// docs/decisions/0010..0017 (statement cost 1 us; the first tick of an
// activation is the one on entry to the program body), so a difference is a
// change of behaviour, not noise.
#include <catch2/catch.hpp>

#include "runtime/civil_time.h"
#include "tests/unit/runtime/fake_body.h"

using namespace strun::rt;
using namespace strun::rt::test;

TEST_CASE("a higher-priority task preempts mid-loop and the preempted one resumes where it stopped", "[scheduler][golden]") {
    Scenario s;
    s.add(cyclic("Slow", 20, 10 * ms), 2000);
    s.add(cyclic("Fast", 5, 1 * ms), 200);
    CHECK(s.run(virtualFor(3 * ms)) ==
          "T#0s Slow release\n"
          "T#0s Fast release\n"
          "T#0s Fast start\n"
          "T#200us Fast end\n"
          "T#200us Slow start\n"
          "T#1ms Fast release\n"
          "T#1ms Slow preempt\n"
          "T#1ms Fast start\n"
          "T#1ms200us Fast end\n"
          "T#1ms200us Slow resume\n"
          "T#2ms Fast release\n"
          "T#2ms Slow preempt\n"
          "T#2ms Fast start\n"
          "T#2ms200us Fast end\n"
          "T#2ms200us Slow resume\n"
          "T#2ms600us Slow end\n");
    CHECK(s.state == PlcState::Run);
    CHECK(s.scheduler->endTime() == 3 * ms);
    // 2000 statements of its own and 400 us of preemption: execution time counts both.
    CHECK(s.bodies[0]->completed == 1);
    CHECK(s.taskJson("Slow")["max_exec_us"] == 2400);
    CHECK(s.taskJson("Slow")["max_latency_us"] == 200);
    CHECK(s.taskJson("Fast")["cycles"] == 3);
    CHECK(s.taskJson("Fast")["max_latency_us"] == 0);
}

TEST_CASE("equal priority never preempts; the shorter period starts first at RUN", "[scheduler][golden]") {
    Scenario s;
    s.add(cyclic("B", 10, 3 * ms), 2500);
    s.add(cyclic("A", 10, 2 * ms), 300);
    CHECK(s.run(virtualFor(6 * ms)) ==
          "T#0s B release\n"
          "T#0s A release\n"
          "T#0s A start\n"
          "T#300us A end\n"
          "T#300us B start\n"
          "T#2ms A release\n"
          "T#2ms800us B end\n"
          "T#2ms800us A start\n"
          "T#3ms B release\n"
          "T#3ms100us A end\n"
          "T#3ms100us B start\n"
          "T#4ms A release\n"
          "T#5ms600us B end\n"
          "T#5ms600us A start\n"
          "T#5ms900us A end\n");
    CHECK(s.taskJson("A")["max_latency_us"] == 1600);
    CHECK(s.taskJson("A")["overruns"] == 0);
}

TEST_CASE("among waiting tasks of equal priority the longest waiting goes first", "[scheduler][golden]") {
    // Q (event) is released at the 1 ms sampling tick, P (cyclic) at 0: P has
    // waited longer, so it runs first although events precede cyclic tasks at RUN.
    Scenario s;
    uint8_t flag = 0;
    s.add(cyclic("P", 10, 2 * ms), 100);
    TaskSpec q = ofKind("Q", TaskKind::Event, 10);
    q.trigger.byte = &flag;
    s.add(q, 100);
    s.add(cyclic("H", 1, 10 * ms), 2500).onStatement = [&](int activation, int statement) {
        if (activation == 0 && statement == 499) flag = 1;
    };
    CHECK(s.run(virtualFor(3 * ms)) ==
          "T#0s P release\n"
          "T#0s H release\n"
          "T#0s H start\n"
          "T#1ms Q release\n"
          "T#2ms P overrun\n"
          "T#2ms500us H end\n"
          "T#2ms500us P start\n"
          "T#2ms600us P end\n"
          "T#2ms600us Q start\n"
          "T#2ms700us Q end\n");
}

TEST_CASE("a cyclic task released while busy drops the activation, records OVERRUN and keeps its grid", "[scheduler][golden]") {
    Scenario s;
    s.add(cyclic("Busy", 10, 1 * ms), 2500);
    CHECK(s.run(virtualFor(5 * ms)) ==
          "T#0s Busy release\n"
          "T#0s Busy start\n"
          "T#1ms Busy overrun\n"
          "T#2ms Busy overrun\n"
          "T#2ms500us Busy end\n"
          "T#3ms Busy release\n"
          "T#3ms Busy start\n"
          "T#4ms Busy overrun\n");
    CHECK(s.state == PlcState::Run);
    CHECK(s.taskJson("Busy")["overruns"] == 3);
    CHECK(s.taskJson("Busy")["cycles"] == 1);
    const auto& diags = s.scheduler->diagnostics();
    REQUIRE(diags.size() == 3);
    CHECK(diags[0].code == DiagCode::Overrun);
    CHECK(diags[0].time == 1 * ms);
    CHECK(diags[0].task == "Busy");
    CHECK(diags[2].time == 4 * ms);
    CHECK(s.scheduler->diagnosticsJson()[1]["time"] == "T#2ms");
}

TEST_CASE("WHILE TRUE in the default MainTask trips the 200 ms watchdog and STOPs", "[scheduler][golden]") {
    Scenario s;
    s.add(ofKind("MainTask", TaskKind::Freewheeling, 30, 200 * ms), 10).loopForever = true;
    RunOptions options;  // no --for / --cycles: only the fault ends the run
    CHECK(s.run(options) ==
          "T#0s MainTask release\n"
          "T#0s MainTask start\n"
          "T#200ms MainTask watchdog\n"
          "T#200ms MainTask stop WATCHDOG\n");
    CHECK(s.state == PlcState::Stop);
    CHECK(s.scheduler->endTime() == 200 * ms);
    auto diags = s.scheduler->diagnosticsJson();
    REQUIRE(diags.size() == 1);
    CHECK(diags[0]["code"] == "WATCHDOG");
    CHECK(diags[0]["time"] == "T#200ms");
    CHECK(diags[0]["task"] == "MainTask");
    CHECK(s.taskJson("MainTask")["watchdog_trips"] == 1);
    CHECK(s.taskJson("MainTask")["cycles"] == 0);
}

TEST_CASE("a watchdog trip with an execution-timeout task aborts the activation and the PLC keeps running", "[scheduler][golden]") {
    Scenario s;
    s.add(cyclic("Work", 10, 10 * ms, 2 * ms), 1000).loopForeverInActivation = 1;
    s.add(ofKind("Timeout", TaskKind::ExecTimeout, 5), 50);
    CHECK(s.run(virtualFor(25 * ms)) ==
          "T#0s Work release\n"
          "T#0s Work start\n"
          "T#1ms Work end\n"
          "T#10ms Work release\n"
          "T#10ms Work start\n"
          "T#12ms Work watchdog\n"
          "T#12ms Timeout release\n"
          "T#12ms Work abort\n"
          "T#12ms Timeout start\n"
          "T#12ms50us Timeout end\n"
          "T#20ms Work release\n"
          "T#20ms Work start\n"
          "T#21ms Work end\n");
    CHECK(s.state == PlcState::Run);
    CHECK(s.bodies[0]->aborted == 1);
    CHECK(s.taskJson("Work")["cycles"] == 2);
    CHECK(s.taskJson("Work")["watchdog_trips"] == 1);
}

TEST_CASE("the watchdog counts preemption time; a preempted task is aborted when it would resume", "[scheduler][golden]") {
    Scenario s;
    s.add(cyclic("Low", 20, 10 * ms, 3 * ms), 2000);
    TaskSpec high = ofKind("High", TaskKind::TimeEvent, 1);
    high.atCalendarNanos = 1 * ms;  // once, 1 ms after the default --start (1970-01-01)
    s.add(high, 2500);
    s.add(ofKind("Timeout", TaskKind::ExecTimeout, 5), 50);
    CHECK(s.run(virtualFor(5 * ms)) ==
          "T#0s Low release\n"
          "T#0s Low start\n"
          "T#1ms High release\n"
          "T#1ms Low preempt\n"
          "T#1ms High start\n"
          "T#3ms Low watchdog\n"
          "T#3ms Timeout release\n"
          "T#3ms500us High end\n"
          "T#3ms500us Low abort\n"
          "T#3ms500us Timeout start\n"
          "T#3ms550us Timeout end\n");
    CHECK(s.state == PlcState::Run);
}

TEST_CASE("the execution-timeout task tripping its own watchdog STOPs the PLC", "[scheduler][golden]") {
    Scenario s;
    s.add(cyclic("Work", 10, 10 * ms, 1 * ms), 10).loopForever = true;
    s.add(ofKind("Timeout", TaskKind::ExecTimeout, 5, 1 * ms), 10).loopForever = true;
    CHECK(s.run(virtualFor(25 * ms)) ==
          "T#0s Work release\n"
          "T#0s Work start\n"
          "T#1ms Work watchdog\n"
          "T#1ms Timeout release\n"
          "T#1ms Work abort\n"
          "T#1ms Timeout start\n"
          "T#2ms Timeout watchdog\n"
          "T#2ms Timeout stop WATCHDOG\n");
    CHECK(s.state == PlcState::Stop);
    CHECK(s.scheduler->diagnostics().size() == 2);
}

namespace {
// Prog: cyclic 1 ms, 100 statements; its second activation raises `code` at statement 10.
FakeBody& faultyProgram(Scenario& s, DiagCode code) {
    FakeBody& body = s.add(cyclic("Prog", 10, 1 * ms), 100);
    body.faultAt = 9;
    body.faultActivation = 1;
    body.fault = code;
    return body;
}
}  // namespace

TEST_CASE("ARRAY_BOUNDS runs the program-error task and the PLC keeps running", "[scheduler][golden]") {
    Scenario s;
    faultyProgram(s, DiagCode::ArrayBounds);
    s.add(ofKind("ErrTask", TaskKind::ProgramError, 5), 20);
    CHECK(s.run(virtualFor(2500 * us)) ==
          "T#0s Prog release\n"
          "T#0s Prog start\n"
          "T#100us Prog end\n"
          "T#1ms Prog release\n"
          "T#1ms Prog start\n"
          "T#1ms10us Prog error ARRAY_BOUNDS\n"
          "T#1ms10us ErrTask release\n"
          "T#1ms11us Prog preempt\n"
          "T#1ms11us ErrTask start\n"
          "T#1ms31us ErrTask end\n"
          "T#1ms31us Prog resume\n"
          "T#1ms120us Prog end\n"
          "T#2ms Prog release\n"
          "T#2ms Prog start\n"
          "T#2ms100us Prog end\n");
    CHECK(s.state == PlcState::Run);
    auto diags = s.scheduler->diagnosticsJson();
    REQUIRE(diags.size() == 1);
    // Issue 7: diagnostics gained "file" and "col" and keep this key order.
    CHECK(diags[0] == nlohmann::ordered_json{{"time", "T#1ms10us"}, {"code", "ARRAY_BOUNDS"}, {"task", "Prog"},
                                             {"pou", "FakePrg"},   {"file", ""},              {"line", 10},
                                             {"col", 0},           {"message", "fake fault"}});
}

TEST_CASE("ARRAY_BOUNDS without a program-error task STOPs at the fault", "[scheduler][golden]") {
    Scenario s;
    faultyProgram(s, DiagCode::ArrayBounds);
    CHECK(s.run(virtualFor(5 * ms)) ==
          "T#0s Prog release\n"
          "T#0s Prog start\n"
          "T#100us Prog end\n"
          "T#1ms Prog release\n"
          "T#1ms Prog start\n"
          "T#1ms10us Prog error ARRAY_BOUNDS\n"
          "T#1ms10us Prog stop ARRAY_BOUNDS\n");
    CHECK(s.state == PlcState::Stop);
    CHECK(s.scheduler->endTime() == 1 * ms + 10 * us);
    CHECK(s.bodies[0]->aborted == 1);
}

TEST_CASE("CALL_DEPTH always STOPs, even with a program-error task", "[scheduler][golden]") {
    Scenario s;
    faultyProgram(s, DiagCode::CallDepth);
    s.add(ofKind("ErrTask", TaskKind::ProgramError, 5), 20);
    CHECK(s.run(virtualFor(5 * ms)) ==
          "T#0s Prog release\n"
          "T#0s Prog start\n"
          "T#100us Prog end\n"
          "T#1ms Prog release\n"
          "T#1ms Prog start\n"
          "T#1ms10us Prog error CALL_DEPTH\n"
          "T#1ms10us Prog stop CALL_DEPTH\n");
    CHECK(s.state == PlcState::Stop);
    CHECK(s.taskJson("ErrTask")["cycles"] == 0);
}

TEST_CASE("DIV_BY_ZERO is recorded and execution goes on", "[scheduler][golden]") {
    Scenario s;
    faultyProgram(s, DiagCode::DivByZero);
    s.add(ofKind("ErrTask", TaskKind::ProgramError, 5), 20);
    CHECK(s.run(virtualFor(1500 * us)) ==
          "T#0s Prog release\n"
          "T#0s Prog start\n"
          "T#100us Prog end\n"
          "T#1ms Prog release\n"
          "T#1ms Prog start\n"
          "T#1ms10us Prog error DIV_BY_ZERO\n"
          "T#1ms100us Prog end\n");
    CHECK(s.state == PlcState::Run);
    CHECK(s.scheduler->diagnostics().size() == 1);
}

TEST_CASE("a program error inside the program-error task STOPs the PLC", "[scheduler][golden]") {
    Scenario s;
    faultyProgram(s, DiagCode::ArrayBounds);
    FakeBody& handler = s.add(ofKind("ErrTask", TaskKind::ProgramError, 5), 20);
    handler.faultAt = 4;
    CHECK(s.run(virtualFor(5 * ms)) ==
          "T#0s Prog release\n"
          "T#0s Prog start\n"
          "T#100us Prog end\n"
          "T#1ms Prog release\n"
          "T#1ms Prog start\n"
          "T#1ms10us Prog error ARRAY_BOUNDS\n"
          "T#1ms10us ErrTask release\n"
          "T#1ms11us Prog preempt\n"
          "T#1ms11us ErrTask start\n"
          "T#1ms16us ErrTask error ARRAY_BOUNDS\n"
          "T#1ms16us ErrTask stop ARRAY_BOUNDS\n");
    CHECK(s.state == PlcState::Stop);
}

TEST_CASE("startup runs first and alone, interrupted only by the fault tasks; then the seed's start-up order", "[scheduler][golden]") {
    Scenario s;
    uint8_t flag = 0;
    s.add(cyclic("Cyc10", 10, 10 * ms), 100);
    s.add(ofKind("Free", TaskKind::Freewheeling, 10), 100);
    s.add(cyclic("Hi", 2, 5 * ms), 100);
    TaskSpec ev = ofKind("Ev", TaskKind::Event, 10);
    ev.trigger.byte = &flag;
    s.add(ev, 100);
    FakeBody& startup = s.add(ofKind("Startup", TaskKind::Startup, 0), 500);
    startup.faultAt = 99;  // ARRAY_BOUNDS: the error task (priority 20) still interrupts it
    startup.onStatement = [&](int, int statement) {
        if (statement == 199) flag = 1;  // a rising edge during startup is seen when it ends
    };
    s.add(cyclic("Cyc5", 10, 5 * ms), 100);
    s.add(ofKind("ErrTask", TaskKind::ProgramError, 20), 50);
    TaskSpec timed = ofKind("TE", TaskKind::TimeEvent, 1);
    timed.atCalendarNanos = 200 * us;  // due during startup: waits for its end
    s.add(timed, 100);
    CHECK(s.run(virtualFor(1200 * us)) ==
          "T#0s Startup release\n"
          "T#0s Startup start\n"
          "T#100us Startup error ARRAY_BOUNDS\n"
          "T#100us ErrTask release\n"
          "T#101us Startup preempt\n"
          "T#101us ErrTask start\n"
          "T#151us ErrTask end\n"
          "T#151us Startup resume\n"
          "T#200us TE release\n"
          "T#550us Startup end\n"
          "T#550us Cyc10 release\n"
          "T#550us Free release\n"
          "T#550us Hi release\n"
          "T#550us Ev release\n"
          "T#550us Cyc5 release\n"
          "T#550us TE start\n"
          "T#650us TE end\n"
          "T#650us Hi start\n"
          "T#750us Hi end\n"
          "T#750us Ev start\n"
          "T#850us Ev end\n"
          "T#850us Cyc5 start\n"
          "T#950us Cyc5 end\n"
          "T#950us Cyc10 start\n"
          "T#1ms50us Cyc10 end\n"
          "T#1ms50us Free start\n"
          "T#1ms150us Free end\n"
          "T#1ms150us Free release\n"
          "T#1ms150us Free start\n");
    CHECK(s.state == PlcState::Run);
}

TEST_CASE("a status task runs continuously while its BOOL is TRUE", "[scheduler][golden]") {
    Scenario s;
    uint8_t flag = 0;
    TaskSpec stat = ofKind("Stat", TaskKind::Status, 10);
    stat.trigger.byte = &flag;
    s.add(stat, 700);
    s.add(cyclic("Driver", 5, 2 * ms), 100).onStatement = [&](int activation, int statement) {
        if (statement == 0 && activation == 1) flag = 1;
        if (statement == 0 && activation == 3) flag = 0;
    };
    CHECK(s.run(virtualFor(7 * ms)) ==
          "T#0s Driver release\n"
          "T#0s Driver start\n"
          "T#100us Driver end\n"
          "T#2ms Driver release\n"
          "T#2ms Driver start\n"
          "T#2ms100us Driver end\n"
          "T#2ms100us Stat release\n"
          "T#2ms100us Stat start\n"
          "T#2ms800us Stat end\n"
          "T#2ms800us Stat release\n"
          "T#2ms800us Stat start\n"
          "T#3ms500us Stat end\n"
          "T#3ms500us Stat release\n"
          "T#3ms500us Stat start\n"
          "T#4ms Driver release\n"
          "T#4ms Stat preempt\n"
          "T#4ms Driver start\n"
          "T#4ms100us Driver end\n"
          "T#4ms100us Stat resume\n"
          "T#4ms300us Stat end\n"
          "T#4ms300us Stat release\n"
          "T#4ms300us Stat start\n"
          "T#5ms Stat end\n"
          "T#5ms Stat release\n"
          "T#5ms Stat start\n"
          "T#5ms700us Stat end\n"
          "T#5ms700us Stat release\n"
          "T#5ms700us Stat start\n"
          "T#6ms Driver release\n"
          "T#6ms Stat preempt\n"
          "T#6ms Driver start\n"
          "T#6ms100us Driver end\n"
          "T#6ms100us Stat resume\n"
          "T#6ms500us Stat end\n");
    CHECK(s.taskJson("Stat")["cycles"] == 6);
}

TEST_CASE("an event task runs once per rising edge seen at a sampling tick or task end", "[scheduler][golden]") {
    // L raises the BOOL at 1.5 ms and drops it at 1.8 ms (a pulse between two
    // samples: not seen), raises it at 1.9 ms (seen at the 2 ms tick: Ev
    // preempts L) and drops it at 2.33 ms.
    Scenario s;
    uint8_t flag = 0;
    TaskSpec ev = ofKind("Ev", TaskKind::Event, 5);
    ev.trigger.byte = &flag;
    s.add(ev, 30);
    s.add(cyclic("L", 20, 10 * ms), 2500).onStatement = [&](int, int statement) {
        if (statement == 1499) flag = 1;
        if (statement == 1799) flag = 0;
        if (statement == 1899) flag = 1;
        if (statement == 2299) flag = 0;
    };
    CHECK(s.run(virtualFor(3 * ms)) ==
          "T#0s L release\n"
          "T#0s L start\n"
          "T#2ms Ev release\n"
          "T#2ms L preempt\n"
          "T#2ms Ev start\n"
          "T#2ms30us Ev end\n"
          "T#2ms30us L resume\n"
          "T#2ms530us L end\n");
    CHECK(s.taskJson("Ev")["cycles"] == 1);
}

TEST_CASE("an event task's BOOL already TRUE at RUN is no edge; an edge while it is busy is an OVERRUN", "[scheduler][golden]") {
    Scenario s;
    uint8_t flag = 1;
    TaskSpec ev = ofKind("Ev", TaskKind::Event, 20);
    ev.trigger.byte = &flag;
    s.add(ev, 2500);
    s.add(cyclic("Toggler", 5, 1 * ms), 10).onStatement = [&](int, int statement) {
        if (statement == 0) flag = !flag;  // FALSE at 1 us, TRUE at 1 ms 1 us, FALSE at 2 ms 1 us...
    };
    CHECK(s.run(virtualFor(3500 * us)) ==
          "T#0s Toggler release\n"
          "T#0s Toggler start\n"
          "T#10us Toggler end\n"
          "T#1ms Toggler release\n"
          "T#1ms Toggler start\n"
          "T#1ms10us Toggler end\n"
          "T#1ms10us Ev release\n"
          "T#1ms10us Ev start\n"
          "T#2ms Toggler release\n"
          "T#2ms Ev preempt\n"
          "T#2ms Toggler start\n"
          "T#2ms10us Toggler end\n"
          "T#2ms10us Ev resume\n"
          "T#3ms Toggler release\n"
          "T#3ms Ev preempt\n"
          "T#3ms Toggler start\n"
          "T#3ms10us Toggler end\n"
          "T#3ms10us Ev overrun\n"
          "T#3ms10us Ev resume\n");
    CHECK(s.taskJson("Ev")["overruns"] == 1);
    CHECK(s.scheduler->diagnostics().at(0).code == DiagCode::Overrun);
}

TEST_CASE("a MONTH_END time event follows month lengths and leap years", "[scheduler][golden]") {
    Scenario s;
    TaskSpec monthEnd = ofKind("ME", TaskKind::TimeEvent, 10);
    int64_t jan31 = daysFromCivil({2024, 1, 31}) * kNanosPerDay;
    monthEnd.atCalendarNanos = jan31 + ((23 * 60 + 59) * 60 + 59) * kNanosPerSecond + 500 * ms;
    monthEnd.repeat = TimeRepeat::MonthEnd;
    s.add(monthEnd, 10);
    RunOptions options = virtualFor(70 * kNanosPerDay);
    options.startCalendarNanos = jan31 + ((23 * 60 + 59) * 60 + 59) * kNanosPerSecond;  // DT#2024-01-31-23:59:59
    CHECK(s.run(options) ==
          "T#500ms ME release\n"
          "T#500ms ME start\n"
          "T#500ms10us ME end\n"
          "T#29d500ms ME release\n"  // 2024-02-29, a leap year
          "T#29d500ms ME start\n"
          "T#29d500ms10us ME end\n"
          "T#60d500ms ME release\n"  // 2024-03-31
          "T#60d500ms ME start\n"
          "T#60d500ms10us ME end\n");
}

TEST_CASE("a time event already past at RUN never runs once; a repeating one continues from RUN", "[scheduler][golden]") {
    Scenario s;
    TaskSpec past = ofKind("Past", TaskKind::TimeEvent, 10);
    past.atCalendarNanos = 0;
    s.add(past, 10);
    TaskSpec hourly = ofKind("Hourly", TaskKind::TimeEvent, 10);
    hourly.atCalendarNanos = 30 * 60 * kNanosPerSecond;  // 00:30, hourly
    hourly.repeat = TimeRepeat::Hourly;
    s.add(hourly, 10);
    RunOptions options = virtualFor(3 * 3600 * kNanosPerSecond);
    options.startCalendarNanos = 2 * 3600 * kNanosPerSecond;  // 02:00
    CHECK(s.run(options) ==
          "T#30m Hourly release\n"
          "T#30m Hourly start\n"
          "T#30m10us Hourly end\n"
          "T#1h30m Hourly release\n"
          "T#1h30m Hourly start\n"
          "T#1h30m10us Hourly end\n"
          "T#2h30m Hourly release\n"
          "T#2h30m Hourly start\n"
          "T#2h30m10us Hourly end\n");
    CHECK(s.taskJson("Past")["cycles"] == 0);
}
