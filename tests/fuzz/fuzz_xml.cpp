// libFuzzer target: any bytes as an XML project file - a PLCopen TC6 project
// when its root says so, else a TwinCAT object - converted to ST, compiled and
// run for 5 ms of PLC time. Build and use: docs/fuzzing.md.
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_session.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static strun::fuzz::Session* session = new strun::fuzz::Session();  // the library is parsed once
    session->runXml(data, size);
    return 0;
}
