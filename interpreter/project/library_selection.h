// Which embedded library files and native library functions a project needs.
// Parsing and checking the whole ST library on every run dominated start-up,
// so a project gets only the files that declare a name it mentions, plus,
// transitively, the files those mention (decision 0150), and only the native
// functions of the libraries it names (decision 0220). What each file declares
// and what each library file needs come from the library registry
// (stdlib/library_registry.h), computed at build time. The scan of the
// project is lexical and case-insensitive, by the rule of
// stdlib/library_mentions.h (decision 0421: functions select when called,
// namespaces when qualified): a name in a comment or string may pull in a
// file it does not need, never the reverse.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "stdlib/embedded_sources.h"

namespace strun::project {

struct LibrarySelection {
    std::vector<const stdlib::EmbeddedSource*> files;  // in the order of embeddedSources()
    std::vector<std::string_view> nativeLibraries;     // libraries one of whose native functions is named
};
LibrarySelection selectLibraries(const std::vector<std::string_view>& projectTexts);

// The files of selectLibraries().
std::vector<const stdlib::EmbeddedSource*> embeddedSourcesFor(const std::vector<std::string_view>& projectTexts);

// Every block type (FUNCTION_BLOCK, INTERFACE, TYPE) and function (ST or
// native) the library provides, as written: the "did you mean" candidates
// of the files a project did not select (`TONN` -> 'TON').
struct LibraryNames {
    std::vector<std::string> types, functions;
};
const LibraryNames& embeddedLibraryNames();

}  // namespace strun::project
