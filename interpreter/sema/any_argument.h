// Inputs declared with a generic type (ANY, ANY_NUM, ANY_INT, ...) on a
// FUNCTION or METHOD, as TwinCAT and CODESYS allow (decision 0302): the
// parameter is a __SYSTEM.AnyType and each call passes the argument's type
// class, address and size.
#pragma once

#include <string_view>
#include <vector>

#include "interpreter/sema/symbols.h"

namespace strun::sema {

class Checker;

// ANY, ANY_NUM, ANY_INT, ANY_REAL, ANY_BIT, ANY_STRING, ANY_DATE,
// ANY_ELEMENTARY, ANY_MAGNITUDE, ANY_SIGNED, ANY_UNSIGNED, ANY_DURATION, ANY_CHARS (upper case).
bool isGenericTypeName(std::string_view upperName);

// When `p` is an input declared with a generic type and `v` is not already
// an AnyType (passed on as it is): appends the statements that bind it to
// `out`, sets `ok` (false after an error, reported) and returns true.
bool bindAnyArgument(Checker& ck, const VarSym* p, Checked v, exec::Expr* place, const ast::Loc& loc,
                     std::vector<exec::Stmt*>& out, bool& ok);

}  // namespace strun::sema
