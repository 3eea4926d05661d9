// libFuzzer target: any bytes as an ST project, compiled and run for 5 ms
// of PLC time, and scanned by both the scanner and the grammar's lexer. Build and use: docs/fuzzing.md (cmake -DSTRUN_FUZZ=ON with clang).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "interpreter/ast/utf8_input.h"
#include "tests/fuzz/scanner_oracle.h"

#include "tests/fuzz/fuzz_session.h"

// Also: the scanner must produce the same tokens as the lexer generated from
// the grammar (decision 0157); a difference aborts like a crash.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static strun::fuzz::Session* session = new strun::fuzz::Session();  // the library is parsed once
    session->runOnce(data, size);
    const std::string text = strun::ast::sanitizeUtf8(std::string(reinterpret_cast<const char*>(data), size));
    if (const auto difference = strun::fuzz::scannerDifference(text)) {
        std::fprintf(stderr, "scanner differs from the grammar's lexer: %s\n", difference->c_str());
        std::abort();
    }
    return 0;
}
