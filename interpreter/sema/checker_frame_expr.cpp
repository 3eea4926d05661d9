// An expression typed in an editor (a debugger's watch, hover, condition or
// log point), checked as if it were written in the body of a POU: the same
// names, the same rules and the same messages as `check`, so a wrong
// expression answers what the compiler would say.
#include "interpreter/sema/checker.h"

namespace strun::sema {

Checked Checker::checkInScope(const ast::Expr& e, PouInfo* pou, uint32_t& frameBytes) {
    PouInfo* savedPou = pou_;
    const std::string* savedName = currentPouName_;
    const uint32_t savedTop = frameTop_;
    const int savedLoops = loopDepth_;
    pou_ = pou;
    currentPouName_ = pou && pou->code ? &pou->code->name : nullptr;
    // Temporaries of the expression go after everything the body uses.
    frameTop_ = pou && pou->code ? pou->code->frameSize : 0;
    loopDepth_ = 0;
    Checked c = checkExpr(e);
    if (c.ok) c = settle(c);
    frameBytes = frameTop_;
    pou_ = savedPou;
    currentPouName_ = savedName;
    frameTop_ = savedTop;
    loopDepth_ = savedLoops;
    return c;
}

}  // namespace strun::sema
