#include "live/http_api.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

#include "interpreter/project/dump_json.h"
#include "interpreter/project/vcd_signals.h"
#include "live/web_page.h"
#include "stdlib/time_literals.h"
#include "stdlib/value_format.h"

namespace strun::live {

using json = nlohmann::ordered_json;

namespace {

// How long POST /api/step waits for the PLC to pause again before it
// answers with the state as it is (paused: false).
constexpr auto kStepWait = std::chrono::seconds(30);
// Server-Sent Events: bounds of `every`, and a comment line this often so
// that a vanished client is noticed.
constexpr int64_t kMinEvery = 10'000'000;       // 10 ms
constexpr int64_t kMaxEvery = 60'000'000'000;   // 1 min
constexpr int64_t kDefaultEvery = 100'000'000;  // 100 ms
constexpr auto kKeepAlive = std::chrono::seconds(10);
// GET /api/timeline answers at most this many events.
constexpr uint64_t kTimelineAnswer = 20000;

std::string dumpJson(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

bool startsWithIgnoreCase(std::string_view text, std::string_view prefix) {
    return text.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), text.begin(), [](char a, char b) {
               return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
           });
}

// A JSON "value" as ST literal text: a string as it is, numbers and booleans written out.
bool literalText(const json& value, std::string& out) {
    if (value.is_string()) out = value.get<std::string>();
    else if (value.is_boolean()) out = value.get<bool>() ? "TRUE" : "FALSE";
    else if (value.is_number_integer() || value.is_number_unsigned()) out = value.dump();
    else if (value.is_number_float()) {
        double d = value.get<double>();
        if (!std::isfinite(d)) return false;
        out = value.dump();
        if (out.find_first_of(".eE") == std::string::npos) out += ".0";
    } else {
        return false;
    }
    return true;
}

// Constant-time comparison, so the token cannot be guessed byte by byte from timing.
bool sameSecret(std::string_view a, std::string_view b) {
    unsigned diff = unsigned(a.size() ^ b.size());
    for (size_t i = 0; i < a.size(); ++i) diff |= unsigned(uint8_t(a[i]) ^ uint8_t(b.empty() ? 0 : b[i % b.size()]));
    return diff == 0;
}

std::vector<size_t> matching(const ControlPlane& control, const std::vector<std::string>& patterns) {
    std::vector<size_t> out;
    const auto& vars = control.variables();
    for (size_t i = 0; i < vars.size(); ++i) {
        bool take = patterns.empty();
        for (const std::string& p : patterns)
            if (project::matchesPattern(p, vars[i].path)) {
                take = true;
                break;
            }
        if (take) out.push_back(i);
    }
    return out;
}

}  // namespace

HttpResponse jsonResponse(int status, const json& body) {
    HttpResponse r;
    r.status = status;
    r.body = dumpJson(body);
    return r;
}

HttpResponse errorResponse(int status, const std::string& message) { return jsonResponse(status, json{{"error", message}}); }

LiveHttpApi::LiveHttpApi(ControlPlane& control, std::string token) : control_(control), token_(std::move(token)) {}

bool LiveHttpApi::authorized(const HttpRequest& request) const {
    if (token_.empty()) return true;
    const std::string* auth = request.header("authorization");
    if (!auth || !startsWithIgnoreCase(*auth, "Bearer ")) return false;
    std::string_view given(*auth);
    given.remove_prefix(7);
    while (!given.empty() && given.front() == ' ') given.remove_prefix(1);
    return sameSecret(given, token_);
}

json LiveHttpApi::stateJson() {
    std::shared_ptr<const Snapshot> snap = control_.latest();
    json out;
    out["state"] = rt::plcStateName(snap->state);
    out["paused"] = control_.paused() && !snap->ended;
    out["time"] = stdlib::formatDuration(snap->time);
    out["tasks"] = rt::taskStatsJson(control_.tasks(), snap->tasks);
    out["forces"] = control_.forcesJson();
    uint64_t dropped = 0;
    out["diagnostics"] = rt::diagnosticsJson(control_.diagnostics(&dropped), control_.sourceFiles());
    out["diagnostics_dropped"] = dropped;
    out["ended"] = snap->ended;
    out["cycle"] = snap->sequence;
    return out;
}

json LiveHttpApi::varsJson(const std::vector<std::string>& patterns) {
    std::shared_ptr<const Snapshot> snap = control_.latest();
    json values = json::object();
    for (size_t i : matching(control_, patterns)) {
        const LiveVariable& var = control_.variables()[i];
        project::appendMember(values, var.path, ControlPlane::valueJson(*snap, var));
    }
    json out;
    out["time"] = stdlib::formatDuration(snap->time);
    out["values"] = std::move(values);
    return out;
}

HttpResponse LiveHttpApi::handle(const HttpRequest& request) {
    const std::string& path = request.path;
    const bool get = request.method == "GET" || request.method == "HEAD";
    if (path == "/" || path == "/index.html") {
        if (!get) return errorResponse(405, "use GET");
        HttpResponse page;
        page.contentType = "text/html; charset=utf-8";
        page.body = std::string(monitorPage());
        // Everything the page needs is in it: nothing may come from elsewhere.
        page.headers.emplace_back("Content-Security-Policy",
                                  "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
                                  "connect-src 'self'; img-src 'self' data:; base-uri 'none'; form-action 'none'");
        page.headers.emplace_back("Referrer-Policy", "no-referrer");
        return page;
    }
    static const char* const kGets[] = {"/api/state", "/api/vars", "/api/events", "/api/variables", "/api/timeline"};
    static const char* const kPosts[] = {"/api/write", "/api/force", "/api/unforce", "/api/pause", "/api/resume", "/api/step"};
    bool isGet = std::any_of(std::begin(kGets), std::end(kGets), [&](const char* p) { return path == p; });
    bool isPost = std::any_of(std::begin(kPosts), std::end(kPosts), [&](const char* p) { return path == p; });
    if (!isGet && !isPost) return errorResponse(404, "no such path");
    if (!authorized(request)) {
        HttpResponse r = errorResponse(401, "this server needs Authorization: Bearer TOKEN (--serve-token)");
        r.headers.emplace_back("WWW-Authenticate", "Bearer");
        return r;
    }
    if (isPost) {
        if (request.method != "POST") return errorResponse(405, "use POST");
        const std::string* type = request.header("content-type");
        if (!type || !startsWithIgnoreCase(*type, "application/json")) return errorResponse(415, "a POST must carry Content-Type: application/json");
        return post(path, request);
    }
    if (!get) return errorResponse(405, "use GET");
    if (path == "/api/state") return jsonResponse(200, stateJson());
    if (path == "/api/vars") return jsonResponse(200, varsJson(request.queryValues("watch")));
    if (path == "/api/variables") return variablesList();
    if (path == "/api/timeline") return timelineJson(request);
    return events(request);
}

HttpResponse LiveHttpApi::post(const std::string& path, const HttpRequest& request) {
    json body = request.body.empty() ? json::object() : json::parse(request.body, nullptr, false);
    if (body.is_discarded()) return errorResponse(400, "the body is not valid JSON (UTF-8)");
    if (!body.is_object()) return errorResponse(400, "the body must be a JSON object");
    std::string error;
    if (path == "/api/pause") {
        control_.pause();
        return jsonResponse(200, json{{"ok", true}});
    }
    if (path == "/api/resume") {
        control_.resume();
        return jsonResponse(200, json{{"ok", true}});
    }
    if (path == "/api/step") {
        std::string task;
        uint64_t cycles = 1;
        if (body.contains("task") && !body["task"].is_null()) {
            if (!body["task"].is_string()) return errorResponse(400, "\"task\" must be a task's name");
            task = body["task"].get<std::string>();
        }
        if (body.contains("cycles") && !body["cycles"].is_null()) {
            const json& c = body["cycles"];
            if (c.is_number_unsigned() || (c.is_number_integer() && c.get<int64_t>() > 0)) cycles = c.get<uint64_t>();
            else return errorResponse(400, "\"cycles\" must be a whole number of at least 1");
        }
        if (!control_.startStep(task, cycles, error)) return errorResponse(400, error);
        control_.waitUntilPaused(std::chrono::duration_cast<std::chrono::milliseconds>(kStepWait));
        return jsonResponse(200, stateJson());
    }
    if (path == "/api/unforce" && body.contains("all")) {
        if (!body["all"].is_boolean()) return errorResponse(400, "\"all\" must be true or false");
        if (body["all"].get<bool>()) {
            control_.unforceAll();
            return jsonResponse(200, json{{"ok", true}});
        }
    }
    if (!body.contains("name") || !body["name"].is_string()) return errorResponse(400, "\"name\" (a string) is missing");
    std::string name = body["name"].get<std::string>();
    if (path == "/api/unforce") {
        if (!control_.unforce(name, error)) return errorResponse(400, error);
        return jsonResponse(200, json{{"ok", true}});
    }
    std::string literal;
    if (!body.contains("value") || !literalText(body["value"], literal))
        return errorResponse(400, "\"value\" (an ST literal as a string, a number or a boolean) is missing");
    bool ok = path == "/api/write" ? control_.write(name, literal, error) : control_.force(name, literal, error);
    if (!ok) return errorResponse(400, error);
    return jsonResponse(200, json{{"ok", true}});
}

HttpResponse LiveHttpApi::variablesList() {
    json list = json::array();
    for (const LiveVariable& v : control_.variables()) {
        json e;
        e["path"] = v.path;
        e["type"] = v.bit >= 0 ? std::string("BOOL") : v.type->name;
        list.push_back(std::move(e));
    }
    return jsonResponse(200, list);
}

HttpResponse LiveHttpApi::timelineJson(const HttpRequest& request) {
    uint64_t since = 0;
    for (const std::string& s : request.queryValues("since")) {
        if (s.empty() || s.size() > 19 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
            return errorResponse(400, "\"since\" must be a whole number");
        since = std::stoull(s);
    }
    uint64_t next = control_.timelineNext();
    if (next > kTimelineAnswer) since = std::max(since, next - kTimelineAnswer);
    json events = json::array();
    for (const TimelineEvent& e : control_.timeline(since)) events.push_back(json::array({e.index, e.time, e.task, e.running}));
    json tasks = json::array();
    for (const rt::TaskSpec& t : control_.tasks()) tasks.push_back(t.name);
    std::shared_ptr<const Snapshot> snap = control_.latest();
    json out;
    out["next"] = next;
    out["time_ns"] = snap->time;
    out["tasks"] = std::move(tasks);
    out["events"] = std::move(events);
    return jsonResponse(200, out);
}

// Server-Sent Events: the values that changed since the previous event, at
// most one event every `every` of real time; an `event: state` whenever the
// state or the pause changes.
HttpResponse LiveHttpApi::events(const HttpRequest& request) {
    int64_t every = kDefaultEvery;
    for (const std::string& text : request.queryValues("every")) {
        auto parsed = stdlib::parseDurationLiteral(text);
        if (!parsed || parsed.value() < 0) return errorResponse(400, "\"every\" must be a duration (e.g. 100ms, T#1s)");
        every = std::clamp<int64_t>(parsed.value(), kMinEvery, kMaxEvery);
    }
    std::vector<size_t> watched = matching(control_, request.queryValues("watch"));
    HttpResponse r;
    r.contentType = "text/event-stream";
    r.stream = [this, watched = std::move(watched), every](const std::function<bool(std::string_view)>& send) {
        std::shared_ptr<const Snapshot> previous;
        // The state as the stream starts is no change: the first event is
        // the values (GET /api/state has the state).
        std::string lastState = dumpJson(json{{"state", rt::plcStateName(control_.latest()->state)},
                                              {"paused", control_.paused() && !control_.latest()->ended}});
        auto lastSent = std::chrono::steady_clock::now();
        std::string chunk;
        for (;;) {
            std::shared_ptr<const Snapshot> snap = control_.latest();
            json state{{"state", rt::plcStateName(snap->state)}, {"paused", control_.paused() && !snap->ended}};
            std::string stateText = dumpJson(state);
            chunk.clear();
            std::string stateEvent;
            if (stateText != lastState) {
                stateEvent = "event: state\ndata: " + stateText + "\n\n";
                lastState = stateText;
            }
            if (!previous || snap->sequence != previous->sequence) {
                json values = json::object();
                const auto& vars = control_.variables();
                for (size_t i : watched) {
                    const LiveVariable& v = vars[i];
                    if (previous) {
                        const uint8_t* a = previous->data.data() + v.offset;
                        const uint8_t* b = snap->data.data() + v.offset;
                        bool same = v.bit >= 0 ? ((*a ^ *b) >> v.bit & 1) == 0 : std::memcmp(a, b, v.size) == 0;
                        if (same) continue;
                    }
                    project::appendMember(values, v.path, ControlPlane::valueJson(*snap, v));
                }
                if (!previous || !values.empty()) {
                    json event{{"time", stdlib::formatDuration(snap->time)}, {"values", std::move(values)}};
                    chunk += "data: " + dumpJson(event) + "\n\n";
                }
                previous = snap;
            }
            chunk += stateEvent;
            auto now = std::chrono::steady_clock::now();
            if (chunk.empty() && now - lastSent >= kKeepAlive) chunk = ": keep-alive\n\n";
            if (!chunk.empty()) {
                if (!send(chunk)) return;
                lastSent = now;
            }
            if (snap->ended || shutdown_.load()) return;
            // The next event no sooner than `every` of real time; state changes wait as long.
            auto until = now + std::chrono::nanoseconds(every);
            while (std::chrono::steady_clock::now() < until && !shutdown_.load() && !control_.ended())
                std::this_thread::sleep_for(std::min<std::chrono::nanoseconds>(until - std::chrono::steady_clock::now(),
                                                                               std::chrono::milliseconds(50)));
        }
    };
    return r;
}

}  // namespace strun::live
