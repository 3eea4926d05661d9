// The code of a compile diagnostic, given where the diagnostic is raised
// (decision 0298): `error(diag::E0101, loc, "undeclared identifier ...")`.
// The code belongs to the call site, so rewording a message can never change
// or lose its code. One constant per E/W code of the catalogue
// (diagnostic_catalogue.cpp); the unit test `diagnostic codes: every typed
// code is in the catalogue` keeps the two lists together.
//
// There is no way to report a compile diagnostic without its code: the
// CompileLog has no such overload, so a new call site cannot forget it
// (docs/diagnostics.md, "Adding a diagnostic").
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace strun::diag {

#define STRUN_DIAGNOSTIC_CODES(X)                                                                                          \
    X(E0001) X(E0002) X(E0003) X(E0004) X(E0005) X(E0006) X(E0007) X(E0008) X(E0009) X(E0010) X(E0011)                \
    X(E0101) X(E0102) X(E0103) X(E0104) X(E0105) X(E0106) X(E0107) X(E0108) X(E0109)                                   \
    X(E0201) X(E0202) X(E0203) X(E0204) X(E0205) X(E0206) X(E0207)                                                     \
    X(E0301) X(E0302) X(E0303) X(E0304)                                                                                 \
    X(E0401) X(E0402) X(E0403) X(E0405) X(E0406) X(E0407) X(E0408)                                                     \
    X(E0501) X(E0502) X(E0503) X(E0504)                                                                                 \
    X(E0601) X(E0602)                                                                                                   \
    X(W0001) X(W0002) X(W0003) X(W0004) X(W0005) X(W0006) X(W0007) X(W0008) X(W0009) X(W0010) X(W0011) X(W0012)        \
    X(W0013) X(W0014) X(W0015) X(W0016) X(W0017) X(W0040) X(W0041) X(W0042) X(W0043) X(W0044) X(W0045)

enum class Code : uint8_t {
#define STRUN_DIAGNOSTIC_CODE_ENUMERATOR(c) c,
    STRUN_DIAGNOSTIC_CODES(STRUN_DIAGNOSTIC_CODE_ENUMERATOR)
#undef STRUN_DIAGNOSTIC_CODE_ENUMERATOR
};

// diag::E0101 rather than diag::Code::E0101 at the many call sites.
#define STRUN_DIAGNOSTIC_CODE_CONSTANT(c) inline constexpr Code c = Code::c;
STRUN_DIAGNOSTIC_CODES(STRUN_DIAGNOSTIC_CODE_CONSTANT)
#undef STRUN_DIAGNOSTIC_CODE_CONSTANT

// "E0101".
constexpr std::string_view text(Code code) {
    switch (code) {
#define STRUN_DIAGNOSTIC_CODE_TEXT(c) \
    case Code::c:                     \
        return #c;
        STRUN_DIAGNOSTIC_CODES(STRUN_DIAGNOSTIC_CODE_TEXT)
#undef STRUN_DIAGNOSTIC_CODE_TEXT
    }
    return "E0999";
}

// Every code, in the order above (the unit test walks it).
inline constexpr Code kAllCodes[] = {
#define STRUN_DIAGNOSTIC_CODE_ITEM(c) Code::c,
    STRUN_DIAGNOSTIC_CODES(STRUN_DIAGNOSTIC_CODE_ITEM)
#undef STRUN_DIAGNOSTIC_CODE_ITEM
};

// The code named "E0101", if there is one (codes carried as text, e.g. by a
// diagnostic that replaces others).
constexpr std::optional<Code> fromText(std::string_view name) {
    for (Code code : kAllCodes)
        if (text(code) == name) return code;
    return std::nullopt;
}

// A warning code (W....): `error(W0001, ...)` is a --strict error that keeps its warning's code.
constexpr bool isWarning(Code code) { return text(code)[0] == 'W'; }

}  // namespace strun::diag
