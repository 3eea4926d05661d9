// A direct address of the process image as text (%IX0.3, %QW2, %MB7,
// %ID1, %ML0) parsed into its area, access size and byte/bit position,
// CODESYS addressing as runtime/machine.h describes it (the index counts
// units of the access size: %QW2 is bytes 4..5). The address's own rules
// only: whether a place may use it (an input where an output is needed) is
// the caller's to say.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace strun::rt {

struct DirectAddress {
    enum class Area : char { Input = 'I', Output = 'Q', Memory = 'M' };
    Area area = Area::Input;
    char size = 'X';   // X B W D L
    size_t byte = 0;   // first byte in the area
    int bit = -1;      // X: 0..7, else -1
    size_t bytes() const { return size == 'X' ? 1 : size == 'B' ? 1 : size == 'W' ? 2 : size == 'D' ? 4 : 8; }
};

// nullopt with `error` set ("not a direct address (%IX0.3, %QW2, %MW5)", ...)
// when `text` is not one or lies outside the image of `areaBytes` bytes.
// `%IX` may be written `%I` (`%I0.3`); a bit address needs byte.bit.
std::optional<DirectAddress> parseDirectAddress(std::string_view text, size_t areaBytes, std::string& error);

std::string formatDirectAddress(const DirectAddress& address);  // "%QX1.2", "%MW5"

}  // namespace strun::rt
