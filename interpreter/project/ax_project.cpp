#include "interpreter/project/ax_project.h"

#include <filesystem>
#include <set>
#include <system_error>

namespace strun::project {

bool isAxProject(const std::vector<std::string>& paths) {
    namespace fs = std::filesystem;
    std::set<fs::path> seen;  // folders already looked at: a project's files share them
    for (const std::string& path : paths) {
        std::error_code ec;
        if (path.empty() || path.front() == '<' || !fs::is_regular_file(path, ec)) continue;
        fs::path dir = fs::absolute(fs::path(path), ec).parent_path();
        if (ec) continue;
        // Up to the root: `strun check src/` of an AX project finds the
        // apax.yml of the project folder above src/.
        for (int depth = 0; depth < 64 && !dir.empty() && seen.insert(dir).second; ++depth) {
            if (fs::is_regular_file(dir / "apax.yml", ec)) return true;
            fs::path parent = dir.parent_path();
            if (parent == dir) break;
            dir = parent;
        }
    }
    return false;
}

}  // namespace strun::project
