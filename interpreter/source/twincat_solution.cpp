#include "interpreter/source/twincat_solution.h"

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "interpreter/source/read_source.h"
#include "stdlib/number_scan.h"

namespace strun::source {

namespace {

namespace fs = std::filesystem;

// The files directly in `dir` whose extension (lower case) is `ext`, sorted.
std::vector<fs::path> filesIn(const fs::path& dir, const std::string& ext) {
    std::vector<fs::path> found;
    std::error_code ec;
    for (fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && stdlib::lowerAscii(it->path().extension().string()) == ext) found.push_back(it->path());
    std::sort(found.begin(), found.end());
    return found;
}

// Whether the file at `path` has a `PrjFilePath="..."` attribute whose
// file name is `plcprojName` (lower case; Windows paths ignore case). A file
// that cannot be read names nothing.
bool namesProjectFile(const fs::path& path, const std::string& plcprojName) {
    std::string text, unused;
    if (!readSourceText(path.string(), 0, text, unused)) return false;
    const std::string lower = stdlib::lowerAscii(text);
    static constexpr std::string_view kAttribute = "prjfilepath=\"";
    for (size_t at = lower.find(kAttribute); at != std::string::npos; at = lower.find(kAttribute, at + 1)) {
        const size_t begin = at + kAttribute.size();
        const size_t end = lower.find('"', begin);
        if (end == std::string::npos) return false;
        std::string value = lower.substr(begin, end - begin);
        const size_t slash = value.find_last_of("\\/");
        if ((slash == std::string::npos ? value : value.substr(slash + 1)) == plcprojName) return true;
    }
    return false;
}

// Whether the solution `tsproj` names the project file `plcprojName` (lower
// case): in the .tsproj itself (`PrjFilePath="Plc\Plc.plcproj"`) or in an
// independent project file of its PLC configuration (`_Config/PLC/Plc.xti`).
bool solutionNames(const fs::path& tsproj, const std::string& plcprojName) {
    if (namesProjectFile(tsproj, plcprojName)) return true;
    for (const fs::path& xti : filesIn(tsproj.parent_path() / "_Config" / "PLC", ".xti"))
        if (namesProjectFile(xti, plcprojName)) return true;
    return false;
}

}  // namespace

std::vector<std::string> enclosingTwinCatTypeSystems(const std::vector<std::string>& plcProjects) {
    std::vector<std::string> typeSystems;
    for (const std::string& project : plcProjects) {
        const fs::path plcproj = fs::absolute(project).lexically_normal();
        const std::string name = stdlib::lowerAscii(plcproj.filename().string());
        fs::path dir = plcproj.parent_path();
        for (int level = 0; level < 2 && dir.has_parent_path() && dir != dir.parent_path(); ++level) {
            dir = dir.parent_path();
            bool taken = false;
            for (const fs::path& tsproj : filesIn(dir, ".tsproj")) {
                if (!solutionNames(tsproj, name)) continue;
                if (std::find(typeSystems.begin(), typeSystems.end(), tsproj.string()) == typeSystems.end()) {
                    typeSystems.push_back(tsproj.string());
                    for (const fs::path& tmc : filesIn(dir, ".tmc")) typeSystems.push_back(tmc.string());
                }
                taken = true;
            }
            if (taken) break;
        }
    }
    return typeSystems;
}

}  // namespace strun::source
