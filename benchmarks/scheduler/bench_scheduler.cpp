// bench_scheduler: measures the task runtime itself, with bodies that do
// (almost) nothing, so the numbers are the scheduler's overhead.
//
//   bench_scheduler [--real-cycles N] [--realtime] [--virtual-only]
//
// Virtual clock: activations per second of a freewheeling 1-statement task
// (the worst case for per-activation overhead), with and without the
// process-image copies, and of a preemption-heavy pair of tasks.
// Real clock: release jitter (release to first statement) of a 1 ms cyclic
// task over N cycles (default 10 000): p50 / p99 / max.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "runtime/scheduler.h"

using namespace strun::rt;

namespace {

constexpr PlcTime kMs = 1'000'000;

// Ticks `statements` times, like an interpreted program of that many statements.
class TickBody : public TaskBody {
public:
    TickBody(Machine& machine, int statements) : machine_(machine), statements_(statements) {}
    bool runActivation() override {
        for (int i = 0; i < statements_; ++i)
            if (machine_.tick()) return false;
        return true;
    }

private:
    Machine& machine_;
    int statements_;
};

// Records how late each activation's first statement comes after its 1 ms grid point.
class JitterBody : public TaskBody {
public:
    JitterBody(Machine& machine, PlcTime period, size_t expected) : machine_(machine), period_(period) {
        latencies_.reserve(expected);
    }
    bool runActivation() override {
        if (machine_.tick()) return false;
        PlcTime now = machine_.handler->currentTime();
        latencies_.push_back(now % period_);  // the grid starts at PLC time 0
        return true;
    }
    std::vector<PlcTime>& latencies() { return latencies_; }

private:
    Machine& machine_;
    PlcTime period_;
    std::vector<PlcTime> latencies_;
};

TaskSpec task(const char* name, TaskKind kind, int priority, PlcTime interval = 0) {
    TaskSpec spec;
    spec.name = name;
    spec.kind = kind;
    spec.priority = priority;
    spec.interval = interval;
    return spec;
}

double secondsSince(std::chrono::steady_clock::time_point begin) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

void freewheelingRate(bool imageCopies) {
    Machine machine;
    if (!imageCopies) machine.image.inputExtent = machine.image.outputExtent = 0;
    TickBody body(machine, 1);
    RunOptions options;
    options.cycles = imageCopies ? 200'000 : 5'000'000;
    Scheduler scheduler(machine, {task("MainTask", TaskKind::Freewheeling, 30)}, {&body}, options);
    auto begin = std::chrono::steady_clock::now();
    scheduler.run();
    double seconds = secondsSince(begin);
    std::printf("virtual  freewheeling 1-statement task, %s: %.2f M activations/s (%.0f ns each)\n",
                imageCopies ? "64 KiB %I/%Q copies" : "no I/O copies", double(scheduler.activations()) / seconds / 1e6,
                seconds / double(scheduler.activations()) * 1e9);
}

void preemptionRate() {
    // Fast (every 20 us, 5 statements) preempts Background (endless) 50 000
    // times a simulated second: two switches per preemption plus the resume.
    Machine machine;
    machine.image.inputExtent = machine.image.outputExtent = 0;
    TickBody fast(machine, 5);
    TickBody background(machine, 1'000'000'000);
    RunOptions options;
    options.duration = 2'000 * kMs;
    Scheduler scheduler(machine,
                        {task("Fast", TaskKind::Cyclic, 5, 20'000), task("Background", TaskKind::Freewheeling, 30)},
                        {&fast, &background}, options);
    auto begin = std::chrono::steady_clock::now();
    scheduler.run();
    double seconds = secondsSince(begin);
    uint64_t preemptions = scheduler.activations() - 1;
    std::printf("virtual  preemption at statement boundaries: %.2f M preempt+resume pairs/s (%.0f ns each)\n",
                double(preemptions) / seconds / 1e6, seconds / double(preemptions) * 1e9);
}

void realJitter(size_t cycles, bool realtime) {
    Machine machine;
    JitterBody body(machine, 1 * kMs, cycles);
    RunOptions options;
    options.virtualClock = false;
    options.realtime = realtime;
    options.cycles = cycles;
    Scheduler scheduler(machine, {task("Tick1ms", TaskKind::Cyclic, 5, 1 * kMs)}, {&body}, options);
    scheduler.run();
    std::vector<PlcTime>& latencies = body.latencies();
    if (latencies.empty()) return;
    std::sort(latencies.begin(), latencies.end());
    auto at = [&](double fraction) { return double(latencies[size_t(fraction * double(latencies.size() - 1))]) / 1000.0; };
    uint64_t overruns = scheduler.tasksJson()[0]["overruns"];
    std::printf("real     1 ms cyclic task, %zu cycles%s: release jitter p50 %.1f us, p99 %.1f us, max %.1f us; %llu overruns\n",
                latencies.size(), realtime ? " (--realtime)" : "", at(0.5), at(0.99), double(latencies.back()) / 1000.0,
                static_cast<unsigned long long>(overruns));
}

}  // namespace

int main(int argc, char** argv) {
    size_t realCycles = 10'000;
    bool realtime = false;
    bool virtualOnly = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--real-cycles") && i + 1 < argc) realCycles = std::strtoull(argv[++i], nullptr, 10);
        else if (!std::strcmp(argv[i], "--realtime")) realtime = true;
        else if (!std::strcmp(argv[i], "--virtual-only")) virtualOnly = true;
        else {
            std::fprintf(stderr, "usage: bench_scheduler [--real-cycles N] [--realtime] [--virtual-only]\n");
            return 2;
        }
    }
    freewheelingRate(false);
    freewheelingRate(true);
    preemptionRate();
    if (!virtualOnly) realJitter(realCycles, realtime);
    return 0;
}
