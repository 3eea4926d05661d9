// A small HTTP/1.1 server for --serve, bounded against hostile clients
// (docs/decisions/0170-own-http-server.md says why it is not cpp-httplib):
//  - at most Limits::maxConnections open connections; when full, the one
//    that has waited longest without completing a request is dropped for
//    the newcomer (a slowloris only loses its own connections), else the
//    newcomer gets 503;
//  - a request head (request line and headers) of at most maxHead bytes
//    and maxHeaders lines, received within headTimeout; a body of at most
//    maxBody bytes (Content-Length only; 413 beyond) within bodyTimeout;
//  - every write must make progress within writeTimeout, else the
//    connection is closed (a client that does not read only loses its own
//    answers);
//  - keep-alive up to maxRequestsPerConnection requests, idle at most idleTimeout.
// One thread accepts; each connection has a thread of its own. Handlers
// run on the connection's thread. Nothing here knows about the PLC.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

namespace strun::live {

struct HttpRequest {
    std::string method;  // "GET", "POST", ...
    std::string path;    // percent-decoded, without the query
    std::vector<std::pair<std::string, std::string>> query;    // decoded, in order (names may repeat)
    std::vector<std::pair<std::string, std::string>> headers;  // names in lower case
    std::string body;
    std::string peer;  // client address

    const std::string* header(std::string_view lowerName) const;
    std::vector<std::string> queryValues(std::string_view name) const;
};

struct HttpResponse {
    int status = 200;
    std::string contentType = "application/json";
    std::string body;
    std::vector<std::pair<std::string, std::string>> headers;  // extra headers
    // Set for a streamed answer (Server-Sent Events): after the head the
    // server calls it with a sender until it returns false; the sender
    // returns false once the client is gone or too slow.
    std::function<void(const std::function<bool(std::string_view)>& send)> stream;
};

class HttpServer {
public:
    struct Limits {
        size_t maxConnections = 128;
        size_t maxHead = 16 * 1024;
        size_t maxHeaders = 64;
        size_t maxBody = 64 * 1024;
        size_t maxRequestsPerConnection = 1000;
        std::chrono::milliseconds headTimeout{5000};
        std::chrono::milliseconds bodyTimeout{5000};
        std::chrono::milliseconds idleTimeout{15000};
        std::chrono::milliseconds writeTimeout{5000};
    };
    using Handler = std::function<HttpResponse(const HttpRequest&)>;

    HttpServer(Handler handler, Limits limits);
    HttpServer() : HttpServer(nullptr, Limits{}) {}
    ~HttpServer();
    HttpServer(const HttpServer&) = delete;
    HttpServer& operator=(const HttpServer&) = delete;

    // Binds and listens (port 0: any free port). False with `error`.
    bool listen(const std::string& host, int port, std::string& error);
    int port() const { return port_; }
    // Accepts on a thread of its own until stop().
    void start();
    // Closes every connection (streams end), joins every thread.
    void stop();
    bool stopping() const { return stopping_.load(std::memory_order_acquire); }
    size_t openConnections() const;

private:
    struct Connection {
        int fd = -1;
        std::string peer;
        std::thread thread;
        std::atomic<bool> waiting{true};  // no request in progress (reading a head, or idle)
        std::atomic<int64_t> since{0};   // steady-clock ticks: when it started waiting
        std::atomic<bool> done{false};
    };
    void acceptLoop();
    void serve(Connection& c);
    void reap(bool all);
    bool evictOneWaiting();

    Handler handler_;
    Limits limits_;
    int listenFd_ = -1;
    int wakeRead_ = -1, wakeWrite_ = -1;
    int port_ = 0;
    std::thread acceptor_;
    std::atomic<bool> stopping_{false};
    mutable std::mutex connectionsMutex_;
    std::list<std::unique_ptr<Connection>> connections_;
};

// "%41b" -> "Ab"; `plusIsSpace` for query strings. Invalid escapes stay as they are.
std::string percentDecode(std::string_view text, bool plusIsSpace);

}  // namespace strun::live
