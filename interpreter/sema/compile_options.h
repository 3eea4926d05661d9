// The command-line choices that change how a project compiles. The CLI
// (`run`, `check`, `test`) fills one and hands it to project::compileProject,
// which passes it to the checker.
#pragma once

#include <string>

namespace strun::sema {

struct CompileOptions {
    // --target: the PLC family whose task model, limits and system variables
    // apply (an id of rt::allProfiles(); the CLI validates it).
    std::string target = "generic";
    // --strict: IEC 61131-3 typing; implicit conversions the default accepts
    // with a warning are errors.
    bool strict = false;
};

}  // namespace strun::sema
