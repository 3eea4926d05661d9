// --modbus [ADDR:]PORT: a Modbus TCP server (libmodbus) over the process
// image with OpenPLC's table (live/modbus_map.h, docs/modbus.md).
//
// Threads: one accepts, one per connection (at most kMaxConnections; a
// further client is accepted and closed at once). A connection thread waits
// for its client only: a slow or hostile client (a frame trickled byte by
// byte, garbage, a flood of requests) costs its own connection at most.
// Reads answer from one published snapshot per request; writes go to the
// PLC's write queue. The threads run at a lower CPU priority than the scan
// (nice +10) and never take a lock the scan takes.
#pragma once

#include <atomic>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "live/modbus_plc.h"

namespace strun::live {

struct ModbusServerLimits {
    int maxConnections = 32;          // clients served at once
    double requestsPerSecond = 2000;  // per connection; faster clients wait for their answers
    int burst = 200;                  // requests a connection may send at once before the rate applies
    int idleSeconds = 60;             // a connection that sends nothing for this long is closed
    int byteTimeoutMs = 500;          // a frame whose bytes stop coming for this long closes its connection
};

class ModbusServer {
public:
    explicit ModbusServer(ModbusPlc& plc, ModbusServerLimits limits = {});
    ~ModbusServer();  // stop()
    ModbusServer(const ModbusServer&) = delete;
    ModbusServer& operator=(const ModbusServer&) = delete;

    // Binds and listens on the IPv4 address `host` and `port` (0: any free
    // port). False with `error` when it cannot. Then port() is the bound port.
    bool listen(const std::string& host, int port, std::string& error);
    int port() const { return port_; }
    void start();  // the accept thread
    void stop();   // closes every connection and joins every thread

    // Counters (for tests and the closing summary).
    uint64_t requestsAnswered() const { return answered_.load(std::memory_order_relaxed); }
    uint64_t connectionsRefused() const { return refused_.load(std::memory_order_relaxed); }

private:
    struct Connection;
    void acceptLoop();
    void serve(Connection& c);
    void reap(bool all);

    ModbusPlc& plc_;
    ModbusServerLimits limits_;
    int listenFd_ = -1;
    int port_ = 0;
    std::atomic<bool> stopping_{false};
    std::thread acceptThread_;
    std::mutex connectionsMutex_;
    std::list<std::unique_ptr<Connection>> connections_;
    std::atomic<uint64_t> answered_{0}, refused_{0};
};

}  // namespace strun::live
