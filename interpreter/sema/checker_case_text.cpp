// CASE on a CHAR / WCHAR or STRING / WSTRING selector, as SIMATIC AX code
// writes it (simatic-ax/conversion: `CASE c OF '0': ...`, `_c : STRING; CASE
// _c OF '0': ...`; decision 0394). A CHAR is an integer: its labels are the
// characters' codes. A STRING selector becomes a CASE on the number of the
// label it equals (exec::StringCaseKey).
#include <fmt/format.h>

#include "interpreter/exec/text_value_nodes.h"
#include "interpreter/sema/checker.h"

namespace strun::sema {

exec::Expr* Checker::caseTextSelector(const Checked& sel) {
    const Type* t = sel.type;
    if (!isStringType(t->kind)) return nullptr;
    const uint32_t maxLen = std::max<uint32_t>(t->maxLen, 1);
    exec::Expr* key = t->kind == TK::WString ? static_cast<exec::Expr*>(pool().make<exec::StringCaseKey<char16_t>>(sel.node, maxLen))
                                             : static_cast<exec::Expr*>(pool().make<exec::StringCaseKey<char>>(sel.node, maxLen));
    key->type = types().elementary(TK::DInt);
    return key;
}

bool Checker::caseTextLabel(exec::Expr* key, const Type* selector, Checked& label, const ast::Loc& loc, int64_t& out) {
    if (isCharType(selector->kind)) {
        // 'A' (a one-character string literal) or a CHAR constant.
        if (!label.type || !(isStringType(label.type->kind) || isCharType(label.type->kind))) {
            error(diag::E0503, loc, fmt::format("CASE label of type {} does not match the selector type {}", typeName(label.type), typeName(selector)));
            return false;
        }
        Checked c = coerce(label, selector, loc, "CASE label");
        if (!c.ok) return false;
        if (!c.isConst) {
            error(diag::E0503, loc, fmt::format("a CASE label of a {} selector is one character, like 'A'", typeName(selector)));
            return false;
        }
        out = c.constInt;
        return true;
    }
    auto* bytes = exec::nodeCast<exec::ConstBytes>(label.node);
    if (!label.type || !isStringType(label.type->kind) || label.type->kind != selector->kind || !bytes) {
        error(diag::E0503, loc, fmt::format("CASE label of type {} does not match the selector type {}", typeName(label.type), typeName(selector)));
        return false;
    }
    auto number = [&](auto* k, auto text) {
        for (size_t i = 0; i < k->labels.size(); ++i)
            if (k->labels[i] == text) return static_cast<int64_t>(i + 1);
        k->labels.push_back(text);
        return static_cast<int64_t>(k->labels.size());
    };
    if (selector->kind == TK::WString) {
        std::u16string text;
        for (size_t i = 0; i + 1 < bytes->bytes.size(); i += 2) {
            char16_t ch = static_cast<char16_t>(bytes->bytes[i] | (bytes->bytes[i + 1] << 8));
            if (ch == 0) break;
            text.push_back(ch);
        }
        out = number(static_cast<exec::StringCaseKey<char16_t>*>(key), text);
    } else {
        std::string text;
        for (uint8_t b : bytes->bytes) {
            if (b == 0) break;
            text.push_back(static_cast<char>(b));
        }
        out = number(static_cast<exec::StringCaseKey<char>*>(key), text);
    }
    return true;
}

}  // namespace strun::sema

namespace strun::sema {

exec::Expr* Checker::charAsString(const Checked& ch, const Type* target) {
    const bool wide = target->kind == TK::WString;
    const uint32_t off = allocTemp(wide ? 4 : 2);
    return wide ? static_cast<exec::Expr*>(pool().make<exec::CharAsString<char16_t>>(ch.node, off))
                : static_cast<exec::Expr*>(pool().make<exec::CharAsString<char>>(ch.node, off));
}

}  // namespace strun::sema
