#include "cli/run_report.h"

#include <string>

#include "cli/diagnostic_render.h"
#include "stdlib/value_format.h"

namespace strun::cli {

namespace {

constexpr size_t kSummaryDiagnostics = 20;  // more are counted, not listed

// FILE:LINE:COL of an entry; the POU's name stands in for an unknown file.
std::string location(const rt::DiagEntry& e, const std::vector<std::string>& files) {
    std::string where;
    if (e.file >= 0 && size_t(e.file) < files.size()) where = files[size_t(e.file)];
    else if (!e.pou.empty()) where = e.pou;
    else where = "strun";
    return where + ":" + std::to_string(e.line > 0 ? e.line : 1) + ":" + std::to_string(e.col > 0 ? e.col : 1);
}

std::string microsText(const nlohmann::ordered_json& micros) {
    double us = micros.is_number() ? micros.get<double>() : 0.0;
    return stdlib::formatDuration(int64_t(us * 1000.0 + (us >= 0 ? 0.5 : -0.5)));
}

}  // namespace

void printFaultReport(std::ostream& out, const rt::Scheduler& scheduler, const SourceSet& sources,
                      const DiagnosticOptions& options, bool color) {
    for (const rt::DiagEntry& e : scheduler.stopFaults()) {
        RuntimeFault fault;
        fault.loc.file = e.file;
        fault.loc.line = e.line;
        fault.loc.col = e.col > 0 ? e.col : 1;
        fault.where = location(e, scheduler.sourceFiles());
        fault.code = rt::diagCodeName(e.code);
        fault.task = e.task.empty() ? std::string("-") : e.task;
        fault.message = e.message;
        printRuntimeFault(out, fault, sources, options.format, color);
    }
}

void printForcesLine(std::ostream& out, const nlohmann::ordered_json& forces) {
    if (forces.empty()) return;
    out << "  forces:";
    const char* separator = " ";
    for (const auto& [name, value] : forces.items()) {
        out << separator << name << " = " << (value.is_string() ? value.get<std::string>() : value.dump());
        separator = ", ";
    }
    out << "\n";
}

void printRunSummary(std::ostream& out, const rt::Scheduler& scheduler, rt::PlcState state, DiagnosticFormat format,
                     const nlohmann::ordered_json& forces) {
    if (format == DiagnosticFormat::Json) {
        nlohmann::ordered_json s;
        s["state"] = rt::plcStateName(state);
        s["time"] = stdlib::formatDuration(scheduler.endTime());
        s["tasks"] = scheduler.tasksJson();
        s["diagnostics"] = scheduler.diagnosticsJson();
        s["more_diagnostics"] = scheduler.droppedDiagnostics();
        if (!forces.empty()) s["forces"] = forces;
        nlohmann::ordered_json j;
        j["summary"] = std::move(s);
        out << j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
        return;
    }
    out << "strun: PLC " << rt::plcStateName(state) << " at " << stdlib::formatDuration(scheduler.endTime()) << "\n";
    for (const auto& task : scheduler.tasksJson()) {
        out << "  task " << task["name"].get<std::string>() << ": " << task["cycles"].get<uint64_t>() << " cycles, "
            << task["overruns"].get<uint64_t>() << " overruns, max execution " << microsText(task["max_exec_us"]) << "\n";
    }
    const auto& entries = scheduler.diagnostics();
    uint64_t total = entries.size() + scheduler.droppedDiagnostics();
    if (total == 0) {
        out << "  diagnostics: none\n";
        printForcesLine(out, forces);
        return;
    }
    out << "  diagnostics: " << total << "\n";
    for (size_t i = 0; i < entries.size() && i < kSummaryDiagnostics; ++i) {
        const rt::DiagEntry& e = entries[i];
        out << "    " << stdlib::formatDuration(e.time) << " " << rt::diagCodeName(e.code);
        if (!e.task.empty()) out << " in " << e.task;
        if (!e.pou.empty()) out << " at " << location(e, scheduler.sourceFiles());
        out << ": " << e.message << "\n";
    }
    if (total > kSummaryDiagnostics) out << "    ... " << (total - std::min<uint64_t>(entries.size(), kSummaryDiagnostics)) << " more\n";
    printForcesLine(out, forces);
}

}  // namespace strun::cli
