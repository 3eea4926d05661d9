// What `strun run` tells a person on stderr when the run ends: one line per
// fault that sent the PLC to STOP/HALT (always), and unless --dump or
// --quiet, a short summary: final state, PLC time, per task cycles /
// overruns / maximum execution time, and the diagnostic buffer.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "cli/diagnostic_options.h"
#include "interpreter/source/source_set.h"
#include "runtime/scheduler.h"

namespace strun::cli {

// `FILE:LINE:COL: runtime error: CODE in TASK: MESSAGE`, one per stopping
// fault, each followed by its source excerpt (cli/diagnostic_render.h).
void printFaultReport(std::ostream& out, const rt::Scheduler& scheduler, const SourceSet& sources,
                      const DiagnosticOptions& options, bool color);
// With --diagnostics-format json the summary is one JSON object on one line,
// {"summary":{"state","time","tasks":[...],"diagnostics":[...],"more_diagnostics"}}
// (tasks and diagnostics as in --dump), so a tool reading stderr line by line
// gets only JSON.
// The forces still active (--force and live forces, as --dump's "forces")
// end the summary: a "forces:" line, or the JSON summary's "forces" member.
void printRunSummary(std::ostream& out, const rt::Scheduler& scheduler, rt::PlcState state,
                     DiagnosticFormat format = DiagnosticFormat::Text,
                     const nlohmann::ordered_json& forces = nlohmann::ordered_json::object());
// "  forces: NAME = VALUE, ..." (nothing when there is none).
void printForcesLine(std::ostream& out, const nlohmann::ordered_json& forces);

}  // namespace strun::cli
