// The HTTP API of --serve (shared/contract "`--serve` and `--paused`",
// docs/live.md): requests mapped onto the control plane. Transport-free
// (live/http_server.h carries it), so each request can be tested directly.
//
//   GET  /                       the monitor page (live/web/, embedded at build time)
//   GET  /api/state              {"state","paused","time","tasks","forces","diagnostics"}
//   GET  /api/vars?watch=P       {"time","values":{PATH: VALUE}}
//   POST /api/write|force        {"name","value"}            -> {"ok": true}
//   POST /api/unforce            {"name"} or {"all": true}   -> {"ok": true}
//   POST /api/pause|resume                                   -> {"ok": true}
//   POST /api/step               {"task","cycles"}           -> the state once paused again
//   GET  /api/events?watch=P&every=D   Server-Sent Events
// Additions for the page (documented in docs/live.md):
//   GET  /api/variables          [{"path","type","writable"}...] every elementary variable
//   GET  /api/timeline?since=N   task switches: {"next","time","tasks","events":[[i,t_ns,task,running]...]}
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "live/control_plane.h"
#include "live/http_server.h"

namespace strun::live {

class LiveHttpApi {
public:
    // `token`: "" = none required; else every /api/ request must carry
    // `Authorization: Bearer TOKEN`.
    LiveHttpApi(ControlPlane& control, std::string token);

    HttpResponse handle(const HttpRequest& request);

    // The bodies of GET /api/state and GET /api/vars (also used by SSE and step).
    nlohmann::ordered_json stateJson();
    nlohmann::ordered_json varsJson(const std::vector<std::string>& patterns);

    // Ends every event stream (the server is stopping).
    void shutdown() { shutdown_.store(true); }

private:
    HttpResponse post(const std::string& path, const HttpRequest& request);
    HttpResponse events(const HttpRequest& request);
    HttpResponse variablesList();
    HttpResponse timelineJson(const HttpRequest& request);
    bool authorized(const HttpRequest& request) const;

    ControlPlane& control_;
    std::string token_;
    std::atomic<bool> shutdown_{false};
};

// A JSON answer: {"error": message} with `status`, or any JSON with 200.
HttpResponse jsonResponse(int status, const nlohmann::ordered_json& body);
HttpResponse errorResponse(int status, const std::string& message);

}  // namespace strun::live
