// Which embedded standard-library files a project needs. Parsing and checking
// the whole ST library on every run dominated start-up, so a project gets
// only the files that declare a name it mentions, plus, transitively, the
// files those mention. The scan is lexical and case-insensitive: a name in a
// comment or string may pull in a file it does not need, never the reverse.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "stdlib/embedded_sources.h"

namespace strun::project {

// In the order of embeddedSources().
std::vector<const stdlib::EmbeddedSource*> embeddedSourcesFor(const std::vector<std::string_view>& projectTexts);

// Every block type (FUNCTION_BLOCK, INTERFACE) and FUNCTION an embedded file
// declares, as written, found by the same lexical scan: the "did you mean"
// candidates of the files a project did not select (`TONN` -> 'TON').
struct LibraryNames {
    std::vector<std::string> types, functions;
};
const LibraryNames& embeddedLibraryNames();

}  // namespace strun::project
