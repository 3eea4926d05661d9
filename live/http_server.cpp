#include "live/http_server.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace strun::live {

namespace {

using Clock = std::chrono::steady_clock;

// Waits until `fd` is ready for `events` or `deadline` passes (or `stop`).
bool waitFor(int fd, short events, Clock::time_point deadline, const std::atomic<bool>& stop) {
    for (;;) {
        if (stop.load(std::memory_order_acquire)) return false;
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) return false;
        pollfd p{fd, events, 0};
        // Wake up now and then to notice stop() even when shutdown() did not reach this fd.
        int n = ::poll(&p, 1, int(std::min<long long>(left, 200)));
        if (n < 0 && errno != EINTR) return false;
        if (n > 0) return (p.revents & (events | POLLHUP | POLLERR)) != 0;
    }
}

// Reads what is there (at most `max` bytes) into `out`; false on EOF, error or deadline.
bool readSome(int fd, std::string& out, size_t max, Clock::time_point deadline, const std::atomic<bool>& stop) {
    if (!waitFor(fd, POLLIN, deadline, stop)) return false;
    char buf[4096];
    ssize_t n = ::recv(fd, buf, std::min(sizeof buf, max), 0);
    if (n <= 0) return false;
    out.append(buf, size_t(n));
    return true;
}

bool writeAll(int fd, std::string_view data, std::chrono::milliseconds timeout, const std::atomic<bool>& stop) {
    while (!data.empty()) {
        // Each chunk must go out within the timeout: a client that stops reading is dropped.
        if (!waitFor(fd, POLLOUT, Clock::now() + timeout, stop)) return false;
        ssize_t n = ::send(fd, data.data(), data.size(), MSG_NOSIGNAL);
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            return false;
        }
        data.remove_prefix(size_t(n));
    }
    return true;
}

const char* reason(int status) {
    switch (status) {
    case 200: return "OK";
    case 204: return "No Content";
    case 400: return "Bad Request";
    case 401: return "Unauthorized";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 408: return "Request Timeout";
    case 411: return "Length Required";
    case 413: return "Payload Too Large";
    case 415: return "Unsupported Media Type";
    case 431: return "Request Header Fields Too Large";
    case 500: return "Internal Server Error";
    case 501: return "Not Implemented";
    case 503: return "Service Unavailable";
    case 505: return "HTTP Version Not Supported";
    }
    return "Unknown";
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::string head(int status, std::string_view contentType, size_t length, bool keepAlive,
                 const std::vector<std::pair<std::string, std::string>>& extra, bool streamed) {
    std::string h = "HTTP/1.1 " + std::to_string(status) + " " + reason(status) + "\r\n";
    h += "Content-Type: " + std::string(contentType) + "\r\n";
    if (!streamed) h += "Content-Length: " + std::to_string(length) + "\r\n";
    h += "Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n";
    for (const auto& [name, value] : extra) h += name + ": " + value + "\r\n";
    h += keepAlive ? "Connection: keep-alive\r\n\r\n" : "Connection: close\r\n\r\n";
    return h;
}

std::string errorBody(std::string_view message) {
    // A JSON string without a JSON library: the messages here are plain ASCII.
    return "{\"error\": \"" + std::string(message) + "\"}";
}

bool validToken(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && !std::strchr("!#$%&'*+-.^_`|~", c)) return false;
    return true;
}

}  // namespace

std::string percentDecode(std::string_view text, bool plusIsSpace) {
    std::string out;
    out.reserve(text.size());
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '%' && i + 2 < text.size() && hex(text[i + 1]) >= 0 && hex(text[i + 2]) >= 0) {
            out += char(hex(text[i + 1]) * 16 + hex(text[i + 2]));
            i += 2;
        } else if (c == '+' && plusIsSpace) {
            out += ' ';
        } else {
            out += c;
        }
    }
    return out;
}

const std::string* HttpRequest::header(std::string_view lowerName) const {
    for (const auto& [name, value] : headers)
        if (name == lowerName) return &value;
    return nullptr;
}

std::vector<std::string> HttpRequest::queryValues(std::string_view name) const {
    std::vector<std::string> out;
    for (const auto& [key, value] : query)
        if (key == name) out.push_back(value);
    return out;
}

HttpServer::HttpServer(Handler handler, Limits limits) : handler_(std::move(handler)), limits_(limits) {}

HttpServer::~HttpServer() { stop(); }

bool HttpServer::listen(const std::string& host, int port, std::string& error) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
    addrinfo* found = nullptr;
    std::string service = std::to_string(port);
    if (int rc = ::getaddrinfo(host.c_str(), service.c_str(), &hints, &found); rc != 0) {
        error = "cannot use the address '" + host + "': " + gai_strerror(rc);
        return false;
    }
    error.clear();
    for (addrinfo* a = found; a; a = a->ai_next) {
        int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
        if (fd < 0) continue;
        int one = 1;
        ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
        if (::bind(fd, a->ai_addr, a->ai_addrlen) == 0 && ::listen(fd, 256) == 0) {
            listenFd_ = fd;
            sockaddr_storage bound{};
            socklen_t len = sizeof bound;
            ::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &len);
            port_ = bound.ss_family == AF_INET6 ? ntohs(reinterpret_cast<sockaddr_in6*>(&bound)->sin6_port)
                                                : ntohs(reinterpret_cast<sockaddr_in*>(&bound)->sin_port);
            break;
        }
        error = std::strerror(errno);
        ::close(fd);
    }
    ::freeaddrinfo(found);
    if (listenFd_ < 0) {
        error = "cannot listen on " + host + ":" + std::to_string(port) + (error.empty() ? "" : ": " + error);
        return false;
    }
    int pipeFds[2];
    if (::pipe2(pipeFds, O_CLOEXEC | O_NONBLOCK) != 0) {
        error = std::string("pipe: ") + std::strerror(errno);
        return false;
    }
    wakeRead_ = pipeFds[0];
    wakeWrite_ = pipeFds[1];
    return true;
}

void HttpServer::start() { acceptor_ = std::thread([this] { acceptLoop(); }); }

size_t HttpServer::openConnections() const {
    std::lock_guard<std::mutex> lock(connectionsMutex_);
    size_t n = 0;
    for (const auto& c : connections_) n += !c->done.load();
    return n;
}

// Joins the threads of finished connections (all of them when `all`).
void HttpServer::reap(bool all) {
    std::list<std::unique_ptr<Connection>> finished;
    {
        std::lock_guard<std::mutex> lock(connectionsMutex_);
        for (auto it = connections_.begin(); it != connections_.end();) {
            if (all || (*it)->done.load()) {
                finished.push_back(std::move(*it));
                it = connections_.erase(it);
            } else {
                ++it;
            }
        }
    }
    for (auto& c : finished) {
        if (c->thread.joinable()) c->thread.join();
        ::close(c->fd);
    }
}

// The connection that has waited longest for a complete request is shut
// down to make room. Under connectionsMutex_.
bool HttpServer::evictOneWaiting() {
    Connection* oldest = nullptr;
    for (auto& c : connections_)
        if (!c->done.load() && c->waiting.load() && (!oldest || c->since.load() < oldest->since.load())) oldest = c.get();
    if (!oldest) return false;
    ::shutdown(oldest->fd, SHUT_RDWR);
    oldest->waiting.store(false);  // not evicted twice
    return true;
}

void HttpServer::acceptLoop() {
    while (!stopping()) {
        pollfd fds[2] = {{listenFd_, POLLIN, 0}, {wakeRead_, POLLIN, 0}};
        int n = ::poll(fds, 2, 1000);
        reap(false);
        if (n <= 0 || stopping()) continue;
        if (!(fds[0].revents & POLLIN)) continue;
        sockaddr_storage from{};
        socklen_t len = sizeof from;
        int fd = ::accept4(listenFd_, reinterpret_cast<sockaddr*>(&from), &len, SOCK_CLOEXEC);
        if (fd < 0) {
            // Out of descriptors (EMFILE): let the others finish before accepting more.
            if (errno == EMFILE || errno == ENFILE) std::this_thread::sleep_for(std::chrono::milliseconds(10));
            continue;
        }
        int one = 1;
        ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
        char host[INET6_ADDRSTRLEN] = "";
        if (from.ss_family == AF_INET) ::inet_ntop(AF_INET, &reinterpret_cast<sockaddr_in*>(&from)->sin_addr, host, sizeof host);
        else if (from.ss_family == AF_INET6) ::inet_ntop(AF_INET6, &reinterpret_cast<sockaddr_in6*>(&from)->sin6_addr, host, sizeof host);

        std::lock_guard<std::mutex> lock(connectionsMutex_);
        size_t open = 0;
        for (const auto& c : connections_) open += !c->done.load();
        if (open >= limits_.maxConnections && !evictOneWaiting()) {
            // Every connection is busy with a request: this one is refused.
            std::string refusal = head(503, "application/json", 0, false, {}, false);
            std::string body = errorBody("too many connections");
            refusal.replace(refusal.find("Content-Length: 0"), 17, "Content-Length: " + std::to_string(body.size()));
            ::send(fd, (refusal + body).data(), refusal.size() + body.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
            ::close(fd);
            continue;
        }
        auto c = std::make_unique<Connection>();
        c->fd = fd;
        c->peer = host;
        c->since.store(Clock::now().time_since_epoch().count());
        Connection* raw = c.get();
        connections_.push_back(std::move(c));
        raw->thread = std::thread([this, raw] {
            serve(*raw);
            // Closed by reap() after the join: until then the number cannot be
            // reused by another connection that evictOneWaiting() might shut down.
            ::shutdown(raw->fd, SHUT_RDWR);
            raw->done.store(true);
        });
    }
}

void HttpServer::serve(Connection& c) {
    std::string buffer;  // received and not yet used
    for (size_t served = 0; served < limits_.maxRequestsPerConnection && !stopping(); ++served) {
        c.since.store(Clock::now().time_since_epoch().count());
        c.waiting.store(true);
        auto reply = [&](int status, std::string_view message) {
            std::string body = errorBody(message);
            std::string out = head(status, "application/json", body.size(), false, {}, false) + body;
            writeAll(c.fd, out, limits_.writeTimeout, stopping_);
        };
        // ---- the head: request line and headers
        size_t end = std::string::npos;
        size_t sepLen = 4;
        Clock::time_point deadline = Clock::now() + (served == 0 ? limits_.headTimeout : limits_.idleTimeout);
        bool started = !buffer.empty();
        for (;;) {
            end = buffer.find("\r\n\r\n");
            if (end == std::string::npos) {
                end = buffer.find("\n\n");
                sepLen = 2;
            } else {
                sepLen = 4;
            }
            if (end != std::string::npos) break;
            if (buffer.size() > limits_.maxHead) {
                reply(431, "the request head is larger than 16 KiB");
                return;
            }
            if (!readSome(c.fd, buffer, limits_.maxHead + 1 - buffer.size(), deadline, stopping_)) {
                if (!buffer.empty() && Clock::now() >= deadline) reply(408, "the request took too long");
                return;
            }
            if (!started) {
                // An idle keep-alive connection gets headTimeout once its next request begins.
                started = true;
                deadline = std::min(deadline, Clock::now() + limits_.headTimeout);
            }
        }
        if (end > limits_.maxHead) {
            reply(431, "the request head is larger than 16 KiB");
            return;
        }
        std::string_view headText(buffer.data(), end);
        HttpRequest req;
        req.peer = c.peer;
        size_t lineEnd = headText.find('\n');
        std::string_view requestLine = trim(headText.substr(0, lineEnd));
        size_t sp1 = requestLine.find(' ');
        size_t sp2 = sp1 == std::string_view::npos ? sp1 : requestLine.find(' ', sp1 + 1);
        if (sp2 == std::string_view::npos || requestLine.find(' ', sp2 + 1) != std::string_view::npos) {
            reply(400, "malformed request line");
            return;
        }
        req.method = std::string(requestLine.substr(0, sp1));
        std::string_view target = requestLine.substr(sp1 + 1, sp2 - sp1 - 1);
        std::string_view version = requestLine.substr(sp2 + 1);
        if (!validToken(req.method) || target.empty() || target[0] != '/') {
            reply(400, "malformed request line");
            return;
        }
        if (version != "HTTP/1.1" && version != "HTTP/1.0") {
            reply(505, "only HTTP/1.0 and HTTP/1.1");
            return;
        }
        size_t q = target.find('?');
        req.path = percentDecode(target.substr(0, q), false);
        if (q != std::string_view::npos) {
            std::string_view query = target.substr(q + 1);
            while (!query.empty()) {
                size_t amp = query.find('&');
                std::string_view pair = query.substr(0, amp);
                size_t eq = pair.find('=');
                if (!pair.empty())
                    req.query.emplace_back(percentDecode(pair.substr(0, eq), true),
                                           eq == std::string_view::npos ? std::string() : percentDecode(pair.substr(eq + 1), true));
                if (amp == std::string_view::npos) break;
                query.remove_prefix(amp + 1);
            }
        }
        std::string_view rest = lineEnd == std::string_view::npos ? std::string_view() : headText.substr(lineEnd + 1);
        bool badHeader = false;
        while (!rest.empty()) {
            size_t nl = rest.find('\n');
            std::string_view line = trim(rest.substr(0, nl));
            rest = nl == std::string_view::npos ? std::string_view() : rest.substr(nl + 1);
            if (line.empty()) continue;
            size_t colon = line.find(':');
            if (colon == std::string_view::npos || !validToken(line.substr(0, colon))) {
                badHeader = true;
                break;
            }
            if (req.headers.size() >= limits_.maxHeaders) {
                reply(431, "too many header lines");
                return;
            }
            req.headers.emplace_back(lower(line.substr(0, colon)), std::string(trim(line.substr(colon + 1))));
        }
        if (badHeader) {
            reply(400, "malformed header line");
            return;
        }
        buffer.erase(0, end + sepLen);
        c.waiting.store(false);  // a complete head: this connection is busy with a request

        // ---- the body: Content-Length only
        if (req.header("transfer-encoding")) {
            reply(411, "a body needs Content-Length (no chunked transfer)");
            return;
        }
        size_t length = 0;
        if (const std::string* cl = req.header("content-length")) {
            if (cl->empty() || cl->size() > 12 || !std::all_of(cl->begin(), cl->end(), [](char ch) { return ch >= '0' && ch <= '9'; })) {
                reply(400, "malformed Content-Length");
                return;
            }
            length = size_t(std::stoull(*cl));
        }
        if (length > limits_.maxBody) {
            reply(413, "the request body is larger than 64 KiB");
            return;
        }
        Clock::time_point bodyDeadline = Clock::now() + limits_.bodyTimeout;
        while (buffer.size() < length)
            if (!readSome(c.fd, buffer, length - buffer.size(), bodyDeadline, stopping_)) {
                if (Clock::now() >= bodyDeadline) reply(408, "the request body took too long");
                return;
            }
        req.body = buffer.substr(0, length);
        buffer.erase(0, length);

        // ---- answer
        const std::string* connection = req.header("connection");
        bool keepAlive = version == "HTTP/1.1" ? !(connection && lower(*connection) == "close")
                                               : (connection && lower(*connection) == "keep-alive");
        HttpResponse res;
        try {
            res = handler_ ? handler_(req) : HttpResponse{404, "application/json", errorBody("not found"), {}, nullptr};
        } catch (const std::exception&) {
            res = HttpResponse{500, "application/json", errorBody("internal error"), {}, nullptr};
            keepAlive = false;
        }
        if (res.stream) {
            if (!writeAll(c.fd, head(res.status, res.contentType, 0, false, res.headers, true), limits_.writeTimeout, stopping_))
                return;
            res.stream([&](std::string_view chunk) { return !stopping() && writeAll(c.fd, chunk, limits_.writeTimeout, stopping_); });
            return;
        }
        bool bodyless = req.method == "HEAD";
        std::string out = head(res.status, res.contentType, res.body.size(), keepAlive, res.headers, false);
        if (!bodyless) out += res.body;
        if (!writeAll(c.fd, out, limits_.writeTimeout, stopping_) || !keepAlive) return;
    }
}

void HttpServer::stop() {
    if (stopping_.exchange(true)) return;
    if (wakeWrite_ >= 0) {
        char byte = 1;
        [[maybe_unused]] ssize_t ignored = ::write(wakeWrite_, &byte, 1);
    }
    if (acceptor_.joinable()) acceptor_.join();
    {
        std::lock_guard<std::mutex> lock(connectionsMutex_);
        for (auto& c : connections_)
            if (!c->done.load()) ::shutdown(c->fd, SHUT_RDWR);
    }
    reap(true);
    for (int* fd : {&listenFd_, &wakeRead_, &wakeWrite_})
        if (*fd >= 0) {
            ::close(*fd);
            *fd = -1;
        }
}

}  // namespace strun::live
