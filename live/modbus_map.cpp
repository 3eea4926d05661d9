#include "live/modbus_map.h"

#include <algorithm>
#include <set>

#include <nlohmann/json.hpp>

#include "runtime/machine.h"
#include "stdlib/time_literals.h"

namespace strun::live {

std::optional<rt::DirectAddress> servedAddress(ModbusTable table, size_t n) {
    rt::DirectAddress a;
    switch (table) {
        case ModbusTable::Coils:
        case ModbusTable::DiscreteInputs:
            if (n >= (table == ModbusTable::Coils ? kServedCoils : kServedDiscreteInputs)) return std::nullopt;
            a.area = table == ModbusTable::Coils ? rt::DirectAddress::Area::Output : rt::DirectAddress::Area::Input;
            a.size = 'X';
            a.byte = n / 8;
            a.bit = int(n % 8);
            return a;
        case ModbusTable::InputRegisters:
            if (n >= kServedInputRegisters) return std::nullopt;
            a.area = rt::DirectAddress::Area::Input;
            a.size = 'W';
            a.byte = 2 * n;
            return a;
        case ModbusTable::HoldingRegisters:
            if (n >= kServedHoldingRegisters) return std::nullopt;
            a.area = n < 1024 ? rt::DirectAddress::Area::Output : rt::DirectAddress::Area::Memory;
            a.size = 'W';
            a.byte = 2 * (n % 1024);
            return a;
    }
    return std::nullopt;
}

const char* deviceTableName(DeviceTable table) {
    switch (table) {
        case DeviceTable::Coils: return "coils";
        case DeviceTable::DiscreteInputs: return "discrete_inputs";
        case DeviceTable::HoldingRegisters: return "holding_registers";
        case DeviceTable::InputRegisters: return "input_registers";
    }
    return "?";
}

bool isBitTable(DeviceTable table) { return table == DeviceTable::Coils || table == DeviceTable::DiscreteInputs; }

namespace {

using Json = nlohmann::json;

// A validation failure: the field's path and what is wrong with it.
struct Invalid {
    std::string field, why;
};

std::string describe(const Json& v) {
    std::string s = v.dump(-1, ' ', false, Json::error_handler_t::replace);
    return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

// Line and column (1-based) of byte `offset` of `text`.
std::pair<size_t, size_t> lineAndColumn(const std::string& text, size_t offset) {
    size_t line = 1, col = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return {line, col};
}

class Validator {
public:
    explicit Validator(const rt::PlcProfile& profile) : profile_(profile) {}

    ModbusClientConfig config(const Json& root) {
        if (!root.is_object()) throw Invalid{"(top level)", "must be an object {\"devices\": [...]}"};
        onlyKeys(root, "", {"devices"});
        if (!root.contains("devices")) throw Invalid{"devices", "missing (a list of devices)"};
        const Json& list = root["devices"];
        if (!list.is_array() || list.empty()) throw Invalid{"devices", "must be a non-empty list of devices"};
        ModbusClientConfig out;
        std::set<std::string> names;
        for (size_t i = 0; i < list.size(); ++i) {
            std::string at = "devices[" + std::to_string(i) + "]";
            out.devices.push_back(device(list[i], at));
            if (!names.insert(out.devices.back().name).second)
                throw Invalid{at + ".name", "'" + out.devices.back().name + "' names two devices"};
        }
        checkOverlaps(out);
        return out;
    }

private:
    ModbusDevice device(const Json& d, const std::string& at) {
        if (!d.is_object()) throw Invalid{at, "must be an object"};
        onlyKeys(d, at, {"name", "host", "port", "unit", "period", "timeout", "read", "write"});
        ModbusDevice dev;
        dev.name = text(d, at, "name", true);
        dev.host = text(d, at, "host", true);
        dev.port = int(integer(d, at, "port", 1, 65535, true, 502));
        dev.unit = int(integer(d, at, "unit", 0, 255, false, 1));
        dev.periodNs = duration(d, at, "period", 100'000'000);
        dev.timeoutNs = duration(d, at, "timeout", 1'000'000'000);
        dev.reads = ranges(d, at, "read", true);
        dev.writes = ranges(d, at, "write", false);
        if (dev.reads.empty() && dev.writes.empty()) throw Invalid{at, "maps nothing: give \"read\" or \"write\" entries"};
        return dev;
    }

    std::vector<MappedRange> ranges(const Json& d, const std::string& at, const char* key, bool read) {
        std::vector<MappedRange> out;
        if (!d.contains(key)) return out;
        std::string listAt = at + "." + key;
        const Json& list = d[key];
        if (!list.is_array()) throw Invalid{listAt, "must be a list"};
        for (size_t i = 0; i < list.size(); ++i) {
            std::string e = listAt + "[" + std::to_string(i) + "]";
            const Json& r = list[i];
            if (!r.is_object()) throw Invalid{e, "must be an object"};
            const char* place = read ? "to" : "from";
            onlyKeys(r, e, {"table", "start", "count", place});
            MappedRange m;
            m.field = e;
            m.table = table(r, e, read);
            m.start = uint16_t(integer(r, e, "start", 0, 65535, true, 0));
            m.count = uint16_t(integer(r, e, "count", 1, 65535, true, 0));
            if (size_t(m.start) + m.count > 65536)
                throw Invalid{e + ".count", "start + count goes past the device's last address 65535"};
            m.image = imageAddress(r, e + "." + place, read, isBitTable(m.table), m.count);
            out.push_back(m);
        }
        return out;
    }

    DeviceTable table(const Json& r, const std::string& e, bool read) {
        std::string name = text(r, e, "table", true);
        for (DeviceTable t : {DeviceTable::Coils, DeviceTable::DiscreteInputs, DeviceTable::HoldingRegisters, DeviceTable::InputRegisters}) {
            if (name != deviceTableName(t)) continue;
            if (!read && (t == DeviceTable::DiscreteInputs || t == DeviceTable::InputRegisters))
                throw Invalid{e + ".table", "'" + name + "' cannot be written: write tables are coils, holding_registers"};
            return t;
        }
        throw Invalid{e + ".table", "'" + name + "' is not a table: " +
                                        (read ? std::string("coils, discrete_inputs, holding_registers, input_registers")
                                              : std::string("coils, holding_registers"))};
    }

    // The first image place of a range: a bit address for bit tables, a word
    // address for registers; reads land in %I, writes come from %Q or %M.
    rt::DirectAddress imageAddress(const Json& r, const std::string& field, bool read, bool bits, size_t count) {
        const char* key = read ? "to" : "from";
        if (!r.contains(key)) throw Invalid{field, "missing (the first image address, e.g. " + std::string(bits ? (read ? "%IX0.0" : "%QX0.0") : (read ? "%IW0" : "%QW0")) + ")"};
        if (!r[key].is_string()) throw Invalid{field, "must be a string holding a direct address, not " + describe(r[key])};
        std::string text = r[key].get<std::string>();
        std::string error;
        std::optional<rt::DirectAddress> a;
        if (auto alias = rt::findInputAlias(profile_, text)) {  // m241 FI0: its %IX bit
            a = rt::DirectAddress{rt::DirectAddress::Area::Input, 'X', alias->byte, alias->bit};
        } else {
            a = rt::parseDirectAddress(text, rt::ProcessImage::kSize, error);
        }
        if (!a) throw Invalid{field, error};
        if (read && a->area != rt::DirectAddress::Area::Input)
            throw Invalid{field, "'" + text + "': values read from a device become physical inputs: give an %I address"};
        if (!read && a->area == rt::DirectAddress::Area::Input)
            throw Invalid{field, "'" + text + "': values written to a device come from %Q or %M, not from inputs"};
        if (bits && a->size != 'X')
            throw Invalid{field, "'" + text + "': a bit table maps to bits: give an X address such as " + (read ? "%IX0.0" : "%QX0.0")};
        if (!bits && a->size != 'W')
            throw Invalid{field, "'" + text + "': registers map to words: give a W address such as " + std::string(read ? "%IW0" : "%QW0")};
        size_t endBit = bits ? a->byte * 8 + size_t(a->bit) + count : (a->byte + 2 * count) * 8;
        if (endBit > rt::ProcessImage::kSize * 8)
            throw Invalid{field, "'" + text + "' + " + std::to_string(count) + " items goes past the end of the process image"};
        return *a;
    }

    // Two reads must not fill the same input bits, and two writes to one
    // device must not send to the same items: either would make the result
    // depend on the order of the entries.
    struct Span {
        size_t begin, end;
        const MappedRange* range;
        const ModbusDevice* device;
    };
    void checkOverlaps(const ModbusClientConfig& c) {
        std::vector<Span> inputs;
        for (const ModbusDevice& d : c.devices) {
            for (const MappedRange& r : d.reads) {
                size_t b = r.image.byte * 8 + size_t(std::max(r.image.bit, 0));
                inputs.push_back({b, b + (isBitTable(r.table) ? r.count : 16u * r.count), &r, &d});
            }
            std::vector<Span> sent;
            for (const MappedRange& r : d.writes) {
                size_t base = r.table == DeviceTable::Coils ? 0 : 1u << 20;
                sent.push_back({base + r.start, base + r.start + r.count, &r, &d});
            }
            overlap(sent, "sends to the same device items as");
        }
        overlap(inputs, "fills the same input bits as");
    }

    static void overlap(std::vector<Span>& spans, const char* what) {
        std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.begin < b.begin; });
        for (size_t i = 1; i < spans.size(); ++i)
            if (spans[i].begin < spans[i - 1].end) {
                const Span& later = spans[i].range->field > spans[i - 1].range->field ? spans[i] : spans[i - 1];
                const Span& other = &later == &spans[i] ? spans[i - 1] : spans[i];
                throw Invalid{later.range->field, std::string("overlaps: it ") + what + " " + other.range->field};
            }
    }

    static void onlyKeys(const Json& o, const std::string& at, std::initializer_list<const char*> known) {
        for (auto it = o.begin(); it != o.end(); ++it) {
            bool ok = std::any_of(known.begin(), known.end(), [&](const char* k) { return it.key() == k; });
            if (ok) continue;
            std::string list;
            for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
            throw Invalid{(at.empty() ? "" : at + ".") + it.key(), "unknown field (known: " + list + ")"};
        }
    }

    static std::string text(const Json& o, const std::string& at, const char* key, bool required) {
        std::string f = at + "." + key;
        if (!o.contains(key)) {
            if (required) throw Invalid{f, "missing"};
            return "";
        }
        if (!o[key].is_string() || o[key].get<std::string>().empty())
            throw Invalid{f, "must be a non-empty string, not " + describe(o[key])};
        return o[key].get<std::string>();
    }

    static int64_t integer(const Json& o, const std::string& at, const char* key, int64_t lo, int64_t hi, bool required, int64_t fallback) {
        std::string f = at + "." + key;
        if (!o.contains(key)) {
            if (required) throw Invalid{f, "missing"};
            return fallback;
        }
        const Json& v = o[key];
        if (!v.is_number_integer()) throw Invalid{f, "must be a whole number " + std::to_string(lo) + ".." + std::to_string(hi) + ", not " + describe(v)};
        bool inside = v.is_number_unsigned() ? v.get<uint64_t>() <= uint64_t(hi) && int64_t(v.get<uint64_t>()) >= lo
                                             : v.get<int64_t>() >= lo && v.get<int64_t>() <= hi;
        if (!inside) throw Invalid{f, describe(v) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi)};
        return v.get<int64_t>();
    }

    // A positive duration, as an IEC literal string ("T#50ms", "50ms").
    static int64_t duration(const Json& o, const std::string& at, const char* key, int64_t fallback) {
        std::string f = at + "." + key;
        if (!o.contains(key)) return fallback;
        const Json& v = o[key];
        if (!v.is_string()) throw Invalid{f, "must be a duration string such as \"T#50ms\", not " + describe(v)};
        auto r = stdlib::parseDurationLiteral(v.get<std::string>());
        if (!r) throw Invalid{f, "'" + v.get<std::string>() + "' is not a duration (e.g. T#50ms): " + r.error()};
        if (r.value() <= 0) throw Invalid{f, "must be longer than 0"};
        if (r.value() > int64_t(86400) * 1'000'000'000) throw Invalid{f, "must be at most one day"};
        return r.value();
    }

    const rt::PlcProfile& profile_;
};

}  // namespace

std::optional<ModbusClientConfig> parseModbusClientConfig(const std::string& text, const std::string& path,
                                                          const rt::PlcProfile& profile, std::string& error) {
    Json root;
    try {
        root = Json::parse(text);
    } catch (const Json::parse_error& e) {
        auto [line, col] = lineAndColumn(text, e.byte > 0 ? e.byte - 1 : 0);
        std::string what = e.what();
        // "[json.exception.parse_error.101] parse error at line 2, column 5: syntax error while parsing ..."
        size_t colon = what.find(": ");
        error = path + ":" + std::to_string(line) + ":" + std::to_string(col) + ": invalid JSON: " +
                (colon == std::string::npos ? what : what.substr(colon + 2));
        return std::nullopt;
    }
    try {
        return Validator(profile).config(root);
    } catch (const Invalid& bad) {
        error = path + ": " + bad.field + ": " + bad.why;
        return std::nullopt;
    }
}

}  // namespace strun::live
