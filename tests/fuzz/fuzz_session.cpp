#include "tests/fuzz/fuzz_session.h"

#include <sstream>

#include <nlohmann/json.hpp>

#include "interpreter/project/dump_json.h"
#include "interpreter/project/task_runner.h"
#include "runtime/scheduler.h"

namespace strun::fuzz {

Session::Session() : library_(project::parseLibrary(libraryLog_)) {}

std::string Session::runOnce(const uint8_t* data, size_t size) {
    if (size > kMaxInputBytes) return "";
    SourceSet sources = library_->sources;
    int file = sources.add("fuzz.st", std::string(reinterpret_cast<const char*>(data), size));
    CompileLog log;
    auto model = project::compileProject(sources, {file}, log, {}, library_.get());
    std::ostringstream sink;
    log.print(sink, sources);
    if (!model) return "";
    std::vector<rt::TaskSpec> specs;
    std::vector<std::unique_ptr<project::TaskRunner>> runners;
    std::vector<rt::TaskBody*> bodies;
    for (const auto& t : model->tasks) {
        specs.push_back(t.spec);
        runners.push_back(std::make_unique<project::TaskRunner>(*model, t));
        bodies.push_back(runners.back().get());
    }
    rt::RunOptions options;
    options.virtualClock = true;
    options.stmtCost = 1000;
    options.duration = kPlcTimeNanos;
    options.warnings = &sink;
    rt::Scheduler scheduler(model->machine, specs, bodies, options);
    rt::PlcState state = scheduler.run();
    nlohmann::ordered_json out;
    out["state"] = rt::plcStateName(state);
    out["globals"] = project::globalsJson(*model);
    out["programs"] = project::programsJson(*model);
    out["tasks"] = scheduler.tasksJson();
    out["diagnostics"] = scheduler.diagnosticsJson();
    return out.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace strun::fuzz
