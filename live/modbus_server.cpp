#include "live/modbus_server.h"

#include <arpa/inet.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <vector>

#include "live/modbus_map.h"
#include "live/network_thread.h"

namespace strun::live {

namespace {

using Area = rt::DirectAddress::Area;
using Clock = std::chrono::steady_clock;

uint16_t be16(const uint8_t* p) { return uint16_t((p[0] << 8) | p[1]); }

// The four tables a connection answers from: libmodbus's mapping, refilled
// from the published image for each request's range just before it replies.
struct Tables {
    modbus_mapping_t* map = modbus_mapping_new_start_address(0, kServedCoils, 0, kServedDiscreteInputs, 0, kServedHoldingRegisters, 0,
                                                             kServedInputRegisters);
    ~Tables() {
        if (map) modbus_mapping_free(map);
    }

    // Copies [first, first + count) of `table`, clamped to the served range, from one view.
    void fill(const ImageView& v, ModbusTable table, size_t first, size_t count) {
        size_t size = table == ModbusTable::Coils ? kServedCoils
                      : table == ModbusTable::DiscreteInputs ? kServedDiscreteInputs
                      : table == ModbusTable::InputRegisters ? kServedInputRegisters
                                                             : kServedHoldingRegisters;
        if (first >= size) return;
        size_t end = std::min(size, first + count);
        for (size_t n = first; n < end; ++n) {
            rt::DirectAddress a = *servedAddress(table, n);
            switch (table) {
                case ModbusTable::Coils: map->tab_bits[n] = v.bit(a.area, a.byte, a.bit); break;
                case ModbusTable::DiscreteInputs: map->tab_input_bits[n] = v.bit(a.area, a.byte, a.bit); break;
                case ModbusTable::InputRegisters: map->tab_input_registers[n] = v.word(a.area, a.byte); break;
                case ModbusTable::HoldingRegisters: map->tab_registers[n] = v.word(a.area, a.byte); break;
            }
        }
    }
};

// What a request reads (filled before the reply) and what it writes
// (queued after it), from its PDU: function, address, quantity and data.
// Only requests libmodbus answers without an exception write: the checks
// below are the ones modbus_reply makes (quantity limits, table bounds).
struct Request {
    const uint8_t* pdu;  // function code first
    size_t length;       // bytes from the function code on

    uint8_t function() const { return pdu[0]; }
    bool has(size_t bytes) const { return length >= bytes; }
    uint16_t field(size_t offset) const { return has(offset + 2) ? be16(pdu + offset) : 0; }

    // The (table, first, count) a read needs filled; count 0: none.
    struct Range {
        ModbusTable table;
        size_t first, count;
    };
    Range readRange() const {
        switch (function()) {
            case MODBUS_FC_READ_COILS: return {ModbusTable::Coils, field(1), field(3)};
            case MODBUS_FC_READ_DISCRETE_INPUTS: return {ModbusTable::DiscreteInputs, field(1), field(3)};
            case MODBUS_FC_READ_HOLDING_REGISTERS: return {ModbusTable::HoldingRegisters, field(1), field(3)};
            case MODBUS_FC_READ_INPUT_REGISTERS: return {ModbusTable::InputRegisters, field(1), field(3)};
            case MODBUS_FC_WRITE_AND_READ_REGISTERS: return {ModbusTable::HoldingRegisters, field(1), field(3)};
            case MODBUS_FC_MASK_WRITE_REGISTER: return {ModbusTable::HoldingRegisters, field(1), 1};
            default: return {ModbusTable::Coils, 0, 0};
        }
    }

    // The writes an accepted request makes, in item order; the values after
    // the reply are in `map` (mask write computes its own there).
    void writes(const modbus_mapping_t* map, std::vector<ImageWrite>& out) const {
        out.clear();
        auto coils = [&](size_t first, size_t count) {
            if (count < 1 || first + count > kServedCoils) return;
            for (size_t n = first; n < first + count; ++n) out.push_back({*servedAddress(ModbusTable::Coils, n), map->tab_bits[n]});
        };
        auto registers = [&](size_t first, size_t count) {
            if (count < 1 || first + count > kServedHoldingRegisters) return;
            for (size_t n = first; n < first + count; ++n)
                out.push_back({*servedAddress(ModbusTable::HoldingRegisters, n), map->tab_registers[n]});
        };
        switch (function()) {
            case MODBUS_FC_WRITE_SINGLE_COIL:
                if (has(5) && (field(3) == 0xFF00 || field(3) == 0)) coils(field(1), 1);
                break;
            case MODBUS_FC_WRITE_SINGLE_REGISTER:
                if (has(5)) registers(field(1), 1);
                break;
            case MODBUS_FC_WRITE_MULTIPLE_COILS:
                if (has(6) && field(3) <= MODBUS_MAX_WRITE_BITS && has(6 + size_t(pdu[5]))) coils(field(1), field(3));
                break;
            case MODBUS_FC_WRITE_MULTIPLE_REGISTERS:
                if (has(6) && field(3) <= MODBUS_MAX_WRITE_REGISTERS && has(6 + size_t(pdu[5]))) registers(field(1), field(3));
                break;
            case MODBUS_FC_MASK_WRITE_REGISTER:
                if (has(7)) registers(field(1), 1);
                break;
            case MODBUS_FC_WRITE_AND_READ_REGISTERS:
                // read quantity 1..125 and write quantity 1..121, both inside the table
                if (has(10) && field(3) >= 1 && field(3) <= MODBUS_MAX_WR_READ_REGISTERS && field(1) + field(3) <= kServedHoldingRegisters &&
                    field(7) <= MODBUS_MAX_WR_WRITE_REGISTERS && has(10 + size_t(pdu[9])))
                    registers(field(5), field(7));
                break;
            default: break;
        }
    }
};

// A read's quantity is validated by libmodbus: only fill what it could answer.
bool readAccepted(const Request::Range& r) {
    size_t max = (r.table == ModbusTable::Coils || r.table == ModbusTable::DiscreteInputs) ? MODBUS_MAX_READ_BITS : MODBUS_MAX_READ_REGISTERS;
    return r.count >= 1 && r.count <= max;
}

// Reads exactly `n` bytes, each within `timeoutMs` of the previous one.
bool readRest(int fd, uint8_t* into, size_t n, int timeoutMs) {
    while (n > 0) {
        pollfd p{fd, POLLIN, 0};
        if (poll(&p, 1, timeoutMs) <= 0) return false;
        ssize_t got = recv(fd, into, n, 0);
        if (got <= 0) return false;
        into += got;
        n -= size_t(got);
    }
    return true;
}

}  // namespace

struct ModbusServer::Connection {
    int fd = -1;
    std::thread thread;
    std::atomic<bool> done{false};
};

ModbusServer::ModbusServer(ModbusPlc& plc, ModbusServerLimits limits) : plc_(plc), limits_(limits) {}

ModbusServer::~ModbusServer() { stop(); }

bool ModbusServer::listen(const std::string& host, int port, std::string& error) {
    in_addr probe{};
    if (inet_pton(AF_INET, host.c_str(), &probe) != 1) {
        error = "'" + host + "' is not an IPv4 address";
        return false;
    }
    modbus_t* ctx = modbus_new_tcp(host.c_str(), port);
    if (!ctx) {
        error = std::string("cannot create the server: ") + modbus_strerror(errno);
        return false;
    }
    listenFd_ = modbus_tcp_listen(ctx, 64);
    int listenErrno = errno;
    modbus_free(ctx);  // the listening socket outlives the context (only modbus_close would close it)
    if (listenFd_ < 0) {
        error = "cannot listen on " + host + ":" + std::to_string(port) + ": " + modbus_strerror(listenErrno);
        return false;
    }
    sockaddr_in bound{};
    socklen_t len = sizeof bound;
    getsockname(listenFd_, reinterpret_cast<sockaddr*>(&bound), &len);
    port_ = ntohs(bound.sin_port);
    return true;
}

void ModbusServer::start() {
    if (listenFd_ >= 0 && !acceptThread_.joinable()) acceptThread_ = std::thread([this] { acceptLoop(); });
}

void ModbusServer::stop() {
    stopping_ = true;
    if (acceptThread_.joinable()) acceptThread_.join();
    reap(true);
    if (listenFd_ >= 0) close(listenFd_);
    listenFd_ = -1;
}

// Joins finished connection threads (all of them when `all`, after telling them to stop).
void ModbusServer::reap(bool all) {
    std::lock_guard<std::mutex> lock(connectionsMutex_);
    for (auto it = connections_.begin(); it != connections_.end();) {
        Connection& c = **it;
        if (all && !c.done) shutdown(c.fd, SHUT_RDWR);
        if (all || c.done) {
            if (c.thread.joinable()) c.thread.join();
            it = connections_.erase(it);
        } else {
            ++it;
        }
    }
}

void ModbusServer::acceptLoop() {
    lowerThreadPriority();
    while (!stopping_) {
        pollfd p{listenFd_, POLLIN, 0};
        if (poll(&p, 1, 100) <= 0) continue;
        int fd = accept(listenFd_, nullptr, nullptr);
        if (fd < 0) {
            if (errno == EMFILE || errno == ENFILE) std::this_thread::sleep_for(std::chrono::milliseconds(50));
            continue;
        }
        reap(false);
        std::lock_guard<std::mutex> lock(connectionsMutex_);
        if (int(connections_.size()) >= limits_.maxConnections) {
            refused_.fetch_add(1, std::memory_order_relaxed);
            close(fd);  // over the limit: the client sees the connection close at once
            continue;
        }
        auto c = std::make_unique<Connection>();
        c->fd = fd;
        Connection& ref = *c;
        connections_.push_back(std::move(c));
        ref.thread = std::thread([this, &ref] {
            serve(ref);
            ref.done = true;
        });
    }
}

void ModbusServer::serve(Connection& c) {
    lowerThreadPriority();
    modbus_t* ctx = modbus_new_tcp("127.0.0.1", 502);  // the address is unused: the socket is the accepted one
    Tables tables;
    if (!ctx || !tables.map) {
        if (ctx) modbus_free(ctx);
        close(c.fd);
        return;
    }
    modbus_set_socket(ctx, c.fd);
    modbus_set_byte_timeout(ctx, 0, uint32_t(limits_.byteTimeoutMs) * 1000);
    const int header = modbus_get_header_length(ctx);  // the MBAP header (7 bytes)
    std::vector<uint8_t> query(MODBUS_TCP_MAX_ADU_LENGTH);
    std::vector<ImageWrite> writes;
    // Token bucket: `burst` requests at once, then `requestsPerSecond`.
    double tokens = limits_.burst;
    Clock::time_point refilled = Clock::now(), lastRequest = refilled;
    while (!stopping_) {
        pollfd p{c.fd, POLLIN, 0};
        int ready = poll(&p, 1, 200);
        if (ready < 0 && errno != EINTR) break;
        if (ready <= 0) {
            if (Clock::now() - lastRequest > std::chrono::seconds(limits_.idleSeconds)) break;
            continue;
        }
        if (p.revents & (POLLERR | POLLNVAL)) break;
        int rc = modbus_receive(ctx, query.data());
        if (rc < 0) break;   // closed, a frame cut short, too long or not Modbus
        if (rc == 0) continue;  // not for this server (libmodbus filtered it)
        // MBAP: protocol 0 and a length no shorter than what came: anything
        // else is not a frame we can trust. libmodbus reads only the function
        // code of a function it does not know; the rest of that frame (by its
        // MBAP length) is read here, so that it gets its exception answer and
        // the stream stays in step.
        if (rc < header + 1 || be16(&query[2]) != 0) break;
        int length = be16(&query[4]) + 6;
        if (length < rc || length > MODBUS_TCP_MAX_ADU_LENGTH) break;
        if (length > rc && !readRest(c.fd, &query[size_t(rc)], size_t(length - rc), limits_.byteTimeoutMs)) break;
        rc = length;
        lastRequest = Clock::now();

        tokens = std::min<double>(limits_.burst, tokens + std::chrono::duration<double>(lastRequest - refilled).count() * limits_.requestsPerSecond);
        refilled = lastRequest;
        if (tokens < 1) {
            std::this_thread::sleep_for(std::chrono::duration<double>((1 - tokens) / limits_.requestsPerSecond));
            tokens = 1;
            refilled = Clock::now();
        }
        tokens -= 1;

        Request req{&query[size_t(header)], size_t(rc - header)};
        Request::Range range = req.readRange();
        if (readAccepted(range)) plc_.readImage([&](const ImageView& v) { tables.fill(v, range.table, range.first, range.count); });
        if (modbus_reply(ctx, query.data(), rc, tables.map) < 0) break;
        answered_.fetch_add(1, std::memory_order_relaxed);
        req.writes(tables.map, writes);
        if (!writes.empty()) plc_.write(writes);
    }
    modbus_close(ctx);  // closes c.fd
    modbus_free(ctx);
}

}  // namespace strun::live
