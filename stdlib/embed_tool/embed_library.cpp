// embed_library: the build step that puts strun's ST library into the binary.
//
//   embed_library OUT.cpp ST_DIR LIBRARIES_DIR
//
// Writes OUT.cpp holding
//   - every ST_DIR/*.st (the IEC standard blocks and TcUnit) and every
//     LIBRARIES_DIR/<Library>/*.st as an EmbeddedSource (stdlib/embedded_sources.h),
//   - the library registry (stdlib/library_registry.h): every library folder
//     with its vendor and status (LIBRARIES_DIR/<Library>/library.txt), and
//     one row per name a library provides or is known to have, sorted by
//     upper-case name: the names the .st files declare (POUs, types, enumeration
//     values, global variables), the native functions library.txt lists, and
//     the names of the library strun does not provide.
// The scan runs here, once per build, so that start-up never reads the
// library texts to learn what they declare (decision 0220).
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "stdlib/library_mentions.h"

namespace fs = std::filesystem;

namespace {

struct Name {
    std::string upper, written, library;
    char kind;   // F function, B function block, I interface, P program, N namespace, T type,
                 // E enumeration value, G global variable, X native function, U not provided,
                 // Q qualified_only namespace (selects only as `Q.x`)
    int file;    // index of the embedded source, -1 for X and U
};

struct Library {
    std::string name, vendor, status, summary;
    // `selected_by: namespace`: only its dotted namespace written with its dot
    // (`AxUnit.`) selects it; the names it declares (AxUnit's `Equal`) do not.
    bool selectedByNamespace = false;
};

std::string upperOf(std::string_view s) { return strun::stdlib::upperAscii(s); }

bool isWordStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A token of the declaration scan: a word, or one significant character.
struct Token {
    std::string text;  // the word as written, or the character
    bool word;
};

// The tokens of ST text without comments, pragmas and string literals.
std::vector<Token> tokens(const std::string& t) {
    std::vector<Token> out;
    size_t i = 0, n = t.size();
    while (i < n) {
        char c = t[i];
        if (c == '(' && i + 1 < n && t[i + 1] == '*') {
            size_t e = t.find("*)", i + 2);
            i = e == std::string::npos ? n : e + 2;
        } else if (c == '/' && i + 1 < n && t[i + 1] == '*') {
            size_t e = t.find("*/", i + 2);
            i = e == std::string::npos ? n : e + 2;
        } else if (c == '/' && i + 1 < n && t[i + 1] == '/') {
            size_t e = t.find('\n', i);
            i = e == std::string::npos ? n : e;
        } else if (c == '{') {
            size_t e = t.find('}', i);
            // {attribute 'qualified_only'}: the next TYPE's values are reached only qualified.
            if (t.substr(i, e == std::string::npos ? std::string::npos : e - i).find("qualified_only") != std::string::npos)
                out.push_back({"{Q", false});
            i = e == std::string::npos ? n : e + 1;
        } else if (c == '\'' || c == '"') {
            size_t j = i + 1;
            while (j < n && t[j] != c) j += t[j] == '$' ? 2 : 1;
            i = j + 1;
        } else if (isWordStart(c)) {
            size_t j = i;
            while (j < n && isWordChar(t[j])) ++j;
            out.push_back({t.substr(i, j - i), true});
            i = j;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            while (i < n && (isWordChar(t[i]) || t[i] == '#' || t[i] == '.')) ++i;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else {
            out.push_back({std::string(1, c), false});
            ++i;
        }
    }
    return out;
}

// The names one library file declares.
void scanDeclarations(const std::string& text, const std::string& library, int file, std::vector<Name>& out) {
    const std::vector<Token> tk = tokens(text);
    enum class Block { None, Type, Globals };
    Block block = Block::None;
    int structDepth = 0, parenDepth = 0;
    bool pendingQualified = false, qualified = false;  // enumeration values of a qualified_only TYPE are not names of their own
    // The names inside a qualified_only NAMESPACE (CODESYS' "QualifiedOnly"
    // libraries, such as CAA Types' CAA) are reached only through the
    // namespace, so only its name selects the file, as kind Q (selected only
    // where the project writes `CAA.x`): a project's own COUNT or HANDLE must
    // not pull in CAA.COUNT (decision 0323).
    int namespaceDepth = 0, qualifiedNamespaceDepth = 0;  // 0: not inside a qualified_only namespace
    // The row of a dotted namespace is found by its first name (`System`).
    auto add = [&](const std::string& w, char kind) {
        if (qualifiedNamespaceDepth == 0) out.push_back({upperOf(w.substr(0, w.find('.'))), w, library, kind, file});
    };
    auto at = [&](size_t k) -> const Token* { return k < tk.size() ? &tk[k] : nullptr; };
    auto isChar = [&](size_t k, char c) { const Token* t = at(k); return t && !t->word && t->text[0] == c; };
    for (size_t k = 0; k < tk.size(); ++k) {
        const Token& t = tk[k];
        if (!t.word) {
            if (t.text == "{Q") {
                pendingQualified = true;
                continue;
            }
            if (block == Block::Type) {
                if (t.text == "(") ++parenDepth;
                if (t.text == ")") --parenDepth;
            }
            continue;
        }
        const std::string u = upperOf(t.text);
        if (u == "END_NAMESPACE") {
            if (namespaceDepth == qualifiedNamespaceDepth) qualifiedNamespaceDepth = 0;
            if (namespaceDepth > 0) --namespaceDepth;
            continue;
        }
        if (u == "END_TYPE" || u == "END_VAR") {
            block = Block::None;
            continue;
        }
        if (u == "FUNCTION_BLOCK" || u == "FUNCTION" || u == "INTERFACE" || u == "PROGRAM" || u == "NAMESPACE") {
            const Token* next = at(k + 1);
            if (next && next->word) {
                std::string name = next->text;
                // FUNCTION_BLOCK ABSTRACT/FINAL/PUBLIC X
                size_t j = k + 1;
                while (at(j) && at(j)->word &&
                       (upperOf(at(j)->text) == "ABSTRACT" || upperOf(at(j)->text) == "FINAL" || upperOf(at(j)->text) == "PUBLIC" ||
                        upperOf(at(j)->text) == "INTERNAL"))
                    ++j;
                if (at(j) && at(j)->word) name = at(j)->text;
                // A dotted namespace (SIMATIC AX's System.Timer) is always written
                // with its dot, in `USING System.Timer;` too: kind Q, recorded
                // under its first name and written whole, so that only its whole
                // path selects it (not "system" in a comment, not System.Strings).
                const bool dotted = u == "NAMESPACE" && isChar(j + 1, '.');
                size_t last = j;
                while (u == "NAMESPACE" && isChar(last + 1, '.') && at(last + 2) && at(last + 2)->word) {
                    name += "." + at(last + 2)->text;
                    last += 2;
                }
                const bool qualifiedNamespace = u == "NAMESPACE" && (pendingQualified || dotted);
                add(name, u == "FUNCTION_BLOCK" ? 'B' : u == "FUNCTION" ? 'F' : u == "INTERFACE" ? 'I' : u == "PROGRAM" ? 'P' : qualifiedNamespace ? 'Q' : 'N');
                if (u == "NAMESPACE") {
                    ++namespaceDepth;
                    if (pendingQualified && qualifiedNamespaceDepth == 0) qualifiedNamespaceDepth = namespaceDepth;
                    pendingQualified = false;
                }
                k = last;
            }
            continue;
        }
        if (u == "TYPE") {
            block = Block::Type;
            structDepth = parenDepth = 0;
            qualified = pendingQualified;
            pendingQualified = false;
            continue;
        }
        if (u == "VAR_GLOBAL") {
            block = Block::Globals;
            continue;
        }
        if (block == Block::Type) {
            if (u == "STRUCT" || u == "UNION") ++structDepth;
            if (u == "END_STRUCT" || u == "END_UNION") --structDepth;
            if (structDepth == 0 && parenDepth == 0 && isChar(k + 1, ':') && !isChar(k + 2, '=')) add(t.text, 'T');
            // Enumeration values: words directly inside the type's parentheses, after '(' or ','.
            if (!qualified && structDepth == 0 && parenDepth == 1 && k > 0 && (isChar(k - 1, '(') || isChar(k - 1, ','))) add(t.text, 'E');
        } else if (block == Block::Globals) {
            const bool starts = k > 0 && (isChar(k - 1, ';') || isChar(k - 1, ',') || (tk[k - 1].word && (upperOf(tk[k - 1].text) == "VAR_GLOBAL" ||
                                                                                                     upperOf(tk[k - 1].text) == "CONSTANT" ||
                                                                                                     upperOf(tk[k - 1].text) == "PERSISTENT" ||
                                                                                                     upperOf(tk[k - 1].text) == "RETAIN")));
            if (starts && (isChar(k + 1, ',') || (isChar(k + 1, ':') && !isChar(k + 2, '=')))) add(t.text, 'G');
        }
    }
}

// The text with its comments, strings and pragmas blanked out: what a
// library file uses is in its code, not in what its comments say ("the
// system time" does not need SIMATIC AX's System namespaces). `(* *)` nests,
// as the scanner has it (interpreter/ast/st_scanner.cpp).
std::string codeOnly(const std::string& t) {
    std::string out = t;
    auto blank = [&](size_t from, size_t to) {
        for (size_t k = from; k < to && k < out.size(); ++k)
            if (out[k] != '\n') out[k] = ' ';
    };
    size_t i = 0;
    const size_t n = t.size();
    while (i < n) {
        const char c = t[i];
        const char c1 = i + 1 < n ? t[i + 1] : '\0';
        size_t end = i + 1;
        if (c == '(' && c1 == '*') {
            int depth = 1;
            end = i + 2;
            while (end < n && depth > 0) {
                if (t[end] == '(' && end + 1 < n && t[end + 1] == '*') ++depth, end += 2;
                else if (t[end] == '*' && end + 1 < n && t[end + 1] == ')') --depth, end += 2;
                else ++end;
            }
        } else if (c == '/' && c1 == '*') {
            const size_t e = t.find("*/", i + 2);
            end = e == std::string::npos ? n : e + 2;
        } else if (c == '/' && c1 == '/') {
            const size_t e = t.find('\n', i);
            end = e == std::string::npos ? n : e;
        } else if (c == '{') {
            const size_t e = t.find('}', i);
            end = e == std::string::npos ? n : e + 1;
        } else if (c == '\'' || c == '"') {
            end = i + 1;
            while (end < n && t[end] != c && t[end] != '\n') end += t[end] == '$' ? 2 : 1;
            end = std::min(end + 1, n);
        } else {
            i = end;
            continue;
        }
        blank(i, end);
        i = end;
    }
    return out;
}

// What one library file's code needs, by the rule a project's text is
// scanned with (stdlib/library_mentions.h): the other files it selects and
// the libraries whose native functions it calls.
struct FileUses {
    std::set<int> files;
    std::set<std::string> natives;
};
FileUses usesOf(const std::string& text, int self, const std::vector<Name>& sortedNames) {
    namespace m = strun::stdlib::mentions;
    FileUses uses;
    const std::string code = codeOnly(text);
    m::forEachWord(code, [&](std::string_view word, size_t end, bool afterUsing) {
        const std::string key = upperOf(std::string(m::edgeBlock(word)));
        auto lo = std::lower_bound(sortedNames.begin(), sortedNames.end(), key, [](const Name& a, const std::string& k) { return a.upper < k; });
        for (auto it = lo; it != sortedNames.end() && it->upper == key; ++it) {
            if (it->kind == 'X') uses.natives.insert(it->library);
            else if (it->file >= 0 && it->file != self && m::mentionSelects(it->kind, it->written, code, end, afterUsing)) uses.files.insert(it->file);
        }
    });
    return uses;
}

// library.txt: `key: value` lines; `native:` and `absent:` may repeat and
// take blank-separated names; `#` starts a comment line.
Library readLibraryFile(const fs::path& p, const std::string& name, std::vector<Name>& out) {
    Library lib{name, "", "", ""};
    std::istringstream in(readFile(p));
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::string key = line.substr(0, colon), value = line.substr(colon + 1);
        while (!value.empty() && std::isspace(static_cast<unsigned char>(value.front()))) value.erase(value.begin());
        while (!value.empty() && std::isspace(static_cast<unsigned char>(value.back()))) value.pop_back();
        if (key == "vendor") lib.vendor = value;
        else if (key == "status") lib.status = value;
        else if (key == "summary") lib.summary = value;
        else if (key == "selected_by" && value == "namespace") lib.selectedByNamespace = true;
        else if (key == "native" || key == "absent") {
            std::istringstream words(value);
            for (std::string w; words >> w;) out.push_back({upperOf(w), w, name, key == "native" ? 'X' : 'U', -1});
        } else {
            std::cerr << p.string() << ": unknown key '" << key << "'\n";
            std::exit(1);
        }
    }
    if (lib.status != "real" && lib.status != "partial" && lib.status != "interface" && lib.status != "absent") {
        std::cerr << p.string() << ": status must be real, partial, interface or absent\n";
        std::exit(1);
    }
    return lib;
}

std::vector<fs::path> sortedFiles(const fs::path& dir, const std::string& ext) {
    std::vector<fs::path> files;
    if (fs::is_directory(dir))
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file() && e.path().extension() == ext) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// A C++ raw string literal of any text (split where the delimiter would end it).
std::string rawLiteral(const std::string& text) {
    std::string out = "R\"strun_st(";
    size_t at = 0;
    for (size_t hit; (hit = text.find(")strun_st\"", at)) != std::string::npos; at = hit + 1) out += text.substr(at, hit + 1 - at) + ")strun_st\" R\"strun_st(";
    return out + text.substr(at) + ")strun_st\"";
}

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: embed_library OUT.cpp ST_DIR LIBRARIES_DIR\n";
        return 2;
    }
    struct Source {
        std::string path, library, text;
    };
    std::vector<Source> sources;
    std::vector<Name> names;
    std::vector<Library> libraries;
    for (const fs::path& f : sortedFiles(argv[2], ".st")) sources.push_back({"stdlib/" + f.filename().string(), "", readFile(f)});
    std::vector<fs::path> dirs;
    if (fs::is_directory(argv[3]))
        for (const auto& e : fs::directory_iterator(argv[3]))
            if (e.is_directory()) dirs.push_back(e.path());
    std::sort(dirs.begin(), dirs.end());
    for (const fs::path& dir : dirs) {
        const std::string lib = dir.filename().string();
        if (!fs::exists(dir / "library.txt")) {
            std::cerr << dir.string() << ": no library.txt\n";
            return 1;
        }
        libraries.push_back(readLibraryFile(dir / "library.txt", lib, names));
        for (const fs::path& f : sortedFiles(dir, ".st")) sources.push_back({"stdlib/" + lib + "/" + f.filename().string(), lib, readFile(f)});
    }
    for (size_t i = 0; i < sources.size(); ++i) scanDeclarations(sources[i].text, sources[i].library, static_cast<int>(i), names);
    for (const Library& lib : libraries)
        if (lib.selectedByNamespace) {
            names.erase(std::remove_if(names.begin(), names.end(), [&](const Name& n) { return n.library == lib.name && n.kind != 'Q' && n.kind != 'X'; }),
                        names.end());
            // Its namespace selects it also in `USING AxUnit;` (kind N); a
            // dotted one (`USING System.Strings;`) stays Q: only its path selects it.
            for (Name& n : names)
                if (n.library == lib.name && n.kind == 'Q' && n.written.find('.') == std::string::npos) n.kind = 'N';
        }
    std::sort(names.begin(), names.end(), [](const Name& a, const Name& b) {
        return a.upper != b.upper ? a.upper < b.upper : a.file != b.file ? a.file < b.file : a.kind < b.kind;
    });
    names.erase(std::unique(names.begin(), names.end(),
                            [](const Name& a, const Name& b) { return a.upper == b.upper && a.file == b.file && a.kind == b.kind; }),
                names.end());

    std::ostringstream o;
    o << "// generated by stdlib/embed_tool/embed_library.cpp: do not edit\n"
         "#include \"stdlib/embedded_sources.h\"\n#include \"stdlib/library_registry.h\"\n"
         "namespace strun::stdlib {\n"
         "const std::vector<EmbeddedSource>& embeddedSources() {\n  static const std::vector<EmbeddedSource> sources = {\n";
    for (const Source& s : sources) o << "    {" << quoted(s.path) << ", " << rawLiteral(s.text) << ", " << quoted(s.library) << "},\n";
    o << "  };\n  return sources;\n}\n";
    o << "static constexpr LibraryInfo kLibraries[] = {\n";
    for (const Library& l : libraries)
        o << "    {" << quoted(l.name) << ", " << quoted(l.vendor) << ", " << quoted(l.status) << ", " << quoted(l.summary) << "},\n";
    o << "};\nstd::span<const LibraryInfo> libraries() { return kLibraries; }\n";
    o << "static constexpr LibraryName kNames[] = {\n";
    for (const Name& n : names)
        o << "    {" << quoted(n.upper) << ", " << quoted(n.written) << ", " << quoted(n.library) << ", '" << n.kind << "', " << n.file << "},\n";
    o << "};\nstd::span<const LibraryName> libraryNames() { return kNames; }\n";
    // Each file's uses (library_registry.h): start-up follows these lists
    // instead of scanning the texts of the files it selects.
    std::ostringstream fileList, nativeList, ranges;
    size_t fileCount = 0, nativeCount = 0;
    for (size_t i = 0; i < sources.size(); ++i) {
        const FileUses uses = usesOf(sources[i].text, static_cast<int>(i), names);
        ranges << "    {" << fileCount << ", " << uses.files.size() << ", " << nativeCount << ", " << uses.natives.size() << "},\n";
        for (int f : uses.files) fileList << " " << f << ",";
        for (const std::string& lib : uses.natives) nativeList << " " << quoted(lib) << ",";
        fileCount += uses.files.size();
        nativeCount += uses.natives.size();
    }
    o << "static constexpr int kUsedFiles[] = {" << fileList.str() << " -1};\n";
    o << "static constexpr std::string_view kUsedNatives[] = {" << nativeList.str() << " \"\"};\n";
    o << "static constexpr struct { size_t files, fileCount, natives, nativeCount; } kUses[] = {\n" << ranges.str() << "};\n";
    o << "std::span<const int> libraryFileUses(size_t file) { return {kUsedFiles + kUses[file].files, kUses[file].fileCount}; }\n";
    o << "std::span<const std::string_view> libraryFileNatives(size_t file) { return {kUsedNatives + kUses[file].natives, kUses[file].nativeCount}; }\n";
    // The letter masks of the selecting names (library_registry.h), computed
    // here so that start-up does not walk the whole registry to build them.
    uint64_t byFirst[256] = {}, byLast[256] = {};
    std::vector<uint64_t> hashSet((size_t{1} << strun::stdlib::mentions::kNameHashBits) / 64);
    for (const Name& n : names) {
        if (n.kind == 'U' || n.upper.empty()) continue;
        strun::stdlib::mentions::addNameHash(hashSet, n.upper);
        if (n.upper.size() >= 64) continue;  // the masks pass every word this long
        const uint64_t bit = uint64_t{1} << n.upper.size();
        for (unsigned char c : {static_cast<unsigned char>(n.upper.front()), static_cast<unsigned char>(std::tolower(static_cast<unsigned char>(n.upper.front())))})
            byFirst[c] |= bit;
        for (unsigned char c : {static_cast<unsigned char>(n.upper.back()), static_cast<unsigned char>(std::tolower(static_cast<unsigned char>(n.upper.back())))})
            byLast[c] |= bit;
    }
    auto masks = [&](const char* name, const uint64_t* m) {
        o << "static constexpr uint64_t " << name << "[256] = {";
        for (int c = 0; c < 256; ++c) o << (c % 8 == 0 ? "\n   " : "") << " 0x" << std::hex << m[c] << std::dec << "u,";
        o << "\n};\n";
    };
    masks("kMaskByFirst", byFirst);
    masks("kMaskByLast", byLast);
    o << "static constexpr uint64_t kNameHashSet[] = {";
    for (size_t i = 0; i < hashSet.size(); ++i) o << (i % 8 == 0 ? "\n   " : "") << " 0x" << std::hex << hashSet[i] << std::dec << "u,";
    o << "\n};\n";
    o << "std::span<const uint64_t> libraryNameHashSet() { return kNameHashSet; }\n";
    o << "std::span<const uint64_t, 256> libraryNameMasksByFirst() { return std::span<const uint64_t, 256>(kMaskByFirst); }\n"
         "std::span<const uint64_t, 256> libraryNameMasksByLast() { return std::span<const uint64_t, 256>(kMaskByLast); }\n";
    o << "}  // namespace strun::stdlib\n";
    const std::string text = o.str();
    const fs::path out = argv[1];
    if (fs::exists(out) && readFile(out) == text) return 0;  // unchanged: nothing rebuilds
    std::ofstream(out, std::ios::binary) << text;
    return 0;
}
