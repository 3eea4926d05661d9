// How a run ends (--cycles, --for, requestStop), the process image, the
// bounded diagnostic buffer, the --dump tasks array, and a 26-task load
// whose trace is checked against the scheduling rules line by line.
#include <catch2/catch.hpp>

#include <chrono>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "tests/unit/runtime/fake_body.h"

using namespace strun::rt;
using namespace strun::rt::test;

TEST_CASE("option --cycles counts completed cycles of the default (first) task", "[scheduler]") {
    Scenario s;
    s.add(ofKind("MainTask", TaskKind::Freewheeling, 30, 200 * ms), 10);
    RunOptions options;
    options.cycles = 5;
    s.run(options);
    CHECK(s.state == PlcState::Run);
    CHECK(s.taskJson("MainTask")["cycles"] == 5);
    CHECK(s.scheduler->endTime() == 50 * us);
    CHECK(s.trace.str().substr(s.trace.str().rfind("T#4")) == "T#40us MainTask start\nT#50us MainTask end\n");
}

TEST_CASE("option --cycles of a named task ends the run at its Nth end, unwinding a preempted task", "[scheduler]") {
    Scenario s;
    s.add(ofKind("Background", TaskKind::Freewheeling, 30), 10).loopForever = true;
    s.add(cyclic("Fast", 5, 1 * ms), 100);
    RunOptions options;
    options.cycles = 3;
    options.cyclesTask = "FAST";  // names are case-insensitive
    s.run(options);
    CHECK(s.state == PlcState::Run);
    CHECK(s.taskJson("Fast")["cycles"] == 3);
    CHECK(s.scheduler->endTime() == 2 * ms + 100 * us);
    CHECK(s.bodies[0]->aborted == 1);  // Background was unwound, not completed
}

TEST_CASE("option --cycles 0 and --for 0 end the run at once", "[scheduler]") {
    Scenario a;
    a.add(ofKind("MainTask", TaskKind::Freewheeling, 30), 10);
    RunOptions cycles;
    cycles.cycles = 0;
    CHECK(a.run(cycles).empty() == false);  // the release at RUN is traced
    CHECK(a.taskJson("MainTask")["cycles"] == 0);
    Scenario b;
    b.add(ofKind("MainTask", TaskKind::Freewheeling, 30), 10);
    b.run(virtualFor(0));
    CHECK(b.taskJson("MainTask")["cycles"] == 0);
    CHECK(b.scheduler->endTime() == 0);
}

TEST_CASE("an unknown --task is rejected with a clear message", "[scheduler]") {
    Machine machine;
    std::vector<TaskSpec> specs{cyclic("Fast", 5, 1 * ms)};
    FakeBody body(machine, 1);
    RunOptions options;
    options.cycles = 1;
    options.cyclesTask = "Slow";
    CHECK_THROWS_WITH(Scheduler(machine, specs, {&body}, options), "--task: no task named 'Slow'");
    CHECK(Scheduler::hasTask(specs, "fast"));
    CHECK_FALSE(Scheduler::hasTask(specs, "Slow"));
}

TEST_CASE("option --for stops at the first statement boundary at or after the duration; the state stays RUN", "[scheduler]") {
    Scenario s;
    s.add(ofKind("MainTask", TaskKind::Freewheeling, 30), 1).loopForever = true;
    s.run(virtualFor(1 * ms + 500, 1 * us));  // 1 ms 500 ns: the boundary after it is 1 ms 1 us
    CHECK(s.state == PlcState::Run);
    CHECK(s.scheduler->endTime() == 1 * ms + 1 * us);
    CHECK(s.scheduler->diagnostics().empty());
}

TEST_CASE("the statement cost scales PLC time", "[scheduler]") {
    Scenario s;
    s.add(cyclic("Task", 10, 1 * ms), 100);
    s.run(virtualFor(1 * ms, 250));  // 100 statements of 250 ns
    CHECK(s.trace.str() == "T#0s Task release\nT#0s Task start\nT#25us Task end\n");
    CHECK(s.taskJson("Task")["last_exec_us"] == 25);
    Scenario t;
    t.add(cyclic("Task", 10, 1 * ms), 3);
    t.run(virtualFor(1 * ms, 333));
    CHECK(t.trace.str() == "T#0s Task release\nT#0s Task start\nT#999ns Task end\n");
    CHECK(t.taskJson("Task")["last_exec_us"] == Approx(0.999));
}

TEST_CASE("an empty task body still costs one statement, so a freewheeling task cannot stall PLC time", "[scheduler]") {
    Scenario s;
    s.add(ofKind("MainTask", TaskKind::Freewheeling, 30), 0);
    RunOptions options;
    options.cycles = 1000;
    s.run(options);
    CHECK(s.scheduler->endTime() == 1 * ms);
}

TEST_CASE("requestStop ends an unbounded virtual run cleanly in RUN", "[scheduler]") {
    Scenario s;
    s.add(ofKind("MainTask", TaskKind::Freewheeling, 30), 1).loopForever = true;
    std::thread stopper([] {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        Scheduler::requestStop();
    });
    RunOptions options;
    options.trace = nullptr;
    std::ostringstream ignored;
    options.trace = &ignored;
    s.run(options);
    stopper.join();
    CHECK(s.state == PlcState::Run);
    CHECK(s.scheduler->endTime() > 0);
}

// Issue 12: a virtual run that can never run a task again ends by itself
// (it used to wait for requestStop forever), with a warning.
TEST_CASE("a virtual run with nothing left to do ends by itself", "[scheduler]") {
    Scenario s;
    TaskSpec past = ofKind("Past", TaskKind::TimeEvent, 10);
    past.atCalendarNanos = 0;
    past.repeat = TimeRepeat::Once;
    s.add(past, 1);
    RunOptions options;
    options.startCalendarNanos = 1 * kSecond;
    std::ostringstream warnings;
    options.warnings = &warnings;
    auto begin = std::chrono::steady_clock::now();
    s.run(options);
    CHECK(s.state == PlcState::Run);
    CHECK(std::chrono::steady_clock::now() - begin < std::chrono::seconds(5));
    CHECK(warnings.str().find("no task can ever run again") != std::string::npos);
}

TEST_CASE("inputs are copied into the image when a task starts, outputs out when it ends", "[scheduler]") {
    Scenario s;
    Machine& m = s.machine;
    m.image.physicalInputs[3] = 0x5A;
    s.add(cyclic("IO", 10, 1 * ms), 5).onStatement = [&](int activation, int statement) {
        if (statement == 0) {
            uint8_t expected = activation == 0 ? 0x5A : uint8_t(0x20 + activation - 1);
            CHECK(m.image.inputs[3] == expected);
            m.image.physicalInputs[3] = uint8_t(0x20 + activation);  // the field changes meanwhile...
            CHECK(m.image.inputs[3] == expected);                  // ...but the image stays stable
            m.image.outputs[7] = uint8_t(activation + 1);
            CHECK(m.image.physicalOutputs[7] == activation);  // not yet written out
        }
    };
    s.run(virtualFor(2500 * us));
    CHECK(m.image.physicalOutputs[7] == 3);
}

TEST_CASE("the diagnostic buffer is bounded: the oldest entries are dropped and counted", "[scheduler]") {
    Scenario s;
    FakeBody& body = s.add(cyclic("Faulty", 10, 1 * ms), 10);
    body.faultAt = 0;
    body.fault = DiagCode::DivByZero;
    RunOptions options = virtualFor(100 * ms);
    options.diagnosticCapacity = 8;
    s.run(options);
    const auto& diags = s.scheduler->diagnostics();
    REQUIRE(diags.size() == 8);
    CHECK(s.scheduler->droppedDiagnostics() == 92);
    CHECK(diags.front().time == 92 * ms + 1 * us);  // the newest 8 of 100, oldest first
    CHECK(diags.back().time == 99 * ms + 1 * us);
    CHECK(s.scheduler->diagnosticsJson().size() == 8);
}

TEST_CASE("the --dump tasks array has every field", "[scheduler]") {
    Scenario s;
    s.add(cyclic("Fast", 5, 1 * ms, 10 * ms), 100);
    s.add(ofKind("Idle", TaskKind::ExecTimeout, 3), 1);
    s.run(virtualFor(3 * ms));
    nlohmann::json fast = s.taskJson("Fast");
    CHECK(fast == nlohmann::json{{"name", "Fast"},         {"kind", "cyclic"},      {"priority", 5},
                                 {"cycles", 3},            {"overruns", 0},         {"watchdog_trips", 0},
                                 {"last_exec_us", 100},    {"min_exec_us", 100},    {"max_exec_us", 100},
                                 {"avg_exec_us", 100},     {"min_latency_us", 0},   {"max_latency_us", 0}});
    nlohmann::json idle = s.taskJson("Idle");
    CHECK(idle["kind"] == "exec_timeout");
    CHECK(idle["cycles"] == 0);
    CHECK(idle["min_exec_us"] == 0);
}

TEST_CASE("currentTaskName names the running task", "[scheduler]") {
    Scenario s;
    std::vector<std::string> seen;
    s.add(cyclic("Outer", 20, 10 * ms), 1500).onStatement = [&](int, int statement) {
        if (statement == 0 || statement == 1499) seen.push_back(s.scheduler->currentTaskName());
    };
    s.add(cyclic("Inner", 5, 1 * ms), 3).onStatement = [&](int activation, int statement) {
        if (activation == 1 && statement == 0) seen.push_back(s.scheduler->currentTaskName());
    };
    s.run(virtualFor(2 * ms));
    CHECK(seen == std::vector<std::string>{"Outer", "Inner", "Outer"});
    CHECK(s.scheduler->currentTaskName().empty());
}

namespace {

struct TraceLine {
    std::string time, task, event;
};

std::vector<TraceLine> parseTrace(const std::string& text) {
    std::vector<TraceLine> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        TraceLine parsed;
        fields >> parsed.time >> parsed.task >> parsed.event;
        lines.push_back(parsed);
    }
    return lines;
}

// 26 tasks: 24 cyclic ones over 8 priorities and 6 periods, an event task
// driven by one of them, and a freewheeling background task.
void addManyTasks(Scenario& s, uint8_t& flag) {
    static constexpr PlcTime kPeriods[] = {1 * ms, 2 * ms, 4 * ms, 5 * ms, 10 * ms, 20 * ms};
    for (int i = 0; i < 24; ++i) {
        PlcTime period = kPeriods[i % 6];
        int statements = int(period / (24 * 1 * us)) / 2;  // about half the CPU in all
        // Shorter periods get higher priorities (rate monotonic), so half the
        // CPU is schedulable without overruns; two priorities per period.
        int priority = 2 + (i % 6) * 4 + (i / 6) % 2;
        s.add(cyclic("Cyc_" + std::to_string(i), priority, period), statements);
    }
    s.bodies[5]->onStatement = [&](int activation, int statement) {
        if (statement == 0) flag = activation % 2 == 0;
    };
    TaskSpec ev = ofKind("Ev", TaskKind::Event, 1);
    ev.trigger.byte = &flag;
    s.add(ev, 20);
    s.add(ofKind("Background", TaskKind::Freewheeling, 31), 50);
}

}  // namespace

TEST_CASE("26 tasks at once follow the rules and are deterministic", "[scheduler]") {
    uint8_t flag = 0;
    Scenario s;
    addManyTasks(s, flag);
    std::string trace = s.run(virtualFor(100 * ms));

    std::map<std::string, int> priority;
    for (const TaskSpec& spec : s.specs) priority[spec.name] = spec.priority;
    auto lines = parseTrace(trace);
    REQUIRE(lines.size() > 1000);

    // The first starts (everything released at 0) go by priority, then period.
    std::vector<std::string> firstStarts;
    for (const auto& line : lines) {
        if (line.time != "T#0s" && !firstStarts.empty() && line.event == "release") break;
        if (line.event == "start" && firstStarts.size() < 26) firstStarts.push_back(line.task);
    }
    for (size_t i = 1; i < firstStarts.size(); ++i) {
        INFO(firstStarts[i - 1] << " before " << firstStarts[i]);
        CHECK(priority[firstStarts[i - 1]] <= priority[firstStarts[i]]);
    }

    // Replay the trace: a preemption is always by a strictly higher priority,
    // nesting never exceeds the number of distinct priorities, and only the
    // running task ends.
    std::vector<std::string> stack;
    size_t deepest = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        const auto& line = lines[i];
        if (line.event == "start") {
            stack.push_back(line.task);
            deepest = std::max(deepest, stack.size());
        } else if (line.event == "end") {
            REQUIRE(!stack.empty());
            CHECK(stack.back() == line.task);
            stack.pop_back();
        } else if (line.event == "preempt") {
            REQUIRE(i + 1 < lines.size());
            CHECK(stack.back() == line.task);
            CHECK(lines[i + 1].event == "start");
            CHECK(priority[lines[i + 1].task] < priority[line.task]);
        } else if (line.event == "resume") {
            CHECK(stack.back() == line.task);
        }
    }
    std::set<int> distinct;
    for (const auto& [name, prio] : priority) distinct.insert(prio);
    CHECK(deepest <= distinct.size());
    CHECK(deepest >= 3);  // the load does nest

    // With about half the CPU in use nothing overruns and every cyclic task
    // completes every release but possibly the last.
    for (const auto& task : s.scheduler->tasksJson()) {
        INFO(task.dump());
        CHECK(task["overruns"] == 0);
        CHECK(task["watchdog_trips"] == 0);
    }
    for (size_t i = 0; i < 24; ++i) {
        uint64_t releases = uint64_t(100 * ms / s.specs[i].interval);
        uint64_t cycles = s.taskJson(s.specs[i].name)["cycles"];
        CHECK(cycles + 1 >= releases);
        CHECK(cycles <= releases);
    }
    CHECK(s.taskJson("Ev")["cycles"] > 0);
    CHECK(s.taskJson("Background")["cycles"] > 0);

    // Byte-identical on a second run.
    uint8_t flag2 = 0;
    Scenario again;
    addManyTasks(again, flag2);
    CHECK(again.run(virtualFor(100 * ms)) == trace);
    CHECK(again.scheduler->tasksJson() == s.scheduler->tasksJson());
}

TEST_CASE("a profile that halts on a watchdog trip ends in HALT", "[scheduler]") {
    PlcProfile halting = defaultProfile();
    halting.watchdogReaction = WatchdogReaction::Halt;
    Scenario s;
    s.add(cyclic("Mast", 10, 10 * ms, 1 * ms), 1).loopForever = true;
    RunOptions options = virtualFor(1 * kSecond);
    options.profile = &halting;
    CHECK(s.run(options) ==
          "T#0s Mast release\n"
          "T#0s Mast start\n"
          "T#1ms Mast watchdog\n"
          "T#1ms Mast halt WATCHDOG\n");
    CHECK(s.state == PlcState::Halt);
}

TEST_CASE("a stop requested before run() still stops it", "[scheduler]") {
    Scenario s;
    s.add(ofKind("MainTask", TaskKind::Freewheeling, 30), 1).loopForever = true;
    Scheduler::requestStop();
    s.run(RunOptions{});
    CHECK(s.state == PlcState::Run);
    CHECK(s.scheduler->endTime() == 0);
    // ...and the request does not carry over into the next run.
    Scenario next;
    next.add(ofKind("MainTask", TaskKind::Freewheeling, 30), 1);
    next.run(virtualFor(1 * ms));
    CHECK(next.scheduler->endTime() == 1 * ms);
}

TEST_CASE("M340 %SW9.i inhibits the output writing of task i: the field keeps what it last received", "[scheduler][targets]") {
    Scenario s;
    Machine& m = s.machine;
    std::vector<int> fieldAtStart;
    TaskSpec mast = cyclic("MAST", 1, 10 * ms, 250 * ms);
    mast.systemSlot = 0;
    s.add(mast, 3).onStatement = [&](int activation, int statement) {
        if (statement != 0) return;
        fieldAtStart.push_back(m.image.physicalOutputs[0]);
        m.image.outputs[0] = uint8_t(activation + 1);
        // %SW9.0 (word 9, bit 0): set in the second scan, cleared in the third.
        if (activation == 1) m.image.systemWords[9 * 2] |= 1;
        if (activation == 2) m.image.systemWords[9 * 2] &= uint8_t(~1);
    };
    RunOptions options = virtualFor(35 * ms);
    options.profile = findProfile("m340");
    s.run(options);
    // Scan 1 wrote 1; scan 2's 2 was not written out; scan 3 wrote 3.
    CHECK(fieldAtStart == std::vector<int>{0, 1, 1, 3});
    CHECK(m.image.physicalOutputs[0] == 4);
}
