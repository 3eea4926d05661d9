#include "interpreter/sema/any_argument.h"

#include <fmt/format.h>

#include "interpreter/exec/any_nodes.h"
#include "interpreter/sema/checker.h"

namespace strun::sema {

namespace {

// CODESYS's __SYSTEM.TYPE_CLASS values (stdlib/st/system.st).
int32_t typeClassOf(const Type* t) {
    if (t->isSubrange && t->base) t = t->base;
    switch (t->kind) {
        case TK::Bool: return 0;
        case TK::Byte: return 2;
        case TK::Word: return 3;
        case TK::DWord: return 4;
        case TK::LWord: return 5;
        case TK::SInt: return 6;
        case TK::Int: return 7;
        case TK::DInt: return 8;
        case TK::LInt: return 9;
        case TK::USInt: return 10;
        case TK::UInt: return 11;
        case TK::UDInt: return 12;
        case TK::ULInt: return 13;
        case TK::Real: return 14;
        case TK::LReal: return 15;
        case TK::String: return 16;
        case TK::WString: return 17;
        case TK::Time: return 18;
        case TK::Date: return 19;
        case TK::Dt: return 20;
        case TK::Tod: return 21;
        case TK::Pointer: return 22;
        case TK::Reference: return 23;
        case TK::Enum: return 25;
        case TK::Array: return 26;
        case TK::LTime: return 37;
        case TK::LDate: return 46;
        case TK::LDt: return 47;
        case TK::LTod: return 48;
        case TK::Char: return 2;   // CODESYS has no CHAR: its storage is a BYTE
        case TK::WChar: return 3;  // ... and a WORD
        default: return 28;        // structures, function blocks, interfaces: TYPE_USERDEF
    }
}

// Whether a value of type t may be passed to an input of the generic type `family`.
bool fits(std::string_view family, const Type* t) {
    const TK k = (t->isSubrange && t->base ? t->base : t)->kind;
    if (family == "ANY") return true;
    if (family == "ANY_ELEMENTARY") return isElementary(k);
    if (family == "ANY_NUM" || family == "ANY_MAGNITUDE") return isNumeric(k) || (family == "ANY_MAGNITUDE" && isTimeLike(k));
    if (family == "ANY_INT") return isInteger(k);
    if (family == "ANY_SIGNED") return isSignedInt(k);
    if (family == "ANY_UNSIGNED") return isUnsignedInt(k);
    if (family == "ANY_REAL") return isReal(k);
    if (family == "ANY_BIT") return isAnyBit(k);
    if (family == "ANY_STRING") return isStringType(k);
    if (family == "ANY_CHARS") return isStringType(k) || isCharType(k);
    if (family == "ANY_DATE") return isDateLike(k);
    if (family == "ANY_DURATION") return isTimeLike(k);
    return false;
}

}  // namespace

bool isGenericTypeName(std::string_view u) {
    return u == "ANY" || u == "ANY_NUM" || u == "ANY_INT" || u == "ANY_REAL" || u == "ANY_BIT" || u == "ANY_STRING" ||
           u == "ANY_DATE" || u == "ANY_ELEMENTARY" || u == "ANY_MAGNITUDE" || u == "ANY_SIGNED" || u == "ANY_UNSIGNED" ||
           u == "ANY_DURATION" || u == "ANY_CHARS";
}

bool bindAnyArgument(Checker& ck, const VarSym* p, Checked v, exec::Expr* place, const ast::Loc& loc,
                     std::vector<exec::Stmt*>& out, bool& ok) {
    if (!p->decl || !p->decl->type || p->decl->type->kind != ast::TypeSpecKind::Named || p->type->kind != TK::Struct) return false;
    const std::string family = upper(p->decl->type->name);
    if (!isGenericTypeName(family)) return false;
    if (v.type == p->type) return false;  // an AnyType passed on: copied like any structure
    ok = false;
    // A literal gets the type TwinCAT gives it: the smallest of INT, DINT, LINT
    // that holds an integer, LREAL for a real, as for an untyped constant.
    if (v.untypedInt) {
        const int64_t n = v.constInt;
        const TK k = n >= -32768 && n <= 32767 ? TK::Int : n >= INT32_MIN && n <= INT32_MAX ? TK::DInt : TK::LInt;
        v = ck.coerce(v, ck.types().elementary(k), loc, "argument");
        if (!v.ok) return true;
    } else if (v.untypedReal) {
        v = ck.coerce(v, ck.types().elementary(TK::LReal), loc, "argument");
        if (!v.ok) return true;
    }
    if (!fits(family, v.type)) {
        ck.error(diag::E0201, loc, fmt::format("argument '{}' must be {}, not {}", p->name, family, typeName(v.type)));
        return true;
    }
    const Field* tc = p->type->findField("TYPECLASS");
    const Field* pv = p->type->findField("PVALUE");
    const Field* sz = p->type->findField("DISIZE");
    if (!tc || !pv || !sz) return false;
    exec::Expr* value = v.node;
    // Not storage of its own (a literal, an expression, a call, a bit): through a temporary of the caller.
    if (!v.isPlace || v.propertyInstance || v.node->bitIndex() >= 0) {
        value = ck.tempPlace(v.type);
        out.push_back(ck.storeTo(value, v.type, v.node));
    }
    out.push_back(ck.pool().make<exec::BindAnyArgument>(place, value, typeClassOf(v.type), static_cast<int32_t>(v.type->size),
                                                         tc->offset, pv->offset, sz->offset));
    ok = true;
    return true;
}

}  // namespace strun::sema
