// docs/diagnostics/ from the catalogue (interpreter/source/diagnostic_catalogue.cpp):
//   diagnostic_docs --write DIR   writes README.md and one CODE.md per code
//   diagnostic_docs --check DIR   exit 1 naming every page that differs, is missing or is left over
// The ctest diagnostics.docs_in_sync runs --check on the committed pages.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "interpreter/source/diagnostic_codes.h"

namespace fs = std::filesystem;
using namespace strun::diagnostics;

int main(int argc, char** argv) {
    if (argc != 3 || (std::string(argv[1]) != "--write" && std::string(argv[1]) != "--check")) {
        std::cerr << "usage: diagnostic_docs --write|--check DIR\n";
        return 2;
    }
    const bool write = std::string(argv[1]) == "--write";
    const fs::path dir = argv[2];
    std::map<std::string, std::string> pages{{"README.md", markdownIndex()}};
    for (const CodeInfo& info : catalogue()) pages[std::string(info.code) + ".md"] = markdownPage(info);
    if (write) {
        fs::create_directories(dir);
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().extension() == ".md" && !pages.count(entry.path().filename().string())) fs::remove(entry.path());
        for (const auto& [name, text] : pages) std::ofstream(dir / name, std::ios::binary) << text;
        std::cout << "wrote " << pages.size() << " pages into " << dir.string() << "\n";
        return 0;
    }
    int problems = 0;
    for (const auto& [name, text] : pages) {
        std::ifstream in(dir / name, std::ios::binary);
        std::stringstream committed;
        committed << in.rdbuf();
        if (!in) {
            std::cerr << "missing: " << (dir / name).string() << "\n";
            ++problems;
        } else if (committed.str() != text) {
            std::cerr << "differs from the catalogue: " << (dir / name).string() << "\n";
            ++problems;
        }
    }
    if (fs::is_directory(dir))
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().extension() == ".md" && !pages.count(entry.path().filename().string())) {
                std::cerr << "not in the catalogue: " << entry.path().string() << "\n";
                ++problems;
            }
    if (problems) std::cerr << "regenerate with: build/tests/diagnostic_docs --write docs/diagnostics\n";
    return problems ? 1 : 0;
}
