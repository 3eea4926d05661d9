#include "cli/modbus_options.h"

#include <fstream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "live/control_plane.h"
#include "live/modbus_client.h"
#include "live/modbus_plane.h"
#include "live/modbus_server.h"
#include "runtime/plc_profile.h"

namespace strun::cli {

void addModbusOptions(CLI::App& run, CommandLine& line) {
    // Either option needs the live control plane (cli/live_options.h).
    run.add_option("--modbus", line.modbusServe,
                   "serve the process image over Modbus TCP on ADDR (default 127.0.0.1) and PORT (0: any free port); real clock only")
        ->type_name("[ADDR:]PORT")
        ->each([&line](const std::string&) { line.live.modbus = true; });
    run.add_option("--modbus-client", line.modbusClientFile,
                   "poll the Modbus TCP devices of the JSON mapping FILE into the process image; real clock only")
        ->type_name("FILE")
        ->each([&line](const std::string&) { line.live.modbus = true; });
}

namespace {

// [ADDR:]PORT: ADDR an IPv4 address or `localhost`, PORT 0..65535.
bool parseListen(const std::string& text, ModbusSetup& setup, std::string& error) {
    size_t colon = text.rfind(':');
    std::string port = colon == std::string::npos ? text : text.substr(colon + 1);
    if (colon != std::string::npos) setup.host = text.substr(0, colon);
    if (setup.host == "localhost") setup.host = "127.0.0.1";
    bool digits = !port.empty() && port.size() <= 5 && port.find_first_not_of("0123456789") == std::string::npos;
    if (!digits || std::stoul(port) > 65535) {
        error = "--modbus: '" + text + "' is not [ADDR:]PORT (PORT 0..65535, e.g. 5020 or 127.0.0.1:5020)";
        return false;
    }
    setup.port = int(std::stoul(port));
    unsigned a, b, c, d;
    char extra;
    if (std::sscanf(setup.host.c_str(), "%u.%u.%u.%u%c", &a, &b, &c, &d, &extra) != 4 || a > 255 || b > 255 || c > 255 || d > 255) {
        error = "--modbus: '" + setup.host + "' is not an IPv4 address (e.g. 127.0.0.1, 0.0.0.0)";
        return false;
    }
    setup.serve = true;
    return true;
}

}  // namespace

bool prepareModbus(const CommandLine& line, ModbusSetup& setup, std::string& error) {
    bool serve = !line.modbusServe.empty(), client = !line.modbusClientFile.empty();
    if (!serve && !client) return true;
    if (line.virtualClock) {
        error = std::string(serve ? "--modbus" : "--modbus-client") + " exchanges with the outside world in real time: it cannot be used with --virtual";
        return false;
    }
    if (serve && !parseListen(line.modbusServe, setup, error)) return false;
    if (client) {
        const std::string& path = line.modbusClientFile;
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            error = "--modbus-client: cannot read '" + path + "'";
            return false;
        }
        std::ostringstream text;
        text << in.rdbuf();
        if (text.str().size() > 16 * 1024 * 1024) {
            error = "--modbus-client: '" + path + "' is larger than 16 MiB";
            return false;
        }
        const rt::PlcProfile* profile = rt::findProfile(line.compile.target);
        setup.client = live::parseModbusClientConfig(text.str(), path, profile ? *profile : rt::defaultProfile(), error);
        if (!setup.client) {
            error = "--modbus-client: " + error;
            return false;
        }
    }
    return true;
}

ModbusRun::ModbusRun() = default;
ModbusRun::~ModbusRun() { stop(); }

bool ModbusRun::start(const ModbusSetup& setup, live::ControlPlane& control, rt::RunOptions& run, std::ostream& log,
                      std::string& error) {
    if (!setup.any()) return true;
    plane_ = std::make_unique<live::ModbusPlane>(control, *run.live);
    if (setup.serve) plane_->requireServedTable();
    if (setup.client) plane_->requireMapped(*setup.client);
    live::ModbusPlc& plc = *plane_;
    if (setup.serve) {
        server_ = std::make_unique<live::ModbusServer>(plc);
        if (!server_->listen(setup.host, setup.port, error)) {
            error = "--modbus: " + error;
            server_.reset();
            return false;
        }
        server_->start();
        log << "strun: serving modbus tcp://" << setup.host << ":" << server_->port() << "/" << std::endl;
    }
    if (setup.client) {
        client_ = std::make_unique<live::ModbusClient>(plc, *setup.client);
        client_->start();
    }
    run.live = plane_.get();
    return true;
}

void ModbusRun::stop() {
    if (client_) client_->stop();
    if (server_) server_->stop();
}

}  // namespace strun::cli
