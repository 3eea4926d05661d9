// The task configuration rules against the generic and the Baosky profile.
#include <catch2/catch.hpp>

#include "runtime/task_rules.h"
#include "tests/unit/runtime/fake_body.h"

using namespace strun::rt;
using namespace strun::rt::test;

namespace {
TaskSpec at(TaskSpec spec, int line) {
    spec.loc.line = line;
    return spec;
}
std::vector<std::string> messages(const std::vector<TaskRuleViolation>& violations) {
    std::vector<std::string> result;
    for (const auto& v : violations) result.push_back(std::to_string(v.loc.line) + ": " + v.message);
    return result;
}
}  // namespace

TEST_CASE("task names follow the seed's rules", "[task_rules]") {
    CHECK(taskNameProblem("MainTask").empty());
    CHECK(taskNameProblem("Cycle_1").empty());
    CHECK(taskNameProblem("_a").empty());
    CHECK(taskNameProblem("") == "task name must not be empty");
    CHECK(taskNameProblem("__a") == "task name '__a' must not contain consecutive underscores");
    CHECK(taskNameProblem("a_") == "task name 'a_' must not end with an underscore");
    CHECK(taskNameProblem("1a") == "task name '1a' must not start with a digit");
    CHECK(taskNameProblem("a b") == "task name 'a b' may contain only ASCII letters, digits and underscores");
    CHECK(taskNameProblem("a-b") == "task name 'a-b' may contain only ASCII letters, digits and underscores");
    CHECK(taskNameProblem("t\xC3\xA4sk").find("only ASCII") != std::string::npos);
}

TEST_CASE("the default MainTask configuration is valid", "[task_rules]") {
    TaskSpec main = ofKind("MainTask", TaskKind::Freewheeling, defaultProfile().defaultMainPriority,
                           defaultProfile().defaultMainWatchdog);
    CHECK(checkTaskRules(defaultProfile(), {main}).empty());
    CHECK(defaultProfile().defaultMainWatchdog == 200 * ms);
    CHECK(defaultProfile().defaultMainPriority == 30);
}

TEST_CASE("names are unique regardless of case; violations carry the task's line", "[task_rules]") {
    auto violations = checkTaskRules(defaultProfile(), {at(cyclic("Fast", 5, 1 * ms), 3), at(cyclic("FAST", 6, 2 * ms), 7)});
    CHECK(messages(violations) == std::vector<std::string>{"7: duplicate task name 'FAST' (first declared at line 3)"});
}

TEST_CASE("at most one startup, program-error and execution-timeout task", "[task_rules]") {
    auto violations = checkTaskRules(defaultProfile(), {
                                                           at(ofKind("S1", TaskKind::Startup, 1), 1),
                                                           at(ofKind("S2", TaskKind::Startup, 1), 2),
                                                           at(ofKind("E1", TaskKind::ProgramError, 1), 3),
                                                           at(ofKind("E2", TaskKind::ProgramError, 1), 4),
                                                           at(ofKind("T1", TaskKind::ExecTimeout, 1), 5),
                                                           at(ofKind("T2", TaskKind::ExecTimeout, 1), 6),
                                                       });
    CHECK(messages(violations) ==
          std::vector<std::string>{
              "2: task 'S2': only one startup task is allowed on generic (CODESYS-like)",
              "4: task 'E2': only one program error task is allowed on generic (CODESYS-like)",
              "6: task 'T2': only one exec timeout task is allowed on generic (CODESYS-like)",
          });
}

TEST_CASE("priorities, intervals and watchdogs must be in the profile's ranges", "[task_rules]") {
    auto violations = checkTaskRules(defaultProfile(), {
                                                           at(cyclic("A", 32, 1 * ms), 1),
                                                           at(cyclic("B", -1, 1 * ms), 2),
                                                           at(cyclic("C", 3, 0), 3),
                                                           at(cyclic("D", 3, 1 * ms, -5), 4),
                                                       });
    CHECK(messages(violations) ==
          std::vector<std::string>{
              "1: priority 32 of task 'A' is outside 0..31 for cyclic tasks on generic (CODESYS-like)",
              "2: priority -1 of task 'B' is outside 0..31 for cyclic tasks on generic (CODESYS-like)",
              "3: interval T#0s of task 'C' is outside T#1us..T#1d",
              "4: watchdog T#-5ns of task 'D' is outside T#1us..T#1d",
          });
}

TEST_CASE("the generic profile allows 100 tasks and no more", "[task_rules]") {
    std::vector<TaskSpec> tasks;
    for (int i = 0; i < 101; ++i) tasks.push_back(at(cyclic("T" + std::to_string(i), 10, 10 * ms), i + 1));
    auto violations = checkTaskRules(defaultProfile(), tasks);
    CHECK(messages(violations) ==
          std::vector<std::string>{"101: task 'T100': at most 100 tasks are allowed on generic (CODESYS-like)"});
    tasks.pop_back();
    CHECK(checkTaskRules(defaultProfile(), tasks).empty());
}

TEST_CASE("MONTHLY time events must be on day 1..28", "[task_rules]") {
    TaskSpec monthly = at(ofKind("Pay", TaskKind::TimeEvent, 10), 9);
    monthly.repeat = TimeRepeat::Monthly;
    monthly.atCalendarNanos = int64_t(28) * 86'400 * kSecond;  // 1970-01-29
    CHECK(messages(checkTaskRules(defaultProfile(), {monthly})) ==
          std::vector<std::string>{"9: monthly time event 'Pay' is on day 29; MONTHLY allows days 1..28 (use "
                                   "MONTH_END for the last day of the month)"});
    monthly.atCalendarNanos = int64_t(27) * 86'400 * kSecond;  // the 28th is fine
    CHECK(checkTaskRules(defaultProfile(), {monthly}).empty());
}

TEST_CASE("the Baosky profile has the seed's limits", "[task_rules]") {
    const PlcProfile* baosky = findProfile("BAOSKY");
    REQUIRE(baosky);
    CHECK(findProfile("nope") == nullptr);
    CHECK(allProfiles().front().id == "generic");
    std::vector<TaskSpec> tasks{
        at(cyclic("Cycle_1", 4, 20 * ms), 1),             // priority below 5
        at(cyclic("Cycle_2", 11, 20 * ms, 10 * ms), 2),  // watchdog below the period
        at(ofKind("MainTask", TaskKind::Freewheeling, 10), 3),  // not below every cyclic task
        at(ofKind("Timeout", TaskKind::ExecTimeout, 10, 100 * ms), 4),  // no watchdog allowed
        at(ofKind("Ev", TaskKind::Event, 10), 5),                      // no SINGLE events
    };
    CHECK(messages(checkTaskRules(*baosky, tasks)) ==
          std::vector<std::string>{
              "1: priority 4 of task 'Cycle_1' is outside 5..25 for cyclic tasks on Baosky T3/T4",
              "2: watchdog T#10ms of task 'Cycle_2' is shorter than its interval T#20ms",
              "4: exec timeout task 'Timeout' cannot have a watchdog on Baosky T3/T4",
              "5: event tasks are not available on Baosky T3/T4",
              "3: freewheeling task 'MainTask' (priority 10) must have a lower priority than cyclic task "
              "'Cycle_2' (priority 11) on Baosky T3/T4",
          });
    std::vector<TaskSpec> ten;
    for (int i = 0; i < 10; ++i) ten.push_back(at(cyclic("C" + std::to_string(i), 10, 20 * ms), i + 1));
    CHECK(messages(checkTaskRules(*baosky, ten)) ==
          std::vector<std::string>{"10: task 'C9': at most 9 cyclic tasks are allowed on Baosky T3/T4"});
}
