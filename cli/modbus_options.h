// --modbus [ADDR:]PORT and --modbus-client FILE (run): the options, their
// checks before the run (exit 2), and the server and client threads around
// the run (docs/modbus.md).
#pragma once

#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "cli/cli11_fwd.h"

#include "cli/command_line.h"
#include "live/modbus_map.h"
#include "runtime/scheduler.h"

namespace strun::live {
class ControlPlane;
class ModbusClient;
class ModbusPlane;
class ModbusServer;
}  // namespace strun::live

namespace strun::cli {

void addModbusOptions(CLI::App& run, CommandLine& line);

// What the options asked for, checked.
struct ModbusSetup {
    bool serve = false;
    std::string host = "127.0.0.1";
    int port = 0;
    std::optional<live::ModbusClientConfig> client;
    bool any() const { return serve || client.has_value(); }
};

// Checks the options (real clock only, the address, the mapping file) before
// the project is compiled. False with the one-line usage `error` (exit 2).
bool prepareModbus(const CommandLine& line, ModbusSetup& setup, std::string& error);

// The running server and client on the live run's control plane: started
// before the scheduler runs, stopped (threads joined) by stop() or when
// destroyed.
class ModbusRun {
public:
    ModbusRun();
    ~ModbusRun();
    // Puts itself between the scheduler and the control plane (`run.live`,
    // which the live session set), listens and starts the threads; prints
    // `strun: serving modbus tcp://HOST:PORT/` on `log`. False with `error`
    // when the server cannot listen.
    bool start(const ModbusSetup& setup, live::ControlPlane& control, rt::RunOptions& run, std::ostream& log, std::string& error);
    void stop();

private:
    std::unique_ptr<live::ModbusPlane> plane_;
    std::unique_ptr<live::ModbusServer> server_;
    std::unique_ptr<live::ModbusClient> client_;
};

}  // namespace strun::cli
