// --modbus-client FILE: polls Modbus TCP devices (libmodbus) per the mapping
// (live/modbus_map.h), one thread per device, every `period`:
//   1. read each `read` range; when all of them answered, the values become
//      the physical inputs (a task sees them at its next input phase);
//   2. send each `write` range with the values the last completed
//      activation published.
// A failure (no connection, a timeout, an exception answer) starts an
// outage: IO_FAULT once, naming the device; its inputs keep their last
// values; the connection is dropped and tried again after a back-off
// (the period, doubled after each failed attempt, at most 5 s). The first
// complete exchange ends the outage. The scan never waits for a device.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "live/modbus_map.h"
#include "live/modbus_plc.h"

namespace strun::live {

class ModbusClient {
public:
    ModbusClient(ModbusPlc& plc, ModbusClientConfig config);
    ~ModbusClient();  // stop()
    ModbusClient(const ModbusClient&) = delete;
    ModbusClient& operator=(const ModbusClient&) = delete;

    void start();
    void stop();

    // Completed exchanges and outages so far, all devices (tests, summary).
    uint64_t exchanges() const { return exchanges_.load(std::memory_order_relaxed); }
    uint64_t outages() const { return outages_.load(std::memory_order_relaxed); }

private:
    void poll(const ModbusDevice& device);
    bool waitFor(int64_t ns);  // false when stopping

    ModbusPlc& plc_;
    ModbusClientConfig config_;
    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
    std::atomic<uint64_t> exchanges_{0}, outages_{0};
};

}  // namespace strun::live
