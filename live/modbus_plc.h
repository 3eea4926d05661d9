// What the Modbus threads (live/modbus_server.h, live/modbus_client.h) need
// from the running PLC, and nothing more: the process image as the last
// completed activation published it, a way to hand in writes, and a way to
// record IO_FAULT. The run implements it over the live control plane
// (live/modbus_run.h); tests may implement it over plain buffers. Every
// method is called from network threads and must never make them wait for
// the scan, nor the scan for them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "runtime/direct_address.h"

namespace strun::live {

// One activation's image: all three areas from the same published snapshot.
// Bytes past an area's size read as 0.
struct ImageView {
    const uint8_t* inputs = nullptr;   // %I as the program saw it
    const uint8_t* outputs = nullptr;  // %Q as the activation left it (what the outputs received)
    const uint8_t* memory = nullptr;   // %M
    size_t inputBytes = 0, outputBytes = 0, memoryBytes = 0;

    uint8_t bit(rt::DirectAddress::Area area, size_t byte, int bit) const {
        return byte < bytes(area) ? (base(area)[byte] >> bit) & 1 : 0;
    }
    // The little-endian word at `byte` (the image's %xW).
    uint16_t word(rt::DirectAddress::Area area, size_t byte) const {
        const uint8_t* a = base(area);
        size_t n = bytes(area);
        return uint16_t((byte < n ? a[byte] : 0) | ((byte + 1 < n ? a[byte + 1] : 0) << 8));
    }
    const uint8_t* base(rt::DirectAddress::Area area) const {
        return area == rt::DirectAddress::Area::Input ? inputs : area == rt::DirectAddress::Area::Output ? outputs : memory;
    }
    size_t bytes(rt::DirectAddress::Area area) const {
        return area == rt::DirectAddress::Area::Input ? inputBytes : area == rt::DirectAddress::Area::Output ? outputBytes : memoryBytes;
    }
};

// One item written from outside: a bit (X address; value 0 or 1) or a word
// (W address). An %I address sets the physical input; %Q and %M are
// written as the contract's live writes (before the next activation's input phase).
struct ImageWrite {
    rt::DirectAddress at;
    uint16_t value = 0;
};

class ModbusPlc {
public:
    virtual ~ModbusPlc() = default;
    // Calls `read` with the image the last completed activation published
    // (before the first one: the initial image). The view is valid only during the call.
    virtual void readImage(const std::function<void(const ImageView&)>& read) = 0;
    // Queues writes that are applied together, in order, when the next activation starts.
    virtual void write(std::span<const ImageWrite> writes) = 0;
    // Records IO_FAULT in the diagnostic buffer (at the next activation boundary).
    virtual void ioFault(std::string message) = 0;
};

}  // namespace strun::live
