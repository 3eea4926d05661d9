#include "cli/source_files.h"

#include <fstream>
#include <sstream>

namespace strun::cli {

bool readSourceFiles(const std::vector<std::string>& paths, SourceSet& sources, std::vector<int>& indices, std::string& error) {
    for (const auto& path : paths) {
        std::ifstream in(path, std::ios::binary);
        std::stringstream text;
        if (in) text << in.rdbuf();
        if (!in || in.bad()) {
            error = "cannot read '" + path + "'";
            return false;
        }
        indices.push_back(sources.add(path, text.str()));
    }
    return true;
}

}  // namespace strun::cli
