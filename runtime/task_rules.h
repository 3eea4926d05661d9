// The configuration rules every PLC family shares (task names, one startup /
// program-error / execution-timeout task) and the limits of the chosen
// profile (plc_profile.h). The checker reports each violation as a compile
// error at the task's location.
#pragma once

#include <string>
#include <vector>

#include "runtime/plc_profile.h"
#include "runtime/source_location.h"
#include "runtime/task_spec.h"

namespace strun::rt {

struct TaskRuleViolation {
    SourceLoc loc;
    std::string message;
    bool unavailableOnTarget = false;  // a kind of task the target does not have (else: a rule broken)
};

// Fills in what the TASK declaration left out from the profile: the kind's
// default PRIORITY and WATCHDOG; on a family with fixed tasks (M340) the
// task's fixed priority, default period (none: freewheeling) and watchdog,
// and its system-variable slot. A written PRIORITY where the family fixes
// it (M340 tasks, the Baosky startup task) is replaced; the returned warning
// says so ("" when none). Call before checkTaskRules.
std::string applyTaskDefaults(const PlcProfile& profile, TaskSpec& task);

// Violations in declaration order of the offending task; empty when the
// configuration is valid for `profile`.
std::vector<TaskRuleViolation> checkTaskRules(const PlcProfile& profile, const std::vector<TaskSpec>& tasks);

// The name rules alone (seed 000, 4.6.1.4): not empty, ASCII letters, digits
// and underscores only, not starting with a digit, no consecutive
// underscores, no trailing underscore. Returns "" when `name` is valid, else
// why not.
std::string taskNameProblem(const std::string& name);

// "" when a task may call `programCount` programs on `profile`, else why not
// (Baosky: at most 99 programs per task).
std::string programCountProblem(const PlcProfile& profile, const TaskSpec& task, int programCount);

}  // namespace strun::rt
