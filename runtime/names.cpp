// The printable names of the contract enums (machine.h, task_spec.h). These
// strings are part of the outside interface: --dump "code" and "kind".
#include "runtime/machine.h"
#include "runtime/task_spec.h"

namespace strun::rt {

const char* diagCodeName(DiagCode code) {
    switch (code) {
    case DiagCode::DivByZero: return "DIV_BY_ZERO";
    case DiagCode::ArrayBounds: return "ARRAY_BOUNDS";
    case DiagCode::CallDepth: return "CALL_DEPTH";
    case DiagCode::Watchdog: return "WATCHDOG";
    case DiagCode::Overrun: return "OVERRUN";
    case DiagCode::NullPointer: return "NULL_POINTER";
    case DiagCode::TaskError: return "TASK_ERROR";
    case DiagCode::SystemWatchdog: return "SYSTEM_WATCHDOG";
    case DiagCode::IoFault: return "IO_FAULT";
    case DiagCode::Log: return "LOG";
    }
    return "UNKNOWN";
}

const char* taskKindName(TaskKind kind) {
    switch (kind) {
    case TaskKind::Cyclic: return "cyclic";
    case TaskKind::Freewheeling: return "freewheeling";
    case TaskKind::Event: return "event";
    case TaskKind::Status: return "status";
    case TaskKind::Startup: return "startup";
    case TaskKind::ProgramError: return "program_error";
    case TaskKind::ExecTimeout: return "exec_timeout";
    case TaskKind::TimeEvent: return "time_event";
    case TaskKind::External: return "external";
    }
    return "unknown";
}

}  // namespace strun::rt
