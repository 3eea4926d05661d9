// The library POUs written in ST, embedded in the binary at build time by
// stdlib/embed_tool/embed_library.cpp: the standard blocks (stdlib/st/*.st)
// and the vendor libraries (stdlib/libraries/<Library>/*.st). A project
// compiles only the files it mentions (interpreter/project/library_selection.h).
#pragma once

#include <string_view>
#include <vector>

namespace strun::stdlib {

struct EmbeddedSource {
    std::string_view path;     // "stdlib/timers.st", "stdlib/Tc2_System/Tc2_System.st"
    std::string_view text;
    std::string_view library;  // "Tc2_System"; "" for the standard blocks of stdlib/st
};

const std::vector<EmbeddedSource>& embeddedSources();

}  // namespace strun::stdlib
