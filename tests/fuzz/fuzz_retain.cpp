// libFuzzer target: any bytes as the retain file of a fixed program whose
// retained variables cover every kind of value (strings, BOOL, enumerations,
// subranges, arrays, structures, FB instances, PERSISTENT globals): restored
// as `--retain` does, run for 5 ms of PLC time, saved again. The seed is the
// program's own valid file, and the same with its last line "END FIX" (the
// harness computes the checksum, so mutated values reach the value checks). Build and use:
// docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/fuzz/fuzz_session.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static strun::fuzz::Session* session = new strun::fuzz::Session();  // the library is parsed once
    session->runRetain(data, size);
    return 0;
}

// `fuzz_retain -write_seed=FILE`-like helper: with STRUN_FUZZ_RETAIN_SEED set,
// the valid retain file of the program is written there before fuzzing.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    if (const char* path = std::getenv("STRUN_FUZZ_RETAIN_SEED")) {
        strun::fuzz::Session session;
        for (bool toFix : {false, true}) {
            const std::string file = session.validRetainFile(toFix);
            if (std::FILE* f = std::fopen((std::string(path) + (toFix ? ".fix" : "")).c_str(), "wb")) {
                std::fwrite(file.data(), 1, file.size(), f);
                std::fclose(f);
            }
        }
    }
    return 0;
}
