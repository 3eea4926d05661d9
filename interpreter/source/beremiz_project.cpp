#include "interpreter/source/beremiz_project.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <optional>

#include "interpreter/source/xml_conversion.h"
#include "stdlib/number_scan.h"

namespace strun::source {

namespace {

namespace fs = std::filesystem;

std::string fileName(const std::string& path) { return stdlib::lowerAscii(fs::path(path).filename().string()); }

// A folder as a key: lexically normal, "" for the current directory.
std::string folderKey(const fs::path& folder) {
    std::string key = folder.lexically_normal().generic_string();
    if (key == "." || key == "./") key.clear();
    if (key.size() > 1 && key.back() == '/') key.pop_back();
    return key;
}
std::string folderOf(const std::string& path) { return folderKey(fs::path(path).parent_path()); }

// The key of the folder of the Beremiz project that holds `path` (the
// innermost one, should projects nest), or nullopt.
std::optional<std::string> projectFolderOf(const std::string& path, const std::map<std::string, BeremizFolder>& folders) {
    for (fs::path p = fs::path(path).lexically_normal().parent_path();; p = p.parent_path()) {
        if (folders.count(folderKey(p))) return folderKey(p);
        if (p.empty() || p == p.parent_path()) return std::nullopt;
    }
}

}  // namespace

std::vector<BeremizFolder> takeBeremizFolders(std::vector<std::string>& found) {
    std::map<std::string, std::string> settings, programs;  // folder -> its beremiz.xml / plc.xml
    for (const std::string& f : found) {
        if (fileName(f) == "beremiz.xml") settings[folderOf(f)] = f;
        if (fileName(f) == "plc.xml") programs[folderOf(f)] = f;
    }
    std::map<std::string, BeremizFolder> folders;
    for (const auto& [folder, file] : settings)
        if (programs.count(folder)) {
            folders[folder].settings = file;
            folders[folder].program = programs.at(folder);
        }
    if (folders.empty()) return {};
    std::erase_if(found, [&](const std::string& f) {
        const std::optional<std::string> under = projectFolderOf(f, folders);
        if (!under) return false;
        const std::string& folder = *under;
        if (f == programs.at(folder)) return false;  // the project itself
        if (f != folders.at(folder).settings) folders.at(folder).skipped.push_back(f);
        return true;
    });
    std::vector<BeremizFolder> result;
    for (auto& [folder, project] : folders) result.push_back(std::move(project));
    return result;
}

std::string beremizSkipReason(const BeremizFolder& folder, const std::string& skipped) {
    const fs::path root = fs::path(folder.settings).parent_path().lexically_normal();
    const fs::path relative = fs::path(skipped).lexically_normal().lexically_relative(root);
    const std::string first = relative.empty() ? std::string() : stdlib::lowerAscii(relative.begin()->string());
    if (first == "build" && std::distance(relative.begin(), relative.end()) > 1)
        return "'" + relative.generic_string() + "' skipped: the build output Beremiz generates from plc.xml";
    if (stdlib::lowerAscii(relative.extension().string()) == ".xml") return "'" + relative.generic_string() + "' skipped: a Beremiz settings file, not a program";
    return "'" + relative.generic_string() + "' skipped: Beremiz compiles plc.xml alone (an ST export of it?)";
}

Converted readBeremizExtensionGlobals(const std::string& xml, const std::string& path) {
    XmlConversion c(xml);
    pugi::xml_document doc;
    if (!c.load(doc)) return {};
    const pugi::xml_node root = doc.document_element();
    const std::string kind = root.name();
    // The MQTT client extension (folder `name@mqtt`) declares its connection
    // status MQTT_STATUS_<channel> : INT (Beremiz mqtt/client.py,
    // CTNGlobalInstances); its channel is the IEC_Channel of the folder's
    // baseconfnode.xml (decision 0465). Its topics are located variables of plc.xml.
    const std::string folder = stdlib::lowerAscii(fs::path(path).parent_path().filename().string());
    if (kind == "BaseParams" && fileName(path) == "baseconfnode.xml" && folder.size() > 5 &&
        folder.compare(folder.size() - 5, 5, "@mqtt") == 0 && root.attribute("IEC_Channel")) {
        auto [line, col] = c.where(root);
        c.out.written("VAR_GLOBAL", line, col);
        c.out.written(std::string("    MQTT_STATUS_") + root.attribute("IEC_Channel").value() + " : INT;", line, col);
        c.out.written("END_VAR", line, col);
        c.result.text = std::move(c.out.text());
        c.result.origins = std::move(c.out.origins());
        return std::move(c.result);
    }
    if (kind != "CFile" && kind != "PyFile") return {};
    bool any = false;
    for (const pugi::xml_node v : root.child("variables").children("variable")) {
        const std::string name = v.attribute("name").value(), type = v.attribute("type").value();
        const std::string initial = v.attribute("initial").value();
        auto [line, col] = c.where(v);
        if (name.empty() || type.empty()) {
            c.error(v, "a variable of a Beremiz extension without a name or a type");
            continue;
        }
        if (!any) c.out.written("VAR_GLOBAL", line, col);
        any = true;
        c.out.written("    " + name + " : " + type + (initial.empty() ? "" : " := " + initial) + ";", line, col);
    }
    if (!any) return std::move(c.result);
    c.out.written("END_VAR", 1, 1);
    c.result.text = std::move(c.out.text());
    c.result.origins = std::move(c.out.origins());
    return std::move(c.result);
}

}  // namespace strun::source
