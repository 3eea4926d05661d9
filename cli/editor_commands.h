// strun lsp and strun debug: the editor protocols on stdin / stdout
// (editors/lsp, editors/dap; docs/editors.md).
#pragma once

#include <CLI/CLI.hpp>

namespace strun::cli {

CLI::App* addLspCommand(CLI::App& app);
int lspCommand();
CLI::App* addDebugCommand(CLI::App& app);
int debugCommand();

}  // namespace strun::cli
