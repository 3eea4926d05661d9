#include "interpreter/testing/test_session.h"

#include "interpreter/project/compile.h"
#include "interpreter/project/task_runner.h"
#include "interpreter/testing/axunit_fixtures.h"
#include "interpreter/testing/suite_finder.h"
#include "interpreter/testing/tcunit_parameters.h"
#include "interpreter/testing/test_registry.h"

namespace strun::testing {

namespace {

// A task body that stops the run once every suite has finished.
class StopWhenFinished final : public rt::TaskBody {
public:
    StopWhenFinished(rt::TaskBody& inner, const TestRegistry& reg) : inner_(inner), reg_(reg) {}
    bool runActivation() override {
        bool completed = inner_.runActivation();
        if (reg_.allFinished() || reg_.aborted) rt::Scheduler::requestStop();
        return completed;
    }
    bool currentPosition(std::string& pou, int& line) const override { return inner_.currentPosition(pou, line); }

private:
    rt::TaskBody& inner_;
    const TestRegistry& reg_;
};

// The suites RUN() calls, the limits of GVL_Param_TcUnit, and which suites
// those limits leave out.
void findSuites(sema::ProgramModel& model) {
    collectSuites(model, *model.tests);
    nameAxSuites(*model.tests);  // AxUnit fixtures' suites by the fixtures' names
    readTcUnitLimits(model, *model.tests);
    model.tests->markSuitesPastLimit();
}

}  // namespace

std::unique_ptr<sema::ProgramModel> compileForTests(SourceSet& sources, const std::vector<int>& userFiles, CompileLog& log,
                                                    const sema::CompileOptions& options) {
    // `log` may already hold the input stage's messages: both compiles start from them.
    const CompileLog before = log;
    auto model = project::compileProject(sources, userFiles, log, options);
    if (!model || model->tests->runCalls > 0) {
        if (model) findSuites(*model);
        return model;
    }
    log = before;
    std::vector<int> files = userFiles;
    std::vector<std::string> blocks = model->tests->suiteBlocks;
    // AxUnit fixtures become suite blocks too (decision 0365).
    if (std::string fixtures = axFixtureSuites(model->tests->axFixtures, blocks); !fixtures.empty())
        files.push_back(sources.add("<strun AxUnit fixtures>", std::move(fixtures)));
    files.push_back(sources.add("<strun test program>", syntheticTestProgram(blocks)));
    sema::CompileOptions withProgram = options;
    withProgram.testProgram = kSyntheticProgramName;
    model = project::compileProject(sources, files, log, withProgram);
    if (model) findSuites(*model);
    return model;
}

TestRunResult runTests(sema::ProgramModel& model, rt::RunOptions options, const std::string& filter) {
    TestRegistry& reg = *model.tests;
    reg.filter = filter;
    std::vector<rt::TaskSpec> specs;
    for (const auto& t : model.tasks) specs.push_back(t.spec);
    // The watchdog applies to each suite call (a test that loops fails alone);
    // the task itself runs without one, bounded by the timeout.
    // That is the watchdog of the task calling the program that holds the first suite.
    reg.watchdog = specs.empty() ? 0 : specs.front().watchdog;
    if (!reg.suites.empty()) {
        const std::string& path = reg.suites.front().path;
        const std::string program = path.substr(0, path.find_first_of(".["));
        for (const auto& t : model.tasks)
            for (const auto& call : t.calls)
                if (call.program && call.name == program) reg.watchdog = t.spec.watchdog;
    }
    for (auto& s : specs) s.watchdog = 0;
    options.virtualClock = true;
    options.cycles.reset();
    std::vector<std::unique_ptr<project::TaskRunner>> runners;
    std::vector<std::unique_ptr<StopWhenFinished>> stoppers;
    std::vector<rt::TaskBody*> bodies;
    for (const auto& t : model.tasks) {
        runners.push_back(std::make_unique<project::TaskRunner>(model, t));
        stoppers.push_back(std::make_unique<StopWhenFinished>(*runners.back(), reg));
        bodies.push_back(stoppers.back().get());
    }
    TestRunResult result;
    if (!reg.suites.empty() && !specs.empty()) {
        rt::Scheduler scheduler(model.machine, specs, bodies, options);
        result.state = scheduler.run();
        result.endTime = scheduler.endTime();
        result.diagnostics = scheduler.diagnostics();
    }
    if (result.state != rt::PlcState::Run) {
        std::string why = "the PLC went to STOP";
        for (auto it = result.diagnostics.rbegin(); it != result.diagnostics.rend(); ++it)
            if (it->code != rt::DiagCode::DivByZero && it->code != rt::DiagCode::Overrun) {
                why += ": " + std::string(rt::diagCodeName(it->code)) + ": " + it->message;
                break;
            }
        reg.failUnfinished(why);
    } else {
        reg.failUnfinished(reg.aborted ? reg.abortReason : "timeout");
    }
    reg.addNotRun();
    reg.applyTestLimit();
    return result;
}

}  // namespace strun::testing
