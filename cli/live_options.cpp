#include "cli/live_options.h"

#include <algorithm>
#include <cctype>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/option_types.h"
#include "cli/run_report.h"
#include "live/control_plane.h"
#include "live/http_api.h"
#include "live/http_server.h"
#include "stdlib/value_format.h"

namespace strun::cli {

namespace {

// [ADDR:]PORT -> host and port ("8080", "127.0.0.1:0", "[::1]:8080", "localhost:8080").
bool parseServeAddress(const std::string& text, std::string& host, int& port, std::string& error) {
    std::string t = trimmed(text);
    std::string portText = t;
    host = "127.0.0.1";
    if (!t.empty() && t[0] == '[') {
        size_t close = t.find("]:");
        if (close == std::string::npos) {
            error = "--serve '" + text + "': expected [ADDR:]PORT (e.g. 8080, 127.0.0.1:8080, [::1]:8080)";
            return false;
        }
        host = t.substr(1, close - 1);
        portText = t.substr(close + 2);
    } else if (size_t colon = t.rfind(':'); colon != std::string::npos) {
        host = t.substr(0, colon);
        portText = t.substr(colon + 1);
    }
    bool digits = !portText.empty() && portText.size() <= 5 &&
                  std::all_of(portText.begin(), portText.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    if (host.empty() || !digits || std::stoi(portText) > 65535) {
        error = "--serve '" + text + "': expected [ADDR:]PORT with a PORT of 0..65535 (0: any free port)";
        return false;
    }
    port = std::stoi(portText);
    return true;
}

bool isLoopback(const std::string& host) {
    return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

}  // namespace

void addLiveOptions(CLI::App& run, LiveOptions& options) {
    run.add_option("--force", options.forces, "hold the ST literal VALUE in a variable or direct address from the start (repeatable)")
        ->type_name("NAME=VALUE")
        ->allow_extra_args(false);
    run.add_flag("--paused", options.paused, "start paused: no task runs until resumed or stepped (with --serve)");
    run.add_option("--serve", options.serve, "serve the live monitor page and its HTTP API on ADDR (default 127.0.0.1) and PORT (0: any)")
        ->type_name("[ADDR:]PORT");
    run.add_option("--serve-token", options.serveToken, "with --serve: every /api/ request must carry Authorization: Bearer TOKEN")
        ->type_name("TOKEN");
}

bool LiveSession::serve(const LiveOptions& options, std::string& error) {
    std::string host;
    int port = 0;
    if (!parseServeAddress(options.serve, host, port, error)) return false;
    if (!isLoopback(host) && options.serveToken.empty()) {
        error = "--serve on " + host + ", which is not a loopback address, needs --serve-token TOKEN";
        return false;
    }
    api_ = std::make_unique<live::LiveHttpApi>(*control_, options.serveToken);
    server_ = std::make_unique<live::HttpServer>([api = api_.get()](const live::HttpRequest& r) { return api->handle(r); },
                                                 live::HttpServer::Limits{});
    std::string why;
    if (!server_->listen(host, port, why)) {
        error = "--serve: " + why;
        return false;
    }
    server_->start();
    std::string shown = host.find(':') != std::string::npos ? "[" + host + "]" : host;
    std::cerr << "strun: serving http://" << shown << ":" << server_->port() << "/" << std::endl;
    return true;
}

std::unique_ptr<LiveSession> LiveSession::start(const LiveOptions& options, sema::ProgramModel& model, const rt::PlcProfile& profile,
                                                const std::vector<rt::TaskSpec>& specs, const std::string& stepTask,
                                                rt::RunOptions& run, std::string& error) {
    if (!options.any()) return nullptr;
    if (options.paused && options.serve.empty() && !options.debugger) {
        error = "--paused needs a front end that can resume the run: give --serve [ADDR:]PORT too";
        return nullptr;
    }
    if (!options.serveToken.empty() && options.serve.empty()) {
        error = "--serve-token needs --serve [ADDR:]PORT";
        return nullptr;
    }
    std::unique_ptr<LiveSession> session(new LiveSession);
    session->control_ = std::make_unique<live::ControlPlane>(model, profile, specs, stepTask);
    for (const std::string& text : options.forces) {
        size_t eq = text.find('=');
        std::string name = eq == std::string::npos ? std::string() : trimmed(text.substr(0, eq));
        std::string value = eq == std::string::npos ? std::string() : trimmed(text.substr(eq + 1));
        if (name.empty() || value.empty()) {
            error = "--force " + text + ": expected NAME=VALUE (e.g. Main.start=TRUE)";
            return nullptr;
        }
        std::string why;
        if (!session->control_->forceAtStart(name, value, why)) {
            error = "--force " + text + ": " + why;
            return nullptr;
        }
    }
    if (options.paused) session->control_->startPaused();
    session->control_->setSourceFiles(run.sourceFiles);
    if (!options.serve.empty() && !session->serve(options, error)) return nullptr;
    run.live = session->control_.get();
    return session;
}

LiveSession::~LiveSession() {
    if (api_) api_->shutdown();
    if (server_) server_->stop();
}

void LiveSession::runEnded(const rt::Scheduler& scheduler) {
    control_->runEnded(scheduler);
    if (api_) api_->shutdown();
    if (server_) server_->stop();
}

nlohmann::ordered_json LiveSession::forcesJson() const { return control_->forcesJson(); }

void LiveSession::printForces(std::ostream& out) const { printForcesLine(out, control_->forcesJson()); }

}  // namespace strun::cli
