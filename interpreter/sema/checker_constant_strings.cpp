// STRING and WSTRING CONSTANTs whose value is known when the program is
// compiled (decision 0331). Their uses keep reading the variable (ADR of a
// constant string is an address in the project's memory, as before); the
// value is kept so that the standard string functions can fold a call on
// constants, e.g. `cTopic : STRING(100) := CONCAT(CONCAT(cMain, cType), cDevice);`
// in a VAR_GLOBAL CONSTANT list (CODESYS and TwinCAT accept it).
#include "interpreter/exec/value_nodes.h"
#include "interpreter/sema/checker.h"

namespace strun::sema {

void Checker::foldStringConstant(VarSym& v, const ast::VarDecl& decl) {
    // writeInitial checks the same expression and reports its messages once.
    const size_t messagesBefore = log_.messages().size();
    Checked c = checkExpr(*decl.init->expr);
    if (c.ok) c = coerce(c, v.type, decl.init->loc, "initial value");
    log_.dropFrom(messagesBefore);
    if (!c.ok || !c.isConst) return;
    auto* text = exec::nodeCast<exec::ConstBytes>(c.node);
    if (!text) return;
    // The value as the variable holds it: cut to its length, NUL-terminated.
    std::vector<uint8_t> bytes(v.type->size, 0);
    std::copy_n(text->bytes.begin(), std::min<size_t>(text->bytes.size(), bytes.size()), bytes.begin());
    bytes[bytes.size() - 1] = 0;
    if (v.type->kind == TK::WString && bytes.size() >= 2) bytes[bytes.size() - 2] = 0;
    auto* node = pool().make<exec::ConstBytes>(std::move(bytes));
    node->type = v.type;
    v.constText = node;
}

}  // namespace strun::sema
