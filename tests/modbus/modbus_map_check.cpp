// The Modbus address table, the --modbus-client mapping validator, and the
// server and client threads over a plain image (no scheduler): libmodbus on
// both sides of a loopback connection.
#include <catch2/catch.hpp>

#include <modbus/modbus.h>

#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "live/modbus_client.h"
#include "live/modbus_map.h"
#include "live/modbus_server.h"
#include "runtime/plc_profile.h"

using namespace strun;
using namespace strun::live;
using Area = rt::DirectAddress::Area;

TEST_CASE("the served table is OpenPLC's", "[modbus]") {
    auto coil = servedAddress(ModbusTable::Coils, 13);
    REQUIRE(coil);
    CHECK((coil->area == Area::Output && coil->byte == 1 && coil->bit == 5));
    CHECK(rt::formatDirectAddress(*servedAddress(ModbusTable::DiscreteInputs, 8191)) == "%IX1023.7");
    CHECK(!servedAddress(ModbusTable::Coils, 8192));
    CHECK(rt::formatDirectAddress(*servedAddress(ModbusTable::InputRegisters, 7)) == "%IW7");
    CHECK(!servedAddress(ModbusTable::InputRegisters, 1024));
    CHECK(rt::formatDirectAddress(*servedAddress(ModbusTable::HoldingRegisters, 1023)) == "%QW1023");
    CHECK(rt::formatDirectAddress(*servedAddress(ModbusTable::HoldingRegisters, 1024)) == "%MW0");
    CHECK(rt::formatDirectAddress(*servedAddress(ModbusTable::HoldingRegisters, 2047)) == "%MW1023");
    CHECK(!servedAddress(ModbusTable::HoldingRegisters, 2048));
}

TEST_CASE("direct addresses parse by CODESYS rules", "[modbus]") {
    std::string error;
    auto a = rt::parseDirectAddress("%qw3", 65536, error);
    REQUIRE(a);
    CHECK((a->area == Area::Output && a->size == 'W' && a->byte == 6));
    CHECK(rt::parseDirectAddress("%I2.7", 65536, error)->bit == 7);
    CHECK(!rt::parseDirectAddress("%IX2.8", 65536, error));
    CHECK(!rt::parseDirectAddress("%IW32768", 65536, error));
    CHECK(error.find("outside") != std::string::npos);
    CHECK(!rt::parseDirectAddress("%SW3", 65536, error));
}

namespace {
std::string parseError(const std::string& text, const rt::PlcProfile& profile = rt::defaultProfile()) {
    std::string error;
    auto c = parseModbusClientConfig(text, "m.json", profile, error);
    return c ? std::string("(valid)") : error;
}
}  // namespace

TEST_CASE("the contract's example mapping is valid", "[modbus]") {
    std::string error;
    auto c = parseModbusClientConfig(R"({"devices": [{"name": "plant", "host": "127.0.0.1", "port": 5020, "unit": 1,
                  "period": "T#50ms", "timeout": "T#200ms",
                  "read":  [{"table": "discrete_inputs", "start": 0, "count": 8, "to": "%IX0.0"},
                            {"table": "input_registers",  "start": 0, "count": 2, "to": "%IW2"}],
                  "write": [{"table": "coils",             "start": 0, "count": 8, "from": "%QX0.0"},
                            {"table": "holding_registers", "start": 0, "count": 1, "from": "%QW2"}]}]})",
                                     "m.json", rt::defaultProfile(), error);
    REQUIRE(c);
    REQUIRE(c->devices.size() == 1);
    const ModbusDevice& d = c->devices[0];
    CHECK(d.periodNs == 50'000'000);
    CHECK(d.timeoutNs == 200'000'000);
    CHECK(d.reads[1].image.byte == 4);
    CHECK(d.writes[0].table == DeviceTable::Coils);
}

TEST_CASE("a wrong mapping names the line or the field", "[modbus]") {
    CHECK(parseError("{\"devices\": [\n\n  {,}]}").rfind("m.json:3:", 0) == 0);
    CHECK(parseError(R"({"devices": []})").find("devices:") != std::string::npos);
    CHECK(parseError(R"({"devices": [{"name": "a", "host": "h", "port": 1, "read": [{"table": "coils", "start": 0, "count": 0, "to": "%IX0.0"}]}]})")
              .find("devices[0].read[0].count") != std::string::npos);
    CHECK(parseError(R"({"devices": [{"name": "a", "host": "h", "port": 1, "read": [{"table": "coils", "start": 0, "count": 9, "to": "%IW0"}]}]})")
              .find("devices[0].read[0].to") != std::string::npos);
    CHECK(parseError(R"({"devices": [{"name": "a", "host": "h", "port": 1, "write": [{"table": "coils", "start": 0, "count": 9, "from": "%IX0.0"}]}]})")
              .find("devices[0].write[0].from") != std::string::npos);
    // Two devices filling the same inputs overlap; two devices reading the same outputs do not.
    CHECK(parseError(R"({"devices": [{"name": "a", "host": "h", "port": 1, "read": [{"table": "coils", "start": 0, "count": 9, "to": "%IX0.0"}]},
                                     {"name": "b", "host": "h", "port": 2, "read": [{"table": "coils", "start": 0, "count": 1, "to": "%IX1.0"}]}]})")
              .find("devices[1].read[0]: overlaps") != std::string::npos);
    CHECK(parseError(R"({"devices": [{"name": "a", "host": "h", "port": 1, "write": [{"table": "coils", "start": 0, "count": 9, "from": "%QX0.0"}]},
                                     {"name": "b", "host": "h", "port": 2, "write": [{"table": "coils", "start": 0, "count": 9, "from": "%QX0.0"}]}]})") == "(valid)");
    CHECK(parseError(R"({"devices": [{"name": "a", "host": "h", "port": 1, "write": [{"table": "holding_registers", "start": 0, "count": 4, "from": "%QW0"},
                                                                                  {"table": "holding_registers", "start": 3, "count": 1, "from": "%MW0"}]}]})")
              .find("devices[0].write[1]: overlaps") != std::string::npos);
    CHECK(parseError(R"({"devices": [{"name": "a", "host": "h", "port": 1, "read": [{"table": "coils", "start": 0, "count": 1, "to": "%IX0.0"}]},
                                     {"name": "a", "host": "h", "port": 2, "read": [{"table": "coils", "start": 0, "count": 1, "to": "%IX1.0"}]}]})")
              .find("devices[1].name") != std::string::npos);
    CHECK(parseError(R"({"devices": [{"name": "a", "host": "h", "port": 1, "timeout": "T#0s", "read": [{"table": "coils", "start": 0, "count": 1, "to": "%IX0.0"}]}]})")
              .find("devices[0].timeout") != std::string::npos);
}

TEST_CASE("a target's input alias is an input address", "[modbus]") {
    const rt::PlcProfile* m241 = rt::findProfile("m241");
    REQUIRE(m241);
    std::string text = R"({"devices": [{"name": "a", "host": "h", "port": 1, "read": [{"table": "coils", "start": 0, "count": 1, "to": "FI0"}]}]})";
    CHECK(parseError(text, *m241) == "(valid)");
    CHECK(parseError(text).find("devices[0].read[0].to") != std::string::npos);
}

namespace {

// A process image without a scheduler: reads see `image`, writes are recorded.
struct PlainPlc : ModbusPlc {
    std::mutex m;
    std::vector<uint8_t> inputs = std::vector<uint8_t>(4096), outputs = std::vector<uint8_t>(4096), memory = std::vector<uint8_t>(4096);
    std::vector<ImageWrite> written;
    std::vector<std::string> faults;
    void readImage(const std::function<void(const ImageView&)>& read) override {
        std::lock_guard<std::mutex> lock(m);
        read(ImageView{inputs.data(), outputs.data(), memory.data(), 4096, 4096, 4096});
    }
    void write(std::span<const ImageWrite> writes) override {
        std::lock_guard<std::mutex> lock(m);
        written.insert(written.end(), writes.begin(), writes.end());
    }
    void ioFault(std::string message) override {
        std::lock_guard<std::mutex> lock(m);
        faults.push_back(std::move(message));
    }
};

}  // namespace

TEST_CASE("the server answers from the image and hands writes on", "[modbus]") {
    PlainPlc plc;
    plc.outputs[0] = 0x34;  // %QW0 = 0x1234
    plc.outputs[1] = 0x12;
    plc.memory[2] = 7;      // %MW1 = 7
    plc.inputs[0] = 0x08;   // %IX0.3
    ModbusServer server(plc);
    std::string error;
    REQUIRE(server.listen("127.0.0.1", 0, error));
    server.start();
    modbus_t* ctx = modbus_new_tcp("127.0.0.1", server.port());
    REQUIRE(modbus_connect(ctx) == 0);
    uint16_t regs[2] = {};
    REQUIRE(modbus_read_registers(ctx, 0, 1, regs) == 1);
    CHECK(regs[0] == 0x1234);
    REQUIRE(modbus_read_registers(ctx, 1025, 1, regs) == 1);
    CHECK(regs[0] == 7);
    uint8_t bits[8] = {};
    REQUIRE(modbus_read_input_bits(ctx, 0, 8, bits) == 8);
    CHECK((bits[3] == 1 && bits[2] == 0));
    CHECK(modbus_read_registers(ctx, 2047, 2, regs) == -1);
    CHECK(errno == EMBXILADD);
    uint16_t values[2] = {5, 6};
    REQUIRE(modbus_write_registers(ctx, 1023, 2, values) == 2);
    REQUIRE(modbus_write_bit(ctx, 9, 1) == 1);
    modbus_close(ctx);
    modbus_free(ctx);
    server.stop();
    REQUIRE(plc.written.size() == 3);
    CHECK(rt::formatDirectAddress(plc.written[0].at) == "%QW1023");
    CHECK(plc.written[0].value == 5);
    CHECK(rt::formatDirectAddress(plc.written[1].at) == "%MW0");
    CHECK(rt::formatDirectAddress(plc.written[2].at) == "%QX1.1");
    CHECK(plc.written[2].value == 1);
}

TEST_CASE("the client polls a device, and reports its outage once", "[modbus]") {
    // The device is strun's own server over a second image.
    PlainPlc device;
    device.inputs[10] = 0x22;  // input register 5 = 0x1122
    device.inputs[11] = 0x11;
    device.outputs[4] = 0x2A;  // %QW2 (holding 2) = 42
    auto server = std::make_unique<ModbusServer>(device);
    std::string error;
    REQUIRE(server->listen("127.0.0.1", 0, error));
    server->start();
    int port = server->port();
    std::string mapping = R"({"devices": [{"name": "dev", "host": "127.0.0.1", "port": )" + std::to_string(port) +
                          R"(, "period": "T#10ms", "timeout": "T#100ms",
        "read": [{"table": "input_registers", "start": 5, "count": 1, "to": "%IW8"}],
        "write": [{"table": "holding_registers", "start": 100, "count": 2, "from": "%QW0"}]})" "]}";
    auto config = parseModbusClientConfig(mapping, "m.json", rt::defaultProfile(), error);
    INFO(error);
    REQUIRE(config);
    PlainPlc plc;
    plc.outputs[0] = 1;
    plc.outputs[2] = 2;
    ModbusClient client(plc, *config);
    client.start();
    auto until = [](auto predicate) {
        for (int i = 0; i < 500 && !predicate(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        return predicate();
    };
    CHECK(until([&] {
        std::lock_guard<std::mutex> lock(plc.m);
        return !plc.written.empty();
    }));
    {
        std::lock_guard<std::mutex> lock(plc.m);
        CHECK(rt::formatDirectAddress(plc.written[0].at) == "%IW8");
        CHECK(plc.written[0].value == 0x1122);
    }
    CHECK(until([&] {
        std::lock_guard<std::mutex> lock(device.m);
        return device.written.size() >= 2;
    }));
    {
        std::lock_guard<std::mutex> lock(device.m);
        CHECK(rt::formatDirectAddress(device.written[0].at) == "%QW100");
        CHECK(device.written[0].value == 1);
        CHECK(device.written[1].value == 2);
    }
    server->stop();
    server.reset();
    CHECK(until([&] {
        std::lock_guard<std::mutex> lock(plc.m);
        return !plc.faults.empty();
    }));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    client.stop();
    REQUIRE(plc.faults.size() == 1);
    CHECK(plc.faults[0].find("'dev'") != std::string::npos);
    CHECK(client.outages() == 1);
}
