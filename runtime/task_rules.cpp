#include "runtime/task_rules.h"

#include <cctype>
#include <map>
#include <string_view>

#include "runtime/civil_time.h"
#include "runtime/duration_text.h"

namespace strun::rt {

namespace {

std::string lowered(std::string_view text) {
    std::string result(text);
    for (char& c : result) c = char(std::tolower(static_cast<unsigned char>(c)));
    return result;
}

// "program error" for messages, from the dump name "program_error".
std::string kindWords(TaskKind kind) {
    std::string words = taskKindName(kind);
    for (char& c : words)
        if (c == '_') c = ' ';
    return words;
}

class RuleChecker {
public:
    RuleChecker(const PlcProfile& profile, const std::vector<TaskSpec>& tasks) : profile_(profile), tasks_(tasks) {}

    std::vector<TaskRuleViolation> run() {
        std::array<int, kTaskKindCount> countByKind{};
        for (size_t i = 0; i < tasks_.size(); ++i) {
            const TaskSpec& task = tasks_[i];
            checkName(i);
            checkCount(task, ++countByKind[kindIndex(task.kind)], int(i) + 1);
            if (int(i) + 1 <= profile_.maxTasks) checkGroupCounts(task);  // past the total: one message is enough
            checkTimeEventCounts(task);
            if (const FixedTask* fixed = profile_.fixedTask(task.name)) {
                checkFixedTask(task, *fixed);
            } else if (!profile_.fixedTasks.empty()) {
                reportNotFixed(task);
            } else {
                checkPriority(task);
                checkInterval(task);
                checkWatchdog(task);
            }
            checkTimeEvent(task);
            checkExternal(task);
        }
        checkFreewheelingBelowCyclic();
        checkPeriodicMaster();
        return std::move(violations_);
    }

private:
    void report(const TaskSpec& task, std::string message, bool unavailableOnTarget = false) {
        violations_.push_back({task.loc, std::move(message), unavailableOnTarget});
    }

    void checkName(size_t index) {
        const TaskSpec& task = tasks_[index];
        if (std::string problem = taskNameProblem(task.name); !problem.empty()) report(task, problem);
        // A map, not a scan of the earlier tasks: 20 000 TASKs took 28 s.
        auto [first, isNew] = firstByName_.emplace(lowered(task.name), index);
        if (!isNew)
            report(task, "duplicate task name '" + task.name + "' (first declared at line " +
                             std::to_string(tasks_[first->second].loc.line) + ")");
    }
    std::map<std::string, size_t> firstByName_;

    void checkCount(const TaskSpec& task, int countOfKind, int total) {
        if (total == profile_.maxTasks + 1) {
            report(task, "task '" + task.name + "': at most " + std::to_string(profile_.maxTasks) +
                             " tasks are allowed on " + std::string(profile_.description));
            return;  // one message per task is enough
        }
        const KindLimits& limits = profile_.limits(task.kind);
        if (limits.maxCount == 0) {
            if (countOfKind == 1)
                report(task, kindWords(task.kind) + " tasks are not available on " + std::string(profile_.description), true);
            return;
        }
        if (countOfKind == limits.maxCount + 1) {
            std::string limit = limits.maxCount == 1 ? "only one " + kindWords(task.kind) + " task is"
                                                     : "at most " + std::to_string(limits.maxCount) + " " +
                                                           kindWords(task.kind) + " tasks are";
            report(task, "task '" + task.name + "': " + limit + " allowed on " + std::string(profile_.description));
        }
    }

    void checkGroupCounts(const TaskSpec& task) {
        for (size_t g = 0; g < profile_.groupLimits.size(); ++g) {
            const GroupLimit& group = profile_.groupLimits[g];
            if (!(group.kinds & kindBit(task.kind))) continue;
            if (g >= countByGroup_.size()) break;
            if (++countByGroup_[g] == group.maxCount + 1)
                report(task, "task '" + task.name + "': at most " + std::to_string(group.maxCount) + " " +
                                 std::string(group.words) + " tasks are allowed on " + std::string(profile_.description));
        }
    }

    void checkTimeEventCounts(const TaskSpec& task) {
        if (task.kind != TaskKind::TimeEvent) return;
        bool once = task.repeat == TimeRepeat::Once;
        int limit = once ? profile_.maxOnceTimeEvents : profile_.maxRepeatTimeEvents;
        int count = once ? ++onceTimeEvents_ : ++repeatTimeEvents_;
        if (limit > 0 && count == limit + 1)
            report(task, "task '" + task.name + "': at most " + std::to_string(limit) +
                             (once ? " specified-time (once)" : " repeat-time") + " event tasks are allowed on " +
                             std::string(profile_.description));
    }

    std::string fixedNames() const {
        std::string names;
        for (const FixedTask& fixed : profile_.fixedTasks) names += (names.empty() ? "" : ", ") + std::string(fixed.name);
        return names;
    }

    void reportNotFixed(const TaskSpec& task) {
        report(task, "task '" + task.name + "': the tasks of " + std::string(profile_.description) + " are " +
                         fixedNames());
    }

    // M340: the fixed priority, the task's own period and watchdog ranges.
    void checkFixedTask(const TaskSpec& task, const FixedTask& fixed) {
        std::string where = " of task '" + task.name + "'";
        std::string on = " on " + std::string(profile_.description);
        if (task.kind == TaskKind::Freewheeling) {
            if (!fixed.freewheelingAllowed)
                report(task, "task '" + task.name + "' needs an INTERVAL in " + formatDuration(fixed.minInterval) + ".." +
                                 formatDuration(fixed.maxInterval) + on);
        } else if (task.kind == TaskKind::Cyclic) {
            if (task.interval < fixed.minInterval || task.interval > fixed.maxInterval)
                report(task, "interval " + formatDuration(task.interval) + where + " is outside " +
                                 formatDuration(fixed.minInterval) + ".." + formatDuration(fixed.maxInterval) + on);
            else if (task.interval % fixed.intervalStep != 0)
                report(task, "interval " + formatDuration(task.interval) + where + " must be a multiple of " +
                                 formatDuration(fixed.intervalStep) + on);
        }
        if (task.watchdog < fixed.minWatchdog || task.watchdog > fixed.maxWatchdog)
            report(task, "watchdog " + formatDuration(task.watchdog) + where + " is outside " +
                             formatDuration(fixed.minWatchdog) + ".." + formatDuration(fixed.maxWatchdog) + on);
    }

    void checkExternal(const TaskSpec& task) {
        if (task.inputDelayGiven && task.kind != TaskKind::External)
            report(task, "INPUT_DELAY is only for EXTERNAL tasks (task '" + task.name + "')");
        if (task.kind == TaskKind::External && task.inputDelay < 0)
            report(task, "input delay of task '" + task.name + "' must not be negative");
        else if (task.kind == TaskKind::External && task.inputDelay > profile_.maxExternalInputDelay)
            report(task, "input delay " + formatDuration(task.inputDelay) + " of task '" + task.name + "' is outside T#0s.." +
                             formatDuration(profile_.maxExternalInputDelay) + " on " + std::string(profile_.description) +
                             " (detection within " + formatDuration(profile_.externalDetectionDelay + profile_.maxExternalInputDelay) + ")");
        if (task.kind != TaskKind::External || (task.edges & ~profile_.externalEdges) == 0) return;
        report(task, "external task '" + task.name + "': only EDGE := RISING is available on " +
                         std::string(profile_.description));
    }

    // M340 (seed 002): a cyclic (freewheeling) master task excludes the auxiliary tasks.
    void checkPeriodicMaster() {
        if (profile_.fixedTasks.empty()) return;
        const TaskSpec* master = nullptr;
        for (const TaskSpec& task : tasks_)
            if (const FixedTask* fixed = profile_.fixedTask(task.name); fixed && fixed->freewheelingAllowed) master = &task;
        if (!master || master->kind != TaskKind::Freewheeling) return;
        for (const TaskSpec& task : tasks_)
            if (const FixedTask* fixed = profile_.fixedTask(task.name); fixed && fixed->needsPeriodicMaster)
                report(task, "task '" + task.name + "' needs a periodic " + master->name + " (give " + master->name +
                                 " an INTERVAL); a cyclic " + master->name + " excludes the auxiliary tasks on " +
                                 std::string(profile_.description));
    }

    void checkPriority(const TaskSpec& task) {
        if (task.kind == TaskKind::Startup && profile_.startupPriorityFixed) return;  // applyTaskDefaults fixed it
        const KindLimits& limits = profile_.limits(task.kind);
        if (task.priority >= limits.minPriority && task.priority <= limits.maxPriority) return;
        report(task, "priority " + std::to_string(task.priority) + " of task '" + task.name + "' is outside " +
                         std::to_string(limits.minPriority) + ".." + std::to_string(limits.maxPriority) + " for " +
                         kindWords(task.kind) + " tasks on " + std::string(profile_.description));
    }

    void checkInterval(const TaskSpec& task) {
        if (task.kind != TaskKind::Cyclic) return;
        if (task.interval < profile_.minInterval || task.interval > profile_.maxInterval) {
            report(task, "interval " + formatDuration(task.interval) + " of task '" + task.name + "' is outside " +
                             formatDuration(profile_.minInterval) + ".." + formatDuration(profile_.maxInterval));
        } else if (profile_.intervalStep > 1 && task.interval % profile_.intervalStep != 0) {
            report(task, "interval " + formatDuration(task.interval) + " of task '" + task.name +
                             "' must be a multiple of " + formatDuration(profile_.intervalStep));
        }
    }

    void checkWatchdog(const TaskSpec& task) {
        if (task.watchdog == 0) return;
        if (!profile_.limits(task.kind).watchdogAllowed) {
            report(task, kindWords(task.kind) + " task '" + task.name + "' cannot have a watchdog on " +
                             std::string(profile_.description));
        } else if (task.watchdog < profile_.minWatchdog || task.watchdog > profile_.maxWatchdog) {
            report(task, "watchdog " + formatDuration(task.watchdog) + " of task '" + task.name + "' is outside " +
                             formatDuration(profile_.minWatchdog) + ".." + formatDuration(profile_.maxWatchdog));
        } else if (profile_.watchdogAtLeastInterval && task.kind == TaskKind::Cyclic &&
                   task.watchdog < task.interval) {
            report(task, "watchdog " + formatDuration(task.watchdog) + " of task '" + task.name +
                             "' is shorter than its interval " + formatDuration(task.interval));
        }
    }

    void checkTimeEvent(const TaskSpec& task) {
        if (task.kind != TaskKind::TimeEvent || task.repeat != TimeRepeat::Monthly) return;
        int day = civilFromDays(dayOf(task.atCalendarNanos)).day;
        if (day > 28)
            report(task, "monthly time event '" + task.name + "' is on day " + std::to_string(day) +
                             "; MONTHLY allows days 1..28 (use MONTH_END for the last day of the month)");
    }

    void checkFreewheelingBelowCyclic() {
        if (!profile_.freewheelingBelowCyclic) return;
        for (const TaskSpec& free : tasks_) {
            if (free.kind != TaskKind::Freewheeling) continue;
            for (const TaskSpec& cyclic : tasks_) {
                if (cyclic.kind != TaskKind::Cyclic || cyclic.priority < free.priority) continue;
                report(free, "freewheeling task '" + free.name + "' (priority " + std::to_string(free.priority) +
                                 ") must have a lower priority than cyclic task '" + cyclic.name + "' (priority " +
                                 std::to_string(cyclic.priority) + ") on " + std::string(profile_.description));
                break;
            }
        }
    }

    const PlcProfile& profile_;
    const std::vector<TaskSpec>& tasks_;
    std::vector<TaskRuleViolation> violations_;
    std::array<int, 4> countByGroup_{};
    int onceTimeEvents_ = 0, repeatTimeEvents_ = 0;
};

}  // namespace

std::string taskNameProblem(const std::string& name) {
    if (name.empty()) return "task name must not be empty";
    auto isAsciiDigit = [](char c) { return c >= '0' && c <= '9'; };
    auto isAsciiLetter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
    for (char c : name)
        if (!isAsciiLetter(c) && !isAsciiDigit(c) && c != '_')
            return "task name '" + name + "' may contain only ASCII letters, digits and underscores";
    if (isAsciiDigit(name.front())) return "task name '" + name + "' must not start with a digit";
    if (name.find("__") != std::string::npos) return "task name '" + name + "' must not contain consecutive underscores";
    if (name.back() == '_') return "task name '" + name + "' must not end with an underscore";
    return "";
}

std::string applyTaskDefaults(const PlcProfile& profile, TaskSpec& task) {
    std::string warning;
    auto fixPriority = [&](int fixedPriority) {
        if (task.priorityGiven && task.priority != fixedPriority)
            warning = "the priority of task '" + task.name + "' is fixed at " + std::to_string(fixedPriority) + " on " +
                      std::string(profile.description) + "; PRIORITY := " + std::to_string(task.priority) + " is ignored";
        task.priority = fixedPriority;
    };
    if (const FixedTask* fixed = profile.fixedTask(task.name)) {
        task.systemSlot = profile.fixedTaskIndex(task.name);
        fixPriority(fixed->priority);
        if (!task.watchdogGiven) task.watchdog = fixed->defaultWatchdog;
        if (!task.intervalGiven && task.kind == TaskKind::Freewheeling && fixed->defaultInterval > 0) {
            task.interval = fixed->defaultInterval;
            task.kind = TaskKind::Cyclic;
        }
        return warning;
    }
    const KindLimits& limits = profile.limits(task.kind);
    if (task.kind == TaskKind::Startup && profile.startupPriorityFixed) fixPriority(limits.defaultPriority);
    if (!task.priorityGiven) task.priority = limits.defaultPriority;
    if (!task.watchdogGiven) task.watchdog = limits.defaultWatchdog;
    return warning;
}

std::string programCountProblem(const PlcProfile& profile, const TaskSpec& task, int programCount) {
    if (profile.maxProgramsPerTask == 0 || programCount <= profile.maxProgramsPerTask) return "";
    return "task '" + task.name + "' calls " + std::to_string(programCount) + " programs; at most " +
           std::to_string(profile.maxProgramsPerTask) + " are allowed per task on " + std::string(profile.description);
}

std::vector<TaskRuleViolation> checkTaskRules(const PlcProfile& profile, const std::vector<TaskSpec>& tasks) {
    return RuleChecker(profile, tasks).run();
}

}  // namespace strun::rt
