// strun lsp: the language server (editors/lsp/lsp_server.h).
#include <cstdio>

#include "cli/editor_commands.h"
#include "editors/lsp/lsp_server.h"

namespace strun::cli {

int lspCommand() {
    editors::lsp::LspServer server(stdin, stdout);
    return server.run();
}

}  // namespace strun::cli
