// strun lsp and strun debug: the editor protocols on stdin / stdout
// (editors/lsp, editors/dap; docs/editors.md).
#pragma once

#include "cli/cli11_fwd.h"

namespace strun::cli {

// Registered in cli/main.cpp; run by cli/lsp_command.cpp, cli/debug_command.cpp.
CLI::App* addLspCommand(CLI::App& app);
int lspCommand();
CLI::App* addDebugCommand(CLI::App& app);
int debugCommand();

}  // namespace strun::cli
