// The printable names of the contract enums, and IEC duration text.
#include <catch2/catch.hpp>

#include "runtime/duration_text.h"
#include "runtime/scheduler.h"
#include "stdlib/value_format.h"

using namespace strun::rt;

TEST_CASE("diagnostic codes have their --dump names", "[names]") {
    CHECK(std::string(diagCodeName(DiagCode::DivByZero)) == "DIV_BY_ZERO");
    CHECK(std::string(diagCodeName(DiagCode::ArrayBounds)) == "ARRAY_BOUNDS");
    CHECK(std::string(diagCodeName(DiagCode::CallDepth)) == "CALL_DEPTH");
    CHECK(std::string(diagCodeName(DiagCode::Watchdog)) == "WATCHDOG");
    CHECK(std::string(diagCodeName(DiagCode::Overrun)) == "OVERRUN");
    CHECK(std::string(diagCodeName(DiagCode::NullPointer)) == "NULL_POINTER");
    CHECK(std::string(diagCodeName(DiagCode::TaskError)) == "TASK_ERROR");
    CHECK(std::string(diagCodeName(DiagCode::SystemWatchdog)) == "SYSTEM_WATCHDOG");
    CHECK(std::string(diagCodeName(DiagCode::IoFault)) == "IO_FAULT");
}

TEST_CASE("task kinds and PLC states have their --dump names", "[names]") {
    CHECK(std::string(taskKindName(TaskKind::Cyclic)) == "cyclic");
    CHECK(std::string(taskKindName(TaskKind::Freewheeling)) == "freewheeling");
    CHECK(std::string(taskKindName(TaskKind::Event)) == "event");
    CHECK(std::string(taskKindName(TaskKind::Status)) == "status");
    CHECK(std::string(taskKindName(TaskKind::Startup)) == "startup");
    CHECK(std::string(taskKindName(TaskKind::ProgramError)) == "program_error");
    CHECK(std::string(taskKindName(TaskKind::ExecTimeout)) == "exec_timeout");
    CHECK(std::string(taskKindName(TaskKind::TimeEvent)) == "time_event");
    CHECK(std::string(plcStateName(PlcState::Run)) == "RUN");
    CHECK(std::string(plcStateName(PlcState::Stop)) == "STOP");
    CHECK(std::string(plcStateName(PlcState::Halt)) == "HALT");
}

TEST_CASE("PLC times print as IEC durations", "[names]") {
    CHECK(formatDuration(0) == "T#0s");
    CHECK(formatDuration(1'500'000'000) == "T#1s500ms");
    CHECK(formatDuration(-250'000'000) == "T#-250ms");
    CHECK(formatDuration(1'250'000) == "T#1ms250us");
    CHECK(formatDuration(999) == "T#999ns");
    CHECK(formatDuration(int64_t(86'400) * 1'000'000'000 * 2 + 3'600'000'000'000 + 1'000) == "T#2d1h1us");
    CHECK(formatDuration(std::numeric_limits<int64_t>::min()) == "T#-106751d23h47m16s854ms775us808ns");
}

TEST_CASE("the trace's durations are written exactly like --dump TIME values", "[names]") {
    // The runtime keeps its own formatter (no dependency on the stdlib's
    // evolution); this pins that both agree.
    for (int64_t value : {int64_t(0), int64_t(1), int64_t(-1), int64_t(999'999), int64_t(1'000'000'001),
                          int64_t(90'061'001'001'001), std::numeric_limits<int64_t>::max(),
                          std::numeric_limits<int64_t>::min()}) {
        INFO(value);
        CHECK(formatDuration(value) == strun::stdlib::formatDuration(value));
    }
}
