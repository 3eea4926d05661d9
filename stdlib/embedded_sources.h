// The standard-library POUs written in ST (stdlib/st/*.st), embedded in the
// binary at build time by stdlib/embed_st.cmake and compiled with every project.
#pragma once

#include <string_view>
#include <vector>

namespace strun::stdlib {

struct EmbeddedSource {
    std::string_view path;  // "stdlib/timers.st"
    std::string_view text;
};

const std::vector<EmbeddedSource>& embeddedSources();

}  // namespace strun::stdlib
