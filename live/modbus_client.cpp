#include "live/modbus_client.h"

#include <modbus/modbus.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <string>

#include "live/network_thread.h"

namespace strun::live {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int64_t kMaxBackoffNs = 5'000'000'000;

// A request carries at most this many items (the protocol's limits); longer ranges go in several.
size_t chunkLimit(DeviceTable table, bool write) {
    if (isBitTable(table)) return write ? MODBUS_MAX_WRITE_BITS : MODBUS_MAX_READ_BITS;
    return write ? MODBUS_MAX_WRITE_REGISTERS : MODBUS_MAX_READ_REGISTERS;
}

// The image place of item k of a range: bit k after a bit address, word k after a word address.
rt::DirectAddress itemAddress(const MappedRange& r, size_t k) {
    rt::DirectAddress a = r.image;
    if (a.size == 'X') {
        size_t bit = a.byte * 8 + size_t(a.bit) + k;
        a.byte = bit / 8;
        a.bit = int(bit % 8);
    } else {
        a.byte += 2 * k;
    }
    return a;
}

class Session {
public:
    explicit Session(const ModbusDevice& d) : device_(d) {}
    ~Session() { drop(); }

    // Connects when not connected. False with `error`.
    bool ensure(std::string& error) {
        if (ctx_) return true;
        ctx_ = modbus_new_tcp_pi(device_.host.c_str(), std::to_string(device_.port).c_str());
        if (!ctx_) {
            error = modbus_strerror(errno);
            return false;
        }
        int64_t t = device_.timeoutNs;
        modbus_set_response_timeout(ctx_, uint32_t(t / 1'000'000'000), uint32_t(t % 1'000'000'000 / 1000));
        modbus_set_byte_timeout(ctx_, uint32_t(t / 1'000'000'000), uint32_t(t % 1'000'000'000 / 1000));
        modbus_set_slave(ctx_, device_.unit);
        if (modbus_connect(ctx_) < 0) {
            error = std::string("cannot connect: ") + modbus_strerror(errno);
            drop();
            return false;
        }
        return true;
    }
    void drop() {
        if (!ctx_) return;
        modbus_close(ctx_);
        modbus_free(ctx_);
        ctx_ = nullptr;
    }

    // Reads every range into `out` (image writes). False with `error`.
    bool readAll(std::vector<ImageWrite>& out, std::string& error) {
        out.clear();
        for (const MappedRange& r : device_.reads) {
            for (size_t done = 0; done < r.count;) {
                size_t n = std::min<size_t>(r.count - done, chunkLimit(r.table, false));
                int addr = int(r.start + done);
                int rc = -1;
                if (isBitTable(r.table)) {
                    bits_.resize(n);
                    rc = r.table == DeviceTable::Coils ? modbus_read_bits(ctx_, addr, int(n), bits_.data())
                                                       : modbus_read_input_bits(ctx_, addr, int(n), bits_.data());
                    if (rc == int(n))
                        for (size_t k = 0; k < n; ++k) out.push_back({itemAddress(r, done + k), bits_[k]});
                } else {
                    words_.resize(n);
                    rc = r.table == DeviceTable::HoldingRegisters ? modbus_read_registers(ctx_, addr, int(n), words_.data())
                                                                  : modbus_read_input_registers(ctx_, addr, int(n), words_.data());
                    if (rc == int(n))
                        for (size_t k = 0; k < n; ++k) out.push_back({itemAddress(r, done + k), words_[k]});
                }
                if (rc != int(n)) return failed(r, "read", error);
                done += n;
            }
        }
        return true;
    }

    // Takes the values of every write range from `v` (one activation's
    // image), to be sent by sendAll() once the view is released.
    void collect(const ImageView& v) {
        pending_.clear();
        for (const MappedRange& r : device_.writes) {
            for (size_t done = 0; done < r.count;) {
                size_t n = std::min<size_t>(r.count - done, chunkLimit(r.table, true));
                Chunk c{&r, int(r.start + done), {}};
                for (size_t k = 0; k < n; ++k) {
                    rt::DirectAddress a = itemAddress(r, done + k);
                    c.values.push_back(r.table == DeviceTable::Coils ? v.bit(a.area, a.byte, a.bit) : v.word(a.area, a.byte));
                }
                pending_.push_back(std::move(c));
                done += n;
            }
        }
    }

    // Sends what collect() took. False with `error`.
    bool sendAll(std::string& error) {
        for (const Chunk& c : pending_) {
            int n = int(c.values.size());
            int rc;
            if (c.range->table == DeviceTable::Coils) {
                bits_.assign(c.values.begin(), c.values.end());
                rc = modbus_write_bits(ctx_, c.address, n, bits_.data());
            } else {
                rc = modbus_write_registers(ctx_, c.address, n, c.values.data());
            }
            if (rc != n) return failed(*c.range, "write", error);
        }
        return true;
    }

private:
    bool failed(const MappedRange& r, const char* what, std::string& error) {
        int e = errno;
        error = std::string(what) + " of " + deviceTableName(r.table) + " " + std::to_string(r.start) + ".." +
                std::to_string(r.start + r.count - 1) + " failed: " + modbus_strerror(e);
        // An exception answer leaves the connection usable; anything else (a timeout, a reset) does not.
        if (e < MODBUS_ENOBASE || e > MODBUS_ENOBASE + 32) drop();
        return false;
    }

    const ModbusDevice& device_;
    modbus_t* ctx_ = nullptr;
    std::vector<uint8_t> bits_;
    std::vector<uint16_t> words_;
    struct Chunk {
        const MappedRange* range;
        int address;
        std::vector<uint16_t> values;
    };
    std::vector<Chunk> pending_;
};

}  // namespace

ModbusClient::ModbusClient(ModbusPlc& plc, ModbusClientConfig config) : plc_(plc), config_(std::move(config)) {}

ModbusClient::~ModbusClient() { stop(); }

void ModbusClient::start() {
    for (const ModbusDevice& d : config_.devices) threads_.emplace_back([this, &d] { poll(d); });
}

void ModbusClient::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_)
        if (t.joinable()) t.join();
    threads_.clear();
}

bool ModbusClient::waitFor(int64_t ns) {
    std::unique_lock<std::mutex> lock(mutex_);
    return !wake_.wait_for(lock, std::chrono::nanoseconds(ns), [this] { return stopping_; });
}

void ModbusClient::poll(const ModbusDevice& device) {
    lowerThreadPriority();
    Session session(device);
    std::vector<ImageWrite> inputs;
    bool inOutage = false;
    int64_t backoff = device.periodNs;
    std::string where = "'" + device.name + "' (" + device.host + ":" + std::to_string(device.port) + ")";
    Clock::time_point next = Clock::now();
    for (;;) {
        std::string error;
        bool ok = session.ensure(error) && session.readAll(inputs, error);
        if (ok && !inputs.empty()) plc_.write(inputs);
        if (ok) {
            plc_.readImage([&](const ImageView& v) { session.collect(v); });
            ok = session.sendAll(error);
        }
        if (ok) {
            exchanges_.fetch_add(1, std::memory_order_relaxed);
            inOutage = false;
            backoff = device.periodNs;
            next += std::chrono::nanoseconds(device.periodNs);
            Clock::time_point now = Clock::now();
            if (next < now) next = now;  // a late exchange does not make the next ones come in a burst
        } else {
            if (!inOutage) {
                inOutage = true;
                outages_.fetch_add(1, std::memory_order_relaxed);
                plc_.ioFault("Modbus device " + where + ": " + error + "; inputs keep their last values until it answers again");
            }
            session.drop();
            next = Clock::now() + std::chrono::nanoseconds(backoff);
            backoff = std::min(backoff * 2, std::max(kMaxBackoffNs, device.periodNs));
        }
        int64_t wait = std::chrono::duration_cast<std::chrono::nanoseconds>(next - Clock::now()).count();
        if (!waitFor(std::max<int64_t>(wait, 0))) return;
    }
}

}  // namespace strun::live
