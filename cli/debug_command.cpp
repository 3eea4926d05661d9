// strun debug: the debug adapter (editors/dap/dap_server.h).
#include <cstdio>

#include "cli/editor_commands.h"
#include "editors/dap/dap_server.h"

namespace strun::cli {

CLI::App* addDebugCommand(CLI::App& app) {
    return app.add_subcommand("debug", "a Debug Adapter Protocol adapter on stdin/stdout (docs/editors.md)");
}

int debugCommand() {
    editors::dap::DapServer server(stdin, stdout);
    return server.run();
}

}  // namespace strun::cli
