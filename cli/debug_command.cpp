// strun debug: the debug adapter (editors/dap/dap_server.h).
#include <cstdio>

#include "cli/editor_commands.h"
#include "editors/dap/dap_server.h"

namespace strun::cli {

int debugCommand() {
    editors::dap::DapServer server(stdin, stdout);
    return server.run();
}

}  // namespace strun::cli
