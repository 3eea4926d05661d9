#include "cli/source_files.h"

#include "interpreter/source/read_source.h"

namespace strun::cli {

bool readSourceFiles(const std::vector<std::string>& paths, SourceSet& sources, std::vector<int>& indices, std::string& error) {
    for (const auto& path : paths) {
        int index = 0;
        if (!readSourceFile(path, sources, index, error)) return false;  // size limits of docs/limits.md
        indices.push_back(index);
    }
    return true;
}

}  // namespace strun::cli
