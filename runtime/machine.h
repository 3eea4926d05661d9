// The state shared between the interpreter and the task runtime while a
// project runs. The interpreter touches it at every statement boundary
// (Machine::tick), so the hot part is one decrement and one branch; all
// decisions (preemption, watchdog, fault handling, stop) happen behind
// AttentionHandler::onAttention(), which the scheduler implements.
#pragma once

#include <algorithm>
#include <atomic>
#include <new>
#include <utility>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/heap.h"
#include "runtime/memory_map.h"

namespace strun::rt {

// PLC time: nanoseconds since the PLC went to RUN (virtual or real clock).
using PlcTime = int64_t;
constexpr PlcTime kNever = std::numeric_limits<PlcTime>::max();
// The end of PLC time (2^62 ns, about 146 years): every run stops there, and
// one statement costs at most kMaxStmtCost, so `now` cannot overflow.
constexpr PlcTime kPlcTimeLimit = PlcTime{1} << 62;
constexpr PlcTime kMaxStmtCost = PlcTime{86400} * 1000000000;  // one day

// Every code that can appear in the diagnostic buffer. Documented in
// docs/diagnostics.md; names (diagCodeName) are the `code` strings of --dump.
enum class DiagCode {
    DivByZero,     // DIV_BY_ZERO: integer / or MOD by zero; divisor 1 used
    ArrayBounds,   // ARRAY_BOUNDS: subscript outside the declared range
    CallDepth,     // CALL_DEPTH: call nesting deeper than 16
    Watchdog,      // WATCHDOG: task execution exceeded its watchdog
    Overrun,       // OVERRUN: cyclic task released while still busy; activation dropped
    NullPointer,   // NULL_POINTER: dereference of a null POINTER/REFERENCE
    TaskError,     // TASK_ERROR: other runtime failure of a task (message says which)
    SystemWatchdog,  // SYSTEM_WATCHDOG: a family's firmware watchdog (M241: high priorities held the CPU)
    IoFault,       // IO_FAULT: a --modbus-client device stopped answering (once per outage); the run goes on
    Log,           // LOG: a message the program logged (Tc2_System ADSLOGSTR ...); no reaction
};
const char* diagCodeName(DiagCode code);

// Zero-filled memory straight from the system (anonymous mmap): the five
// 64 KiB areas of the image cost nothing (no memset, no page touched) until
// a program addresses them. Value-initialisation in std::vector, or calloc
// of heap memory, would write every byte (5 % of a one-line run). For
// buffers of a fixed size: construct() leaves bytes as they are, so a vector
// shrunk and grown again would not be zeroed.
// Zeroed memory of `bytes` (throws std::bad_alloc), and its release:
void* allocateZeroedPages(size_t bytes);
void freeZeroedPages(void* p, size_t bytes);

template <typename T>
struct ZeroedAllocator {
    using value_type = T;
    ZeroedAllocator() = default;
    template <typename U>
    ZeroedAllocator(const ZeroedAllocator<U>&) {}
    T* allocate(size_t n) { return static_cast<T*>(allocateZeroedPages(n * sizeof(T))); }
    void deallocate(T* p, size_t n) { freeZeroedPages(p, n * sizeof(T)); }
    template <typename U>
    void construct(U*) {}  // already zero
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) { ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...); }
    template <typename U>
    bool operator==(const ZeroedAllocator<U>&) const { return true; }
};
using ImageArea = std::vector<uint8_t, ZeroedAllocator<uint8_t>>;

// The process image of direct addresses (%I, %Q, %M). CODESYS addressing:
// %IX3.2 = bit 2 of byte 3, %IB3 = byte 3, %IW3 = bytes 6..7, %ID3 = bytes
// 12..15, %IL3 = bytes 24..31 (the index counts units of the access size).
struct ProcessImage {
    static constexpr size_t kSize = 65536;  // bytes per area
    // Defined in zeroed_pages.cpp, not inline: an inline copy compiled at
    // -O1 in the command line's files (STRUN_COLD_OPT) keeps the vectors'
    // empty per-byte construct and destroy loops, 5 x 64 Ki iterations at
    // every start (decision 0348). Out of line, only the runtime's -O3 copy
    // exists, and the loops are gone.
    ProcessImage();
    ProcessImage(const ProcessImage&);
    ProcessImage(ProcessImage&&) noexcept;
    ProcessImage& operator=(const ProcessImage&);
    ProcessImage& operator=(ProcessImage&&) noexcept;
    ~ProcessImage();
    ImageArea inputs = ImageArea(kSize);   // %I as the program sees it
    ImageArea outputs = ImageArea(kSize);  // %Q as the program writes it
    ImageArea memory = ImageArea(kSize);   // %M
    ImageArea physicalInputs = ImageArea(kSize);   // what the "field" presents
    ImageArea physicalOutputs = ImageArea(kSize);  // what the field last received
    // The system bits %S0..%S255 (bit n: byte n/8, bit n%8) and system words
    // %SW0..%SW1023 (word n: bytes 2n..2n+1, little-endian) of a target that
    // has them (runtime/system_area.h); unused elsewhere.
    static constexpr size_t kSystemBits = 256;
    static constexpr size_t kSystemWords = 1024;
    std::vector<uint8_t> systemBits = std::vector<uint8_t>(kSystemBits / 8);
    std::vector<uint8_t> systemWords = std::vector<uint8_t>(kSystemWords * 2);
    // Bytes of %I / %Q the project addresses at all. The scheduler copies
    // that many at every task start (inputs) and end (outputs), so the
    // checker should lower them to the highest byte any direct address
    // reaches + 1; kSize is always correct, only slower (64 KiB per copy).
    size_t inputExtent = kSize;
    size_t outputExtent = kSize;
};

// Implemented by the scheduler.
class AttentionHandler {
public:
    virtual ~AttentionHandler() = default;
    // Called by the interpreter when Machine::time() >= Machine::deadline at a
    // statement boundary. May run higher-priority tasks nested (preemption)
    // before returning. Returns true when the current activation must be
    // aborted (watchdog, STOP): the interpreter then unwinds to the task body.
    virtual bool onAttention() = 0;
    // A runtime fault detected by the interpreter in the running task.
    // Records it in the diagnostic buffer and decides what follows (nothing,
    // release the program-error task, STOP); anything that must interrupt the
    // running code makes the next tick call onAttention().
    // `file` (an index of the project's source files, -1 unknown) and `col`
    // complete the location for the fault report and --dump.
    virtual void onFault(DiagCode code, std::string_view pou, int line, std::string message, int file = -1, int col = 0) = 0;
    // A message the program logs (Tc2_System ADSLOGSTR ...): recorded in the
    // diagnostic buffer as LOG, nothing else follows.
    virtual void onLog(std::string_view pou, int line, std::string message, int file = -1, int col = 0) {}
    // Current PLC time in ns (virtual clock: Machine::now; real clock: read now).
    virtual PlcTime currentTime() = 0;
    // Calendar date-time now, as nanoseconds since 1970-01-01-00:00:00 (UTC),
    // from --start on the virtual clock or the system clock on the real one.
    virtual int64_t calendarNanos() = 0;
    // The calendar time (as calendarNanos) at which the running task's current
    // activation was due to start (TwinCAT F_GetTaskTime, F_GetCurDcTaskTime64).
    virtual int64_t taskStartCalendarNanos() { return calendarNanos(); }
    // The running task's period (0: not a cyclic task) and a request to change
    // it (M241 GetCurrentTaskCycle / SetCurrentTaskCycle). False: refused.
    virtual PlcTime currentTaskInterval() { return 0; }
    // The running task's name ("" when none) and its 1-based place in the
    // task list (0 when none): Tc2_System ADSLOG lines, GETCURTASKINDEX.
    virtual std::string currentTaskName() const { return {}; }
    virtual int currentTaskIndex() const { return 0; }
    // Task `index` (1-based, as currentTaskIndex) for Tc2_System's _TaskInfo[];
    // false when there is none.
    struct TaskInfo {
        std::string_view name;
        int priority = 0;
        PlcTime interval = 0;        // 0: not cyclic
        uint64_t started = 0;        // activations started, the running one included
        PlcTime lastExec = 0;        // execution time of the last completed activation
        bool overrun = false;        // its last release found it still busy
    };
    virtual bool taskInfo(int index, TaskInfo& out) const { return false; }
    virtual bool setCurrentTaskInterval(PlcTime) { return false; }
};

// How many statements may run between two looks at the deadline when the
// countdown alone would allow more: a deadline lowered from another thread
// (the real clock's timer, a Ctrl-C stop request) is seen within this many
// statements (decision 0265).
constexpr int64_t kTickPoll = 256;

struct Machine {
    // PLC time as a countdown (decision 0265). Every statement boundary and
    // loop back-edge ticks: one decrement of `left` and one branch. `left`
    // counts the ticks that may still pass before PLC time can reach the
    // deadline; when it runs out, countdownExpired() works out the time (each tick
    // still costs stmtCost on the virtual clock), calls onAttention() if the
    // deadline is reached, and grants the next countdown. PLC time itself is
    // computed when read: time().
    int64_t left = 0;
    // Virtual clock: the cost of one statement. Real clock: 0, and the
    // scheduler sets the time (setTime) from the clock in onAttention.
    PlcTime stmtCost = 0;
    // When PLC time >= deadline at a tick the interpreter calls
    // handler->onAttention(). On the interpreter's thread it changes only
    // through setDeadline / requestAttention (which grant a new countdown);
    // another thread only lowers it (requestAttentionFromOtherThread), seen
    // within kTickPoll statements.
    std::atomic<PlcTime> deadline{kNever};
    AttentionHandler* handler = nullptr;
    ProcessImage image;
    // What pointers may reach (registered by the compiler, the task bodies and the scheduler).
    MemoryMap memory;
    // __NEW / __DELETE blocks, regions of `memory` while they live.
    Heap heap{memory};

    // At every statement boundary and loop back-edge. True: abort the activation.
    inline bool tick() {
        if (__builtin_expect(--left < 0, 0)) return countdownExpired();
        return false;
    }
    // The current PLC time (virtual clock: base + stmtCost per tick since).
    PlcTime time() const { return base_ + (granted_ - left) * stmtCost; }
    void setTime(PlcTime t) {
        base_ = t;
        granted_ = left;
        regrant();
    }
    void setStmtCost(PlcTime cost) {
        base_ = time();
        granted_ = left;
        stmtCost = cost;
        regrant();
    }
    // On the interpreter's (scheduler's) thread.
    void setDeadline(PlcTime at) {
        deadline.store(at, std::memory_order_relaxed);
        regrant();
    }
    // Make the next tick call onAttention() (interpreter's thread).
    void requestAttention() { setDeadline(std::numeric_limits<PlcTime>::min()); }
    // From another thread or a signal handler: lowers the deadline only (lock
    // free); the running code sees it within kTickPoll statements.
    void requestAttentionFromOtherThread() { deadline.store(std::numeric_limits<PlcTime>::min(), std::memory_order_relaxed); }
    // Make the next tick take the slow path without touching time or the
    // deadline: the interpreter unwinding an aborted activation stops there.
    void expireCountdown() {
        base_ = time();
        left = granted_ = 0;
    }
    // `left` went below 0: this tick is the (granted_ + 1)-th since base_.
    // Calls onAttention() when the deadline is reached; true: abort.
    [[gnu::noinline, gnu::cold]] bool countdownExpired() {
        base_ = time();
        left = granted_ = 0;
        bool abort = false;
        if (base_ >= deadline.load(std::memory_order_relaxed)) abort = handler->onAttention();
        regrant();
        return abort;
    }

private:
    PlcTime base_ = 0;     // PLC time when `left` was `granted_`
    int64_t granted_ = 0;

    // Folds the ticks counted so far into base_ and grants the ticks until
    // the first one whose time reaches the deadline (at most kTickPoll).
    // Always inlined: countdownExpired() is an inline function compiled in
    // many files, and whether GCC inlined regrant() into the copy the linker
    // kept changed with the link order (+0.05 % instructions on every
    // workload after an unrelated file was added).
    [[gnu::always_inline]] void regrant() {
        const PlcTime t = time();
        base_ = t;
        const PlcTime d = deadline.load(std::memory_order_relaxed);
        int64_t k;
        if (t >= d) k = 0;  // the very next tick calls onAttention()
        else if (stmtCost <= 0) k = kTickPoll;
        else k = std::min<int64_t>((d - t - 1) / stmtCost, kTickPoll);  // ceil((d - t) / cost) - 1 ticks pass below d
        left = granted_ = k;
    }
};

}  // namespace strun::rt
