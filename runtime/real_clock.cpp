#include "runtime/real_clock.h"

#include <chrono>
#include <csignal>
#include <ctime>

#include <pthread.h>

namespace strun::rt {

namespace {

int64_t readClock(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return int64_t(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

}  // namespace

int64_t monotonicNanos() { return readClock(CLOCK_MONOTONIC); }
int64_t realtimeNanos() { return readClock(CLOCK_REALTIME); }

void sleepUntilMonotonic(int64_t monotonicDeadline) {
    timespec ts{};
    ts.tv_sec = time_t(monotonicDeadline / 1'000'000'000);
    ts.tv_nsec = long(monotonicDeadline % 1'000'000'000);
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
}

AttentionTimer::AttentionTimer(Machine& machine, int64_t origin) : machine_(machine), origin_(origin) {
    // The timer thread blocks every signal, so SIGINT reaches the PLC thread
    // (and interrupts its idle sleep) instead.
    sigset_t all;
    sigset_t previous;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &previous);
    thread_ = std::thread([this] { loop(); });
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

AttentionTimer::~AttentionTimer() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    wakeUp_.notify_one();
    thread_.join();
}

void AttentionTimer::arm(PlcTime at) {
    wakeAt_.store(at);
    // Only an earlier moment needs waking the thread; a later one is picked
    // up when the current sleep ends.
    if (at < sleepingUntil_.load()) {
        std::lock_guard lock(mutex_);
        wakeUp_.notify_one();
    }
}

void AttentionTimer::shiftOrigin(int64_t delta) {
    origin_.fetch_add(delta);
    std::lock_guard lock(mutex_);
    wakeUp_.notify_one();
}

void AttentionTimer::loop() {
    std::unique_lock lock(mutex_);
    while (!quit_) {
        PlcTime at = wakeAt_.load();
        sleepingUntil_.store(at);
        if (wakeAt_.load() != at) continue;  // re-armed meanwhile: start over
        if (at == kNever) {
            wakeUp_.wait(lock);
            continue;
        }
        PlcTime now = monotonicNanos() - origin_;
        if (now >= at) {
            // Consume the moment so the thread does not poke again until re-armed.
            if (wakeAt_.compare_exchange_strong(at, kNever)) machine_.requestAttentionFromOtherThread();
            continue;
        }
        auto until = std::chrono::steady_clock::time_point(std::chrono::nanoseconds(origin_ + at));
        wakeUp_.wait_until(lock, until);
    }
}

}  // namespace strun::rt
