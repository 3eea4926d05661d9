// One fuzz iteration, independent of libFuzzer: compile ST text against the
// standard library parsed once, run it for a bounded PLC time on the virtual
// clock, and dump its state. Shared by the libFuzzer target and its unit test.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "interpreter/project/compile.h"

namespace strun::fuzz {

class Session {
public:
    Session();
    // Returns the --dump JSON text of the run ("" when the input did not compile).
    std::string runOnce(const uint8_t* data, size_t size);

    static constexpr size_t kMaxInputBytes = 64 * 1024;
    static constexpr int64_t kPlcTimeNanos = 5'000'000;  // 5 ms of PLC time = 5 000 statements at 1 us

private:
    CompileLog libraryLog_;
    std::unique_ptr<project::ParsedLibrary> library_;
};

}  // namespace strun::fuzz
