// Test doubles for the runtime: task bodies that behave like interpreted
// programs without an interpreter. A FakeBody executes N "statements", each
// preceded by Machine::tick() exactly as the interpreter does (the first
// tick is the one on entry to the program body), and can raise a fault, flip
// a BOOL, or loop forever at a chosen statement.
#pragma once

#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "runtime/scheduler.h"

namespace strun::rt::test {

constexpr PlcTime us = 1'000;
constexpr PlcTime ms = 1'000'000;

class FakeBody : public TaskBody {
public:
    FakeBody(Machine& machine, int statements) : machine_(machine), statements(statements) {}

    int statements;
    int faultAt = -1;  // statement index that raises `fault` (every activation)
    DiagCode fault = DiagCode::ArrayBounds;
    int faultActivation = -1;  // only in this activation (0-based); -1: every activation
    bool loopForever = false;  // after the last statement: WHILE TRUE DO END_WHILE
    int loopForeverInActivation = -1;  // only in this activation (0-based)
    PlcTime busyFor = 0;  // real clock: keep executing statements until this much PLC time has passed
    std::function<void(int activation, int statement)> onStatement;
    uint64_t completed = 0;
    uint64_t aborted = 0;

    bool runActivation() override {
        int activation = int(completed + aborted);
        bool forever = loopForever || activation == loopForeverInActivation;
        PlcTime busyUntil = busyFor > 0 ? machine_.handler->currentTime() + busyFor : 0;
        for (int i = 0; i < statements || forever || (busyFor > 0 && machine_.handler->currentTime() < busyUntil); ++i) {
            if (machine_.tick()) {
                ++aborted;
                return false;
            }
            if (i == faultAt && (faultActivation < 0 || faultActivation == activation))
                machine_.handler->onFault(fault, "FakePrg", i + 1, "fake fault");
            if (onStatement) onStatement(activation, i);
        }
        ++completed;
        return true;
    }

private:
    Machine& machine_;
};

inline TaskSpec cyclic(std::string name, int priority, PlcTime interval, PlcTime watchdog = 0) {
    TaskSpec spec;
    spec.name = std::move(name);
    spec.kind = TaskKind::Cyclic;
    spec.priority = priority;
    spec.interval = interval;
    spec.watchdog = watchdog;
    return spec;
}

inline TaskSpec ofKind(std::string name, TaskKind kind, int priority, PlcTime watchdog = 0) {
    TaskSpec spec;
    spec.name = std::move(name);
    spec.kind = kind;
    spec.priority = priority;
    spec.watchdog = watchdog;
    return spec;
}

// A set of tasks with fake bodies, run on one machine.
struct Scenario {
    Machine machine;
    std::vector<TaskSpec> specs;
    std::vector<std::unique_ptr<FakeBody>> bodies;
    std::unique_ptr<Scheduler> scheduler;
    std::ostringstream trace;
    PlcState state = PlcState::Run;

    FakeBody& add(TaskSpec spec, int statements) {
        specs.push_back(std::move(spec));
        bodies.push_back(std::make_unique<FakeBody>(machine, statements));
        return *bodies.back();
    }

    // Runs with `options` (trace captured unless the options bring their own)
    // and returns the trace text.
    std::string run(RunOptions options) {
        if (!options.trace) options.trace = &trace;
        std::vector<TaskBody*> raw;
        for (auto& body : bodies) raw.push_back(body.get());
        scheduler = std::make_unique<Scheduler>(machine, specs, raw, options);
        state = scheduler->run();
        return trace.str();
    }

    nlohmann::json taskJson(const std::string& name) const {
        for (const auto& task : scheduler->tasksJson())
            if (task["name"] == name) return task;
        return nullptr;
    }
};

inline RunOptions virtualFor(PlcTime duration, PlcTime stmtCost = 1 * us) {
    RunOptions options;
    options.virtualClock = true;
    options.stmtCost = stmtCost;
    options.duration = duration;
    return options;
}

}  // namespace strun::rt::test
