// `strun help --man`: the manual page strun.1 (roff), made from the same
// command and option descriptions as --help, so the two cannot drift. The
// build writes it to build/strun.1 and `make install` installs it.
#pragma once

#include <ostream>

#include "cli/cli11_fwd.h"

namespace strun::cli {

int printManPage(const CLI::App& app, std::ostream& out);

}  // namespace strun::cli
