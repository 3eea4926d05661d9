// The run options of a live run (docs/live.md): --force, --paused, --serve,
// --serve-token, and the session that holds the control plane
// (live/control_plane.h) and its front ends while the run lasts.
// run_command.cpp calls these in a few lines; other front ends (Modbus)
// add their options to the run command next to these and get the control
// plane from the session.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "cli/cli11_fwd.h"
#include <nlohmann/json.hpp>

#include "interpreter/sema/program_model.h"
#include "runtime/scheduler.h"

namespace strun::live {
class ControlPlane;
class HttpServer;
class LiveHttpApi;
}

namespace strun::cli {

struct LiveOptions {
    std::vector<std::string> forces;  // --force NAME=VALUE, in the order given
    bool paused = false;              // --paused
    std::string serve;                // --serve [ADDR:]PORT ("" = none)
    std::string serveToken;           // --serve-token TOKEN
    // True when any option needs the control plane.
    bool modbus = false;              // --modbus or --modbus-client (cli/modbus_options.h) use the plane
    bool debugger = false;            // strun debug: the debugger is a front end of the plane (and can resume --paused)
    bool any() const { return !forces.empty() || paused || !serve.empty() || !serveToken.empty() || modbus || debugger; }
};

void addLiveOptions(CLI::App& run, LiveOptions& options);

// The control plane and its front ends for one run.
class LiveSession {
public:
    // Null (and no error) when no live option was given: the run then has
    // no control plane at all. Null with `error` (exit 2) for a bad option:
    // a --force that --set would refuse, --paused without a front end, a
    // --serve address that is not loopback without --serve-token, a port
    // that cannot be bound. On success `run.live` points at the control plane.
    static std::unique_ptr<LiveSession> start(const LiveOptions& options, sema::ProgramModel& model, const rt::PlcProfile& profile,
                                              const std::vector<rt::TaskSpec>& specs, const std::string& stepTask,
                                              rt::RunOptions& run, std::string& error);
    ~LiveSession();

    live::ControlPlane& control() { return *control_; }
    // After Scheduler::run(): the final snapshot, then the front ends stop.
    void runEnded(const rt::Scheduler& scheduler);
    // The summary's line of active forces (nothing when none).
    void printForces(std::ostream& out) const;
    nlohmann::ordered_json forcesJson() const;

private:
    LiveSession() = default;
    bool serve(const LiveOptions& options, std::string& error);
    std::unique_ptr<live::ControlPlane> control_;
    std::unique_ptr<live::LiveHttpApi> api_;
    std::unique_ptr<live::HttpServer> server_;
};

}  // namespace strun::cli
