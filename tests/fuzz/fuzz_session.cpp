#include "tests/fuzz/fuzz_session.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "interpreter/project/dump_json.h"
#include "interpreter/project/retain_store.h"
#include "interpreter/project/task_runner.h"
#include "interpreter/source/project_inputs.h"
#include "interpreter/source/xml_inputs.h"
#include "runtime/fnv1a.h"
#include "runtime/scheduler.h"

namespace strun::fuzz {

Session::Session()
    : library_(project::parseLibrary(libraryLog_)),
      retainPath_((std::filesystem::temp_directory_path() / ("strun-fuzz-" + std::to_string(::getpid()) + ".retain")).string()) {}

Session::~Session() {
    std::error_code ec;
    std::filesystem::remove(retainPath_, ec);
}

std::string Session::runOnce(const uint8_t* data, size_t size) {
    if (size > kMaxInputBytes) return "";
    SourceSet sources = library_->sources;
    int file = sources.add("fuzz.st", std::string(reinterpret_cast<const char*>(data), size));
    return compileAndRun(sources, {file}, false, nullptr);
}

std::string Session::runXml(const uint8_t* data, size_t size) {
    if (size > kMaxInputBytes) return "";
    std::string text(reinterpret_cast<const char*>(data), size);
    // The extension picks the reader, as for a file on the command line.
    const char* name = source::isPlcOpenProject(text) ? "fuzz.xml" : "fuzz.TcPOU";
    SourceSet sources = library_->sources;
    std::vector<int> files;
    CompileLog log;
    source::addProjectSourceText(name, std::move(text), sources, files, log);
    if (log.errorCount() > 0 || files.empty()) return "";
    return compileAndRun(sources, files, false, nullptr);
}

const char* Session::retainProgram() {
    return R"(TYPE E_Mode : (Idle, Run := 5, Fault := 9); END_TYPE
TYPE R_Pair : STRUCT a : INT; s : STRING(10); END_STRUCT END_TYPE
TYPE T_Small : INT(-10..10); END_TYPE
FUNCTION_BLOCK FB_Count
VAR RETAIN n : UDINT; last : TIME; END_VAR
n := n + 1; last := T#1ms * UDINT_TO_DINT(n);
END_FUNCTION_BLOCK
VAR_GLOBAL RETAIN
  gB : BOOL; gW : WSTRING(5); gMode : E_Mode; gSmall : T_Small; gPairs : ARRAY[0..2] OF R_Pair;
END_VAR
VAR_GLOBAL PERSISTENT gLR : LREAL; gDT : DT; gBits : ARRAY[1..40] OF BOOL; END_VAR
PROGRAM Main
VAR RETAIN i : DINT; s : STRING(10); fb : FB_Count; r : REAL; w : WORD; END_VAR
i := i + 1; gB := NOT gB; s := CONCAT('ab', INT_TO_STRING(DINT_TO_INT(i MOD 100)));
gW := "xy"; gMode := Run; gSmall := -3; gPairs[1].a := gPairs[1].a + 2; gPairs[2].s := s;
gLR := gLR + 0.5; gDT := DT#2024-01-02-03:04:05; gBits[i MOD 40 + 1] := TRUE; fb(); r := r + 1.25; w := ROL(w + 1, 3);
IF gB = TRUE THEN w := w OR 1; END_IF
END_PROGRAM
)";
}

std::string Session::validRetainFile(bool checksumToFix) {
    std::error_code ec;
    std::filesystem::remove(retainPath_, ec);
    runRetain(nullptr, 0);  // a cold start, saved at the end
    std::ifstream in(retainPath_, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    std::string file = bytes.str();
    if (checksumToFix && file.rfind("\nEND ") != std::string::npos) file = file.substr(0, file.rfind("\nEND ") + 1) + "END FIX\n";
    return file;
}

namespace {
// A file whose last line is "END FIX" gets the checksum line it needs
// (`END count sum`, FNV-1a 64 of every byte before it): a mutated value line
// then reaches the value checks instead of stopping at the checksum.
void fixRetainChecksum(std::string& bytes) {
    const std::string_view marker = "END FIX";
    std::string_view view = bytes;
    if (!view.empty() && view.back() == '\n') view.remove_suffix(1);
    if (view.size() < marker.size() || view.substr(view.size() - marker.size()) != marker) return;
    const size_t bodyEnd = view.size() - marker.size();
    if (bodyEnd > 0 && bytes[bodyEnd - 1] != '\n') return;
    uint64_t hash = strun::rt::kRetainFnv1aBasis;
    size_t lines = 0;
    for (size_t i = 0; i < bodyEnd; ++i) {
        hash = strun::rt::fnv1aStep(hash, static_cast<uint8_t>(bytes[i]));
        lines += bytes[i] == '\n';
    }
    char end[64];
    std::snprintf(end, sizeof end, "END %zu %016llx\n", lines > 0 ? lines - 1 : 0, static_cast<unsigned long long>(hash));
    bytes.resize(bodyEnd);
    bytes += end;
}
}  // namespace

std::string Session::runRetain(const uint8_t* data, size_t size) {
    if (size > kMaxInputBytes) return "";
    std::string bytes = data ? std::string(reinterpret_cast<const char*>(data), size) : std::string();
    fixRetainChecksum(bytes);
    SourceSet sources = library_->sources;
    int file = sources.add("retained.st", retainProgram());
    return compileAndRun(sources, {file}, true, data ? &bytes : nullptr);
}

std::string Session::compileAndRun(SourceSet& sources, const std::vector<int>& files, bool retained, const std::string* retainBytes) {
    CompileLog log;
    auto model = project::compileProject(sources, files, log, {}, library_.get());
    std::ostringstream sink;
    log.print(sink, sources);
    if (!model) return "";
    // The retain file is restored into the compiled program, as `--retain` does
    // (an empty or absent file is a cold start), and saved when the run ends.
    std::unique_ptr<project::RetainStore> retain;
    if (retained) {
        if (retainBytes)
            std::ofstream(retainPath_, std::ios::binary | std::ios::trunc)
                .write(retainBytes->data(), static_cast<std::streamsize>(retainBytes->size()));
        retain = std::make_unique<project::RetainStore>(*model, retainPath_, sink);
        std::string error;
        if (!retain->start(false, {}, error)) return "";
    }
    std::vector<rt::TaskSpec> specs;
    std::vector<std::unique_ptr<project::TaskRunner>> runners;
    std::vector<rt::TaskBody*> bodies;
    for (const auto& t : model->tasks) {
        specs.push_back(t.spec);
        runners.push_back(std::make_unique<project::TaskRunner>(*model, t));
        runners.back()->setRetainStore(retain.get());
        bodies.push_back(runners.back().get());
    }
    rt::RunOptions options;
    options.virtualClock = true;
    options.stmtCost = 1000;
    options.duration = kPlcTimeNanos;
    options.warnings = &sink;
    rt::Scheduler scheduler(model->machine, specs, bodies, options);
    rt::PlcState state = scheduler.run();
    if (retain) retain->save(true);
    nlohmann::ordered_json out;
    out["state"] = rt::plcStateName(state);
    out["globals"] = project::globalsJson(*model);
    out["programs"] = project::programsJson(*model);
    out["tasks"] = scheduler.tasksJson();
    out["diagnostics"] = scheduler.diagnosticsJson();
    return out.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace strun::fuzz
