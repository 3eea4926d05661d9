// libFuzzer target: any bytes as an ST project, compiled and run for 5 ms
// of PLC time. Build and use: docs/fuzzing.md (cmake -DSTRUN_FUZZ=ON with clang).
#include <cstdint>
#include <cstdlib>

#include "tests/fuzz/fuzz_session.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static strun::fuzz::Session* session = new strun::fuzz::Session();  // the library is parsed once
    session->runOnce(data, size);
    return 0;
}
