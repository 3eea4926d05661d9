// Everything the command line says, as parsed by CLI11 (app.cpp) and read
// by the commands (run_command.cpp, check_command.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/diagnostic_options.h"
#include "cli/live_options.h"
#include "interpreter/sema/compile_options.h"

namespace strun::cli {

struct CommandLine {
    std::vector<std::string> files;
    sema::CompileOptions compile;  // --target, --strict (run, check)
    DiagnosticOptions diagnostics;  // --color, --diagnostics-format, -W (run, check, test)

    // run
    bool virtualClock = false;
    std::optional<int64_t> stmtCost;     // --stmt-cost, ns
    std::optional<uint64_t> cycles;      // --cycles
    std::string task;                    // --task
    std::optional<int64_t> forDuration;  // --for, ns
    std::optional<int64_t> start;        // --start, calendar ns
    bool dump = false;
    bool trace = false;
    bool realtime = false;
    bool quiet = false;
    std::vector<std::string> sets;           // --set NAME=VALUE[@TIME], in the order given
    std::vector<std::string> stimulusFiles;  // --stimulus FILE
    std::string vcdFile;                     // --vcd FILE
    std::vector<std::string> watches;        // --watch PATTERN
    bool vcdText = false;                    // --vcd-text: enumerations by name, STRINGs as text
    std::string retainFile;                  // --retain FILE
    std::string filesDir;                    // --files DIR: the sandbox of the PLC's file blocks
    bool cold = false;                       // --cold
    std::optional<int64_t> retainEvery;      // --retain-every, ns
    LiveOptions live;                        // --force, --paused, --serve, --serve-token (cli/live_options.h)
    std::string modbusServe;                 // --modbus [ADDR:]PORT (cli/modbus_options.h)
    std::string modbusClientFile;            // --modbus-client FILE
};

}  // namespace strun::cli
