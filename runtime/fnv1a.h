// FNV-1a, 64 bits: the one hash of byte strings in strun (retain-file
// checksums, VCD change detection of strings, TcUnit's assertion records).
#pragma once

#include <cstddef>
#include <cstdint>

namespace strun::rt {

inline constexpr uint64_t kFnv1aPrime = 1099511628211ull;
inline constexpr uint64_t kFnv1aBasis = 14695981039346656037ull;  // the standard offset basis
// The retain file format (docs/retain.md) was first written with this basis,
// a digit short of the standard one; files already written must still verify,
// so their checksum keeps it.
inline constexpr uint64_t kRetainFnv1aBasis = 1469598103934665603ull;

constexpr uint64_t fnv1aStep(uint64_t hash, uint8_t byte) { return (hash ^ byte) * kFnv1aPrime; }

inline uint64_t fnv1a(uint64_t hash, const void* data, size_t size) {
    const auto* bytes = static_cast<const uint8_t*>(data);
    for (size_t i = 0; i < size; ++i) hash = fnv1aStep(hash, bytes[i]);
    return hash;
}

}  // namespace strun::rt
