// The library registry: which names each vendor library provides, generated
// at build time from stdlib/libraries/<Library>/ (its .st files and its
// library.txt) by stdlib/embed_tool/embed_library.cpp. It answers two
// questions without reading any library text at start-up:
//   - which embedded files and native functions a project needs
//     (interpreter/project/library_selection.h);
//   - where a name the project does not declare comes from ("'FB_SocketConnect'
//     comes from library Tc2_TcpIp"), also for libraries strun does not provide.
// The libraries and their status are listed in docs/libraries.md.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace strun::stdlib {

struct LibraryInfo {
    std::string_view name;     // "Tc2_System"
    std::string_view vendor;   // "Beckhoff", "CODESYS"
    std::string_view status;   // "real", "partial", "interface", "absent"
    std::string_view summary;  // one line for messages and docs
};

struct LibraryName {
    std::string_view upper;    // upper-case, the sort key
    std::string_view written;  // as the library spells it
    std::string_view library;  // "" for the standard blocks of stdlib/st
    char kind;  // F function, B function block, I interface, P program, N namespace, T type,
                // E enumeration value, G global variable, X native function, U not provided by strun,
                // Q a qualified_only namespace (its names are reached only as `Q.x`, decision 0323),
                // or a dotted one (`System.DateTime`: `upper` is its first name, `written` the path)
    int file;   // index into embeddedSources() (F B I P N T E G Q), -1 (X U)
};

std::span<const LibraryInfo> libraries();
// Sorted by `upper`, then file.
std::span<const LibraryName> libraryNames();

// Bit L of [c]: some name that selects a file or native function (kind not
// U) has length L (< 64) and starts (ends) with the byte c, in either case.
// Generated with the registry, so the word scan of library selection tests
// a word without building anything at start-up.
std::span<const uint64_t, 256> libraryNameMasksByFirst();
std::span<const uint64_t, 256> libraryNameMasksByLast();
// Bit mentions::foldedNameHash(name) is set for every such name: the
// second test of the word scan, after the masks (stdlib/library_mentions.h).
std::span<const uint64_t> libraryNameHashSet();

// What the code of embedded file `file` needs, computed at build time by the
// rule a project's text is scanned with (stdlib/library_mentions.h; comments
// and strings do not count): the other files it selects, and the libraries
// whose native functions it calls.
std::span<const int> libraryFileUses(size_t file);
std::span<const std::string_view> libraryFileNatives(size_t file);

// The rows for one name (any case); empty when no library knows it.
std::span<const LibraryName> libraryNamesFor(std::string_view name);
const LibraryInfo* findLibrary(std::string_view name);  // any case; null if unknown

// The help line of a name the project uses but nothing declares, when a
// library has it: "'X' comes from library L (...)"; "" when none does.
std::string libraryHint(std::string_view name);

}  // namespace strun::stdlib
