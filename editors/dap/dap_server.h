// strun debug: a Debug Adapter Protocol adapter on stdin / stdout
// (docs/editors.md). The requests are served on the main thread; the PLC
// runs on a thread of its own under a DebugSession, which stops it at
// statement boundaries.
#pragma once

#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/command_line.h"
#include "cli/live_options.h"
#include "editors/dap/debug_session.h"
#include "editors/dap/frame_evaluator.h"
#include "editors/protocol/message_stream.h"
#include "interpreter/ast/ast.h"
#include "interpreter/project/task_runner.h"
#include "interpreter/sema/checker.h"
#include "interpreter/source/source_set.h"
#include "runtime/stimulus.h"

namespace strun::editors::dap {

class DapServer {
public:
    DapServer(std::FILE* in, std::FILE* out);
    ~DapServer();
    int run();

private:
    using json = nlohmann::json;
    json dispatch(const std::string& command, const json& args, bool& ok, std::string& error);
    json initialize(const json& args);
    bool launch(const json& args, std::string& error);
    void startRun();
    json setBreakpoints(const json& args);
    json stackTrace(const json& args);
    json scopes(const json& args, bool& ok, std::string& error);
    json variables(const json& args, bool& ok, std::string& error);
    json evaluate(const json& args, bool& ok, std::string& error);
    json setVariable(const json& args, bool& ok, std::string& error);
    void endRun();

    void event(const std::string& name, json body);
    void respond(const json& request, bool ok, json body, const std::string& message);

    // Variables shown while stopped: a scope's list or an aggregate's members.
    struct Shown {
        std::string name;
        std::string evaluateName;
        const sema::Type* type = nullptr;
        uint8_t* address = nullptr;
        int bit = -1;
        bool writable = true;
    };
    struct Container {
        std::vector<Shown> items;
        std::shared_ptr<std::vector<uint8_t>> owned;  // an evaluated aggregate's copy
    };
    int addContainer(Container c);
    json variableJson(const Shown& v);
    bool frameOf(int frameId, int& task, FrameRecord& frame) const;
    int fileOfSourcePath(const std::string& path) const;
    void noteStopped();

    MessageReader reader_;
    MessageWriter writer_;
    int seq_ = 1;
    std::mutex seqMutex_;
    bool linesStartAt1_ = true;
    bool columnsStartAt1_ = true;

    // The launched project.
    cli::CommandLine line_;
    SourceSet sources_;
    std::vector<int> userFiles_;
    std::vector<ast::CompilationUnit> units_;
    CompileLog log_;
    std::unique_ptr<sema::ProgramModel> model_;
    std::unique_ptr<sema::Checker> checker_;
    std::unique_ptr<FrameEvaluator> evaluator_;
    std::mutex evaluatorMutex_;
    std::vector<std::unique_ptr<project::TaskRunner>> runners_;
    std::unique_ptr<DebugSession> session_;
    rt::Stimulus stimulus_;
    rt::RunOptions runOptions_;
    // --force, --serve, --paused: the live control plane (cli/live_options.h), as under `run`.
    std::unique_ptr<cli::LiveSession> live_;
    bool reportHeldPause_ = false;  // a pause request found the run held by the control plane
    bool launched_ = false;
    bool configured_ = false;
    bool stopOnEntry_ = false;
    std::thread runThread_;
    std::atomic<bool> runEnded_{false};
    // Statement lines of each POU, in the user's file: (file) -> [(first, last, lines)].
    struct PouLines {
        int first = 0, last = 0;
        std::vector<int> lines;
    };
    std::map<int, std::vector<PouLines>> statementLines_;
    // Breakpoints asked for before launch, by path.
    std::map<std::string, json> pendingBreakpoints_;
    int nextBreakpointId_ = 1;
    std::map<int, Container> containers_;
    int nextContainer_ = 1;
    int containersEpoch_ = -1;
};

}  // namespace strun::editors::dap
