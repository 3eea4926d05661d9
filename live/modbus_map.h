// Modbus TCP <-> strun's process image: the server's address table (the one
// OpenPLC uses, contract "Modbus TCP") and the --modbus-client JSON mapping,
// parsed and validated before the run (docs/modbus.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "runtime/direct_address.h"
#include "runtime/plc_profile.h"

namespace strun::live {

// ---- the server's table (decision 0180)
enum class ModbusTable { Coils, DiscreteInputs, InputRegisters, HoldingRegisters };
constexpr size_t kServedCoils = 8192;             // %QX0.0 .. %QX1023.7
constexpr size_t kServedDiscreteInputs = 8192;    // %IX0.0 .. %IX1023.7
constexpr size_t kServedInputRegisters = 1024;    // %IW0 .. %IW1023
constexpr size_t kServedHoldingRegisters = 2048;  // %QW0 .. %QW1023, then %MW0 .. %MW1023

// Where one Modbus item lives in the image: coil n -> %QX(n/8).(n mod 8);
// holding register n -> %QW n (n < 1024) or %MW n-1024. Registers are the
// image's two bytes read as a little-endian word (the image's %QW), bits are
// bit n%8 of byte n/8. nullopt outside the served table.
std::optional<rt::DirectAddress> servedAddress(ModbusTable table, size_t n);

// ---- the --modbus-client mapping file
enum class DeviceTable { Coils, DiscreteInputs, HoldingRegisters, InputRegisters };
const char* deviceTableName(DeviceTable table);  // "coils", ...
bool isBitTable(DeviceTable table);

struct MappedRange {
    DeviceTable table = DeviceTable::Coils;
    uint16_t start = 0;   // first item on the device
    uint16_t count = 0;   // items (>= 1)
    rt::DirectAddress image;  // first bit (X) or word (W) in strun's image; item k is the k-th after it
    std::string field;    // "devices[0].read[1]" for messages
};

struct ModbusDevice {
    std::string name;
    std::string host;
    int port = 502;
    int unit = 1;
    int64_t periodNs = 0;
    int64_t timeoutNs = 0;
    std::vector<MappedRange> reads;   // device -> physical inputs (%I)
    std::vector<MappedRange> writes;  // %Q / %M -> device (coils, holding registers)
};

struct ModbusClientConfig {
    std::vector<ModbusDevice> devices;
};

// Parses and validates the mapping `text` (read from `path`). On failure
// returns nullopt and sets `error` to one line: "PATH:LINE:COL: invalid JSON:
// ..." for a syntax error, "PATH: FIELD: ..." (FIELD as `devices[0].read[1].to`)
// for a wrong, missing, unknown, overlapping or out-of-range value.
// `profile`: the target whose input aliases (`FI0` on m241) stand for %I bits.
std::optional<ModbusClientConfig> parseModbusClientConfig(const std::string& text, const std::string& path,
                                                          const rt::PlcProfile& profile, std::string& error);

}  // namespace strun::live
