// CODESYS/TwinCAT attributes that change meaning: `{attribute 'qualified_only'}`,
// `{attribute 'strict'}`. Others (`{attribute 'hide'}`, unknown ones) are ignored.
#pragma once

#include <string>
#include <vector>

#include "interpreter/ast/ast.h"

namespace strun::sema {

// True when one of `pragmas` is `attribute 'name'` (case-insensitive, any spacing).
inline bool hasAttribute(const std::vector<ast::Pragma>& pragmas, const std::string& name) {
    if (pragmas.empty()) return false;  // most declarations: no folded name built (checked at every variable)
    auto squeeze = [](const std::string& s) {
        std::string out;
        for (char c : s)
            if (c != ' ' && c != '\t' && c != '\r' && c != '\n') out.push_back(static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c));
        return out;
    };
    const std::string want = "attribute'" + squeeze(name) + "'";
    for (const auto& p : pragmas)
        if (squeeze(p.text) == want) return true;
    return false;
}

}  // namespace strun::sema
