// The real clock: PLC time is CLOCK_MONOTONIC since RUN, and an attention
// timer thread that lowers Machine::deadline when the scheduler's next moment
// (a release, a watchdog expiry, the end of --for) comes while the
// interpreter thread is busy running a task.
//
// The handshake (docs/decisions/0012-real-clock-handshake.md):
//  * the timer thread only ever LOWERS the deadline (Machine::requestAttentionFromOtherThread);
//  * the interpreter thread raises it only at the top of onAttention, with an
//    atomic exchange, and only then reads the clock and handles everything
//    due — so a poke that lands before the exchange is covered by that clock
//    read, and one that lands after it causes one more (cheap) onAttention;
//  * arm() publishes the next moment; the timer thread re-reads it after
//    announcing how long it is about to sleep (Dekker-style, seq_cst), so a
//    new, earlier moment is never slept through.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

#include "runtime/machine.h"

namespace strun::rt {

// CLOCK_MONOTONIC in ns (std::chrono::steady_clock is the same clock on Linux).
int64_t monotonicNanos();
// CLOCK_REALTIME in ns since 1970.
int64_t realtimeNanos();
// Sleeps until CLOCK_MONOTONIC reaches `monotonicDeadline` (absolute, so no
// drift), or a signal interrupts the sleep.
void sleepUntilMonotonic(int64_t monotonicDeadline);

class AttentionTimer {
public:
    // `origin`: the CLOCK_MONOTONIC value of PLC time 0.
    AttentionTimer(Machine& machine, int64_t origin);
    ~AttentionTimer();
    AttentionTimer(const AttentionTimer&) = delete;
    AttentionTimer& operator=(const AttentionTimer&) = delete;

    // Interpreter thread: poke the machine when PLC time reaches `at`
    // (kNever: nothing to wait for). Replaces the previous moment.
    void arm(PlcTime at);
    // PLC time 0 moves `delta` ns later (the PLC was paused that long).
    void shiftOrigin(int64_t delta);
    std::thread& thread() { return thread_; }
    // Moves PLC time 0 (before the first arm(): the scheduler takes its
    // origin after starting this thread, whose stack --realtime locks).
    void setOrigin(int64_t origin) { origin_.store(origin); }

private:
    void loop();

    Machine& machine_;
    std::atomic<int64_t> origin_;
    std::atomic<PlcTime> wakeAt_{kNever};
    std::atomic<PlcTime> sleepingUntil_{kNever};
    std::mutex mutex_;
    std::condition_variable wakeUp_;
    bool quit_ = false;  // under mutex_
    std::thread thread_;
};

}  // namespace strun::rt
