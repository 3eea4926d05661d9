// The real clock: only properties that hold on a loaded machine (order,
// counts within bounds), never exact times.
#include <catch2/catch.hpp>

#include <chrono>
#include <map>
#include <sstream>
#include <thread>

#include "tests/unit/runtime/fake_body.h"

using namespace strun::rt;
using namespace strun::rt::test;

namespace {

RunOptions realFor(PlcTime duration) {
    RunOptions options;
    options.virtualClock = false;
    options.duration = duration;
    return options;
}

// "T#1s500ms" -> ns (the trace's own format).
PlcTime parseDuration(const std::string& text) {
    PlcTime total = 0;
    size_t i = 2;  // after "T#"
    while (i < text.size()) {
        size_t digitsEnd = i;
        while (digitsEnd < text.size() && std::isdigit(static_cast<unsigned char>(text[digitsEnd]))) ++digitsEnd;
        PlcTime value = std::stoll(text.substr(i, digitsEnd - i));
        size_t unitEnd = digitsEnd;
        while (unitEnd < text.size() && std::isalpha(static_cast<unsigned char>(text[unitEnd]))) ++unitEnd;
        std::string unit = text.substr(digitsEnd, unitEnd - digitsEnd);
        static const std::map<std::string, PlcTime> kUnits{{"d", 86'400'000'000'000},
                                                           {"h", 3'600'000'000'000},
                                                           {"m", 60'000'000'000},
                                                           {"s", 1'000'000'000},
                                                           {"ms", 1'000'000},
                                                           {"us", 1'000},
                                                           {"ns", 1}};
        total += value * kUnits.at(unit);
        i = unitEnd;
    }
    return total;
}

}  // namespace

TEST_CASE("real clock: releases, preemption and counts stay within bounds", "[scheduler][realclock]") {
    Scenario s;
    s.add(cyclic("Fast", 5, 2 * ms), 50);
    s.add(cyclic("Slow", 10, 10 * ms), 1).busyFor = 3 * ms;
    s.add(ofKind("Background", TaskKind::Freewheeling, 30), 1).busyFor = 1 * ms;
    std::string trace = s.run(realFor(300 * ms));

    CHECK(s.state == PlcState::Run);
    CHECK(s.scheduler->endTime() >= 300 * ms);
    CHECK(s.scheduler->endTime() < 3000 * ms);
    // Every 2 ms grid point up to the end is either run or dropped as an overrun.
    uint64_t fastCycles = s.taskJson("Fast")["cycles"];
    uint64_t fastOverruns = s.taskJson("Fast")["overruns"];
    CHECK(fastCycles + fastOverruns >= 120);  // 150 grid points; a starved PLC thread may still owe a few at the stop
    CHECK(fastCycles + fastOverruns <= 151);
    // On a loaded machine many activations may be dropped; some must run.
    CHECK(fastCycles >= 1);
    uint64_t slowCycles = s.taskJson("Slow")["cycles"];
    uint64_t slowOverruns = s.taskJson("Slow")["overruns"];
    CHECK(slowCycles >= 1);
    CHECK(slowCycles + slowOverruns >= 20);
    CHECK(slowCycles + slowOverruns <= 31);
    CHECK(s.taskJson("Background")["cycles"] > 0);
    CHECK(s.taskJson("Slow")["min_exec_us"] >= 3000);

    // The trace is in time order, and every preemption is by a higher priority.
    std::map<std::string, int> priority{{"Fast", 5}, {"Slow", 10}, {"Background", 30}};
    std::istringstream lines(trace);
    std::string line, previousEvent;
    PlcTime previousTime = 0;
    std::string pendingPreempt;
    int preemptions = 0;
    while (std::getline(lines, line)) {
        std::istringstream fields(line);
        std::string time, task, event;
        fields >> time >> task >> event;
        PlcTime at = parseDuration(time);
        CHECK(at >= previousTime);
        previousTime = at;
        if (!pendingPreempt.empty()) {
            CHECK(event == "start");
            CHECK(priority[task] < priority[pendingPreempt]);
            pendingPreempt.clear();
        }
        if (event == "preempt") {
            pendingPreempt = task;
            ++preemptions;
        }
    }
    CHECK(preemptions >= 1);  // a loaded machine may drop most Fast releases; some still preempt
}

TEST_CASE("real clock: WHILE TRUE in MainTask trips the 200 ms watchdog and STOPs", "[scheduler][realclock]") {
    Scenario s;
    s.add(ofKind("MainTask", TaskKind::Freewheeling, 30, 200 * ms), 1).loopForever = true;
    RunOptions options;
    options.virtualClock = false;
    auto begin = std::chrono::steady_clock::now();
    s.run(options);
    auto elapsed = std::chrono::steady_clock::now() - begin;
    CHECK(s.state == PlcState::Stop);
    CHECK(elapsed >= std::chrono::milliseconds(200));
    CHECK(elapsed < std::chrono::milliseconds(3000));
    CHECK(s.scheduler->endTime() >= 200 * ms);
    REQUIRE(s.scheduler->diagnostics().size() == 1);
    CHECK(s.scheduler->diagnostics()[0].code == DiagCode::Watchdog);
    CHECK(s.trace.str().find("MainTask stop WATCHDOG") != std::string::npos);
}

TEST_CASE("real clock: requestStop ends a busy run and an idle run promptly", "[scheduler][realclock]") {
    for (bool busy : {true, false}) {
        INFO("busy " << busy);
        Scenario s;
        if (busy) s.add(ofKind("MainTask", TaskKind::Freewheeling, 30), 1).loopForever = true;
        else s.add(cyclic("Rare", 10, 60 * kSecond), 5);
        RunOptions options;
        options.virtualClock = false;
        std::thread stopper([] {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            Scheduler::requestStop();
        });
        auto begin = std::chrono::steady_clock::now();
        s.run(options);
        stopper.join();
        CHECK(s.state == PlcState::Run);
        CHECK(std::chrono::steady_clock::now() - begin < std::chrono::milliseconds(2000));
        CHECK(s.scheduler->endTime() > 0);  // RUN may start late on a loaded machine
    }
}

TEST_CASE("real clock: the calendar follows the system clock", "[scheduler][realclock]") {
    Scenario s;
    int64_t seen = 0;
    s.add(cyclic("Once", 10, 1 * kSecond), 1).onStatement = [&](int, int) { seen = s.scheduler->calendarNanos(); };
    s.run(realFor(10 * ms));
    int64_t system = std::chrono::duration_cast<std::chrono::nanoseconds>(
                         std::chrono::system_clock::now().time_since_epoch()).count();
    CHECK(seen > system - 10 * kSecond);
    CHECK(seen <= system);
}
