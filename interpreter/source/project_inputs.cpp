#include "interpreter/source/project_inputs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <system_error>

#include "interpreter/source/beremiz_project.h"
#include "interpreter/source/beremiz_standard_blocks.h"
#include "interpreter/source/read_source.h"
#include "interpreter/source/st_textual_il.h"
#include "interpreter/source/st_textual_sfc.h"
#include "interpreter/source/twincat_event_classes.h"
#include "interpreter/source/twincat_global_types.h"
#include "interpreter/source/twincat_library_namespaces.h"
#include "interpreter/source/twincat_plc_project.h"
#include "interpreter/source/twincat_solution.h"
#include "interpreter/source/twincat_system_event_classes.h"
#include "interpreter/source/xml_inputs.h"

namespace strun::source {

namespace {

namespace fs = std::filesystem;

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::string lowerPath(const fs::path& path) {
    std::string s = path.lexically_normal().generic_string();
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// The bytes of the project's files read so far, for the project size limit.
std::size_t projectBytes(const SourceSet& sources) {
    std::size_t total = 0;
    for (int k = 0; k < sources.size(); ++k) total += sources.file(k).text.size();
    return total;
}

// A TwinCAT project folder with .plcproj files: the TwinCAT objects none of
// them compiles are left out, as TwinCAT leaves them out of the build, and
// the libraries they reference are noted (decision 0279). A .plcproj that
// cannot be read, or lists no file, changes nothing.
void applyPlcProjects(const std::vector<std::string>& plcProjects, std::vector<std::string>& found, SourceSet& sources,
                      std::vector<std::string>& pinnedTypes, std::vector<GivenPlcProject>& given) {
    std::set<std::string> compiled;
    bool listsFiles = false;
    for (const std::string& path : plcProjects) {
        std::string text, unused;
        if (!readSourceText(path, projectBytes(sources), text, unused)) continue;
        PlcProject project;
        if (!readPlcProject(text, project, unused)) continue;
        listsFiles = listsFiles || !project.compiled.empty();
        for (const std::string& file : project.compiled) compiled.insert(lowerPath(fs::path(path).parent_path() / file));
        for (const std::string& library : project.libraries) sources.addReferencedLibrary(library);
        pinnedTypes.insert(pinnedTypes.end(), project.pinnedTypes.begin(), project.pinnedTypes.end());
        for (const std::string& type : project.pinnedTypes) sources.addPinnedType(type);
        given.push_back({fs::path(path).parent_path().string(), std::move(project)});
    }
    if (!listsFiles) return;
    std::erase_if(found, [&](const std::string& f) { return isTwinCatObject(f) && !compiled.count(lowerPath(f)); });
}

// A file converted to ST into the SourceSet, with the errors of its conversion.
void addConverted(const std::string& path, std::string text, Converted converted, SourceSet& sources, std::vector<int>& userFiles,
                  CompileLog& log) {
    if (!converted.errors.empty() || !converted.warnings.empty()) {
        // Positions of these messages are in the XML itself: a view of the file without conversion.
        int raw = sources.add(path, "", {}, text);
        for (const auto& w : converted.warnings) log.warning(diag::W0043, ast::Loc{raw, w.line, w.col}, w.message);
        // Whatever the readers could not convert makes the file unusable as a source: E0008.
        for (const auto& e : converted.errors) log.error(diag::E0008, ast::Loc{raw, e.line, e.col}, e.message);
    }
    // The XML stays beside the ST made from it: diagnostics quote the file the user has.
    userFiles.push_back(sources.add(path, std::move(converted.text), std::move(converted.origins), std::move(text)));
}

// One file into the SourceSet: converted when it is XML.
void addFile(const std::string& path, std::string text, SourceSet& sources, std::vector<int>& userFiles, CompileLog& log,
             bool foundInDirectory) {
    const std::string ext = lowerExtension(path);
    Converted converted;
    if (isTwinCatObject(path)) {
        converted = readTwinCat(text);
    } else if (ext == ".xml") {
        if (!isPlcOpenProject(text)) {
            int raw = sources.add(path, "", {}, text);
            if (foundInDirectory) {
                // A JUnit report or another tool's XML left in the project folder (decision 0208).
                log.warning(diag::W0042, ast::Loc{raw, 1, 1}, "not a PLCopen TC6 XML project: skipped");
                return;
            }
            log.error(diag::E0008, ast::Loc{raw, 1, 1}, "not a PLCopen TC6 XML project (the root must be <project> in namespace http://www.plcopen.org/xml/tc6_0201, tc6_0200 or tc6.xsd)");
            return;
        }
        converted = readPlcOpen(text);
    } else if (mayHoldTextualSfc(text)) {
        converted = convertTextualSfc(text);  // ST with textual SFC: the SFC elements become ST (docs/graphical.md)
        if (converted.errors.empty() && converted.origins.empty()) {  // no chart after all: plain ST
            userFiles.push_back(sources.add(path, std::move(text)));
            return;
        }
    } else if (mayHoldTextualIl(text)) {
        converted = convertTextualIl(text);  // ST files with IL bodies: the IL becomes ST (decision 0464)
        if (converted.errors.empty() && converted.origins.empty()) {  // no IL body after all: plain ST
            userFiles.push_back(sources.add(path, std::move(text)));
            return;
        }
    } else {
        userFiles.push_back(sources.add(path, std::move(text)));
        return;
    }
    addConverted(path, std::move(text), std::move(converted), sources, userFiles, log);
}

// What a Beremiz project adds to its plc.xml (decision 0356): the globals of
// its C and Python extensions, matiec's blocks it uses (decision 0360), and,
// when `warnSkipped`, the warning naming the sources under it left out.
void addBeremizProject(BeremizFolder& folder, bool warnSkipped, SourceSet& sources, std::vector<int>& userFiles, CompileLog& log) {
    // The globals of its C and Python extensions are part of it, as Beremiz adds them.
    std::erase_if(folder.skipped, [&](const std::string& f) {
        std::string text, unused;
        if (lowerExtension(f) != ".xml" || !readSourceText(f, projectBytes(sources), text, unused)) return false;
        Converted globals = readBeremizExtensionGlobals(text, f);
        if (globals.text.empty() && globals.errors.empty()) return false;
        addConverted(f, std::move(text), std::move(globals), sources, userFiles, log);
        return true;
    });
    std::string xml, unused;
    if (readSourceText(folder.program, projectBytes(sources), xml, unused))
        if (std::string blocks = beremizStandardBlocks(xml); !blocks.empty())
            userFiles.push_back(sources.add(kBeremizStandardBlocksPath, std::move(blocks)));
    if (!warnSkipped || folder.skipped.empty()) return;
    std::string settings;  // quoted under the warning
    if (!readSourceText(folder.settings, projectBytes(sources), settings, unused)) settings.clear();
    int raw = sources.add(folder.settings, "", {}, std::move(settings));
    Diagnostic& d = log.warning(diag::W0042, ast::Loc{raw, 1, 1},
                                "a Beremiz/OpenPLC project folder: plc.xml is compiled, the other sources in it are skipped");
    for (const std::string& f : folder.skipped) d.note(beremizSkipReason(folder, f));
}

// A TwinCAT type system: a .tsproj (the System's) or a .tmc (a PLC project's).
bool isTwinCatTypeSystem(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".tsproj" || ext == ".tmc";
}

// TC_EVENT_CLASSES and TC_EVENTS from the event classes of the folder's
// .tsproj and .tmc files, when its sources (from `firstFile` on) name them
// (decision 0372): a project that does not name them reads no type system.
// The .tsproj comes first (it is the type system; the .tmc repeat it).
void addEventClassLists(std::vector<std::string> typeSystems, size_t firstFile, SourceSet& sources, std::vector<int>& userFiles) {
    if (typeSystems.empty()) return;
    bool named = false;
    for (size_t k = firstFile; k < userFiles.size() && !named; ++k) named = mentionsTwinCatEventLists(sources.file(userFiles[k]).text);
    if (!named) return;
    std::stable_sort(typeSystems.begin(), typeSystems.end(), [](const std::string& a, const std::string& b) {
        return (lowerExtension(a) == ".tsproj") > (lowerExtension(b) == ".tsproj");
    });
    std::vector<TwinCatEventClass> classes;
    for (const std::string& path : typeSystems) {
        std::string xml, unused;
        if (readSourceText(path, 0, xml, unused)) readTwinCatEventClasses(xml, classes);  // a type system is not a source: its own limit only
    }
    addTwinCatSystemEventClasses(classes);  // TwinCAT's own, in no project file (decision 0400)
    std::string st = twinCatEventClassesSource(classes);
    if (st.empty()) return;
    userFiles.push_back(sources.add(typeSystems.front() + " (TC_EVENTS)", std::move(st)));
}

// The global data types of the folder's type systems its sources (from
// `firstFile` on) name (decision 0447): those of a .tsproj and of a .tmc of
// data types only, and those a .plcproj pins from a PLC project's own .tmc.
// They come as a project library: a DUT of the same name replaces one.
void addGlobalDataTypes(std::vector<std::string> typeSystems, const std::vector<std::string>& pinnedTypes, size_t firstFile,
                        SourceSet& sources, std::vector<int>& userFiles) {
    if (typeSystems.empty() || firstFile >= userFiles.size()) return;
    std::stable_sort(typeSystems.begin(), typeSystems.end(), [](const std::string& a, const std::string& b) {
        return (lowerExtension(a) == ".tsproj") > (lowerExtension(b) == ".tsproj");
    });
    std::vector<TwinCatDataType> types;
    for (const std::string& path : typeSystems) {
        std::string xml, unused;
        if (readSourceText(path, 0, xml, unused)) readTwinCatDataTypes(xml, pinnedTypes.empty() ? nullptr : &pinnedTypes, types);
    }
    std::vector<const std::string*> texts;
    for (size_t k = firstFile; k < userFiles.size(); ++k) texts.push_back(&sources.file(userFiles[k]).text);
    std::string st = twinCatGlobalTypesSource(types, texts);
    if (st.empty()) return;
    const int file = sources.add(typeSystems.front() + " (global data types)", std::move(st));
    sources.markProjectLibrary(file);
    userFiles.push_back(file);
}

// The sources under `dir`, recursively (an unreadable part is left out).
std::vector<std::string> sourcesUnder(const std::string& dir) {
    std::vector<std::string> found;
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && isProjectSource(it->path().string())) found.push_back(it->path().string());
    std::sort(found.begin(), found.end());
    return found;
}

}  // namespace

void addProjectSourceText(const std::string& path, std::string text, SourceSet& sources, std::vector<int>& userFiles, CompileLog& log) {
    addFile(path, std::move(text), sources, userFiles, log, false);
}

const char* const kStdinName = "<stdin>";

bool isTwinCatObject(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".tcpou" || ext == ".tcdut" || ext == ".tcgvl" || ext == ".tcio" || ext == ".tctto" || ext == ".tctleo";
}

bool isProjectSource(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".st" || ext == ".xml" || isTwinCatObject(path);
}

bool readProjectInputs(const std::vector<std::string>& paths, SourceSet& sources, std::vector<int>& userFiles, CompileLog& log,
                       std::string& usageError) {
    bool stdinRead = false;
    std::vector<GivenPlcProject> plcProjectsGiven;  // for the namespaces of the libraries among them
    for (const auto& path : paths) {
        std::error_code ec;
        if (fs::is_directory(path, ec)) {
            // Every source under the directory, in a stable (name) order; project
            // files of the IDEs (.plcproj, .tsproj, .sln, ...) are not sources.
            std::vector<std::string> found, plcProjects, typeSystems, pinnedTypes;
            fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, ec), end;
            for (; !ec && it != end; it.increment(ec)) {
                if (!it->is_regular_file(ec)) continue;
                if (isProjectSource(it->path().string())) found.push_back(it->path().string());
                else if (lowerExtension(it->path().string()) == ".plcproj") plcProjects.push_back(it->path().string());
                else if (isTwinCatTypeSystem(it->path().string())) typeSystems.push_back(it->path().string());
            }
            if (ec) {
                usageError = "cannot read directory '" + path + "'";
                return false;
            }
            std::sort(plcProjects.begin(), plcProjects.end());
            applyPlcProjects(plcProjects, found, sources, pinnedTypes, plcProjectsGiven);
            // A PLC project folder without its solution: the solution around it (decision 0474).
            if (std::none_of(typeSystems.begin(), typeSystems.end(), [](const std::string& f) { return lowerExtension(f) == ".tsproj"; }))
                for (std::string& f : enclosingTwinCatTypeSystems(plcProjects)) typeSystems.push_back(std::move(f));
            std::sort(found.begin(), found.end());
            // A Beremiz / OpenPLC Editor folder is its plc.xml (decision 0356).
            for (BeremizFolder& folder : takeBeremizFolders(found)) addBeremizProject(folder, true, sources, userFiles, log);
            if (found.empty()) {
                usageError = "'" + path + "' contains no source files (.st, PLCopen .xml, .TcPOU, .TcDUT, .TcGVL, .TcIO)";
                return false;
            }
            std::sort(found.begin(), found.end());
            const size_t firstOfDirectory = userFiles.size();
            for (const auto& f : found) {
                std::string text;
                if (!readSourceText(f, projectBytes(sources), text, usageError)) return false;
                addFile(f, std::move(text), sources, userFiles, log, true);
            }
            addGlobalDataTypes(typeSystems, pinnedTypes, firstOfDirectory, sources, userFiles);
            addEventClassLists(typeSystems, firstOfDirectory, sources, userFiles);
            continue;
        }
        std::string text;
        if (path == "-") {
            // Source from standard input: one ST file, named <stdin> in messages.
            if (stdinRead) {
                usageError = "'-' (standard input) can be given once";
                return false;
            }
            stdinRead = true;
            if (!readSourceText(path, projectBytes(sources), text, usageError)) return false;
            addFile(kStdinName, std::move(text), sources, userFiles, log, false);
            continue;
        }
        if (!fs::exists(path, ec)) {
            usageError = "'" + path + "': no such file";
            return false;
        }
        if (!readSourceText(path, projectBytes(sources), text, usageError)) return false;
        // plc.xml named on its own, beside beremiz.xml: the Beremiz project, without the warning (decision 0356).
        if (fs::path(path).filename() == "plc.xml" && fs::exists(fs::path(path).parent_path() / "beremiz.xml", ec)) {
            std::vector<std::string> under = sourcesUnder(fs::path(path).parent_path().empty() ? "." : fs::path(path).parent_path().string());
            for (BeremizFolder& folder : takeBeremizFolders(under))
                if (fs::equivalent(folder.program, path, ec)) addBeremizProject(folder, false, sources, userFiles, log);
        }
        addFile(path, std::move(text), sources, userFiles, log, false);
    }
    assignLibraryNamespaces(plcProjectsGiven, userFiles, sources);
    return true;
}

}  // namespace strun::source
