#include "interpreter/exec/call_nodes.h"

namespace strun::exec {

// runBody for the rarer call forms (a body dispatched on the instance's
// class): kept out of line so that the plain FB call keeps the body's
// Block::exec inlined (call_nodes.h).
void runBodyOutOfLine(Ctx& c, const PouCode& code, uint8_t* inst, uint8_t* f) { runBody(c, code, inst, f); }

template struct CallFbStmtOf<false>;
template struct CallFbStmtOf<true>;

}  // namespace strun::exec
