// FB_JsonReadWriteDataType's native part (decision 0285): a value of a
// declared data type, named at run time ('ST_Values'), to JSON and back.
// F_strun_JsonSymbol(op, pType, nData, pData, pJson, nJson):
//   op 1: the JSON text of the nData bytes at pData, copied with its NUL to
//         pJson (nJson bytes): its length without the NUL; -16#705 when
//         nData is not the type's size, -16#710 when no type has that name,
//         -16#706 when the buffer is too small.
//   op 2: the JSON text at pJson stored into pData; 0, or -16#706 when the
//         text is not JSON (then nothing is written), or the codes above.
//   op 3: the length of op 1's text (no buffer).
// A structure is an object of its members (an extended structure's inherited
// members first), an array a JSON array (one level per dimension), an
// enumeration its integer value, TIME/DATE/... their stored integer count
// (ms for TIME/TOD, ns for the L types, seconds for DATE/DT), STRING/WSTRING text (UTF-8).
// Pointers, references, interfaces and function blocks are left out. When
// reading, members the text lacks and values of the wrong JSON kind leave
// the target's bytes as they are.
#include <cmath>
#include <cstring>
#include <map>

#include "interpreter/builtins/libraries/json_documents.h"
#include "interpreter/builtins/libraries/library_natives.h"
#include "interpreter/builtins/libraries/plc_memory_text.h"
#include "interpreter/exec/value_nodes.h"
#include "stdlib/text_encoding.h"

namespace strun::sema {
// The checker's friend for reading what it resolved: every declared data
// type by upper-case name (checker.h declares the friendship).
struct CheckerAccess {
    static const std::map<std::string, const Type*>& declaredTypes(const Checker& ck) { return ck.resolvedTypes_; }
};
}  // namespace strun::sema

namespace strun::stdlib::bind {

namespace {

using exec::Ctx;
using json::Json;

using TypeNames = std::map<std::string, const Type*>;

constexpr int64_t kInvalidSize = 0x705;
constexpr int64_t kInvalidData = 0x706;
constexpr int64_t kSymbolNotFound = 0x710;

bool included(const Type* t) {
    return t && t->kind != TK::Pointer && t->kind != TK::Reference && t->kind != TK::Interface && t->kind != TK::FunctionBlock &&
           t->kind != TK::Void;
}

Json toJson(const Type* t, const uint8_t* p);

Json arrayToJson(const Type* t, const uint8_t* p, size_t dim) {
    Json out = Json::array();
    const int64_t count = t->dims[dim].count();
    uint64_t stride = t->elem->size;
    for (size_t d = dim + 1; d < t->dims.size(); ++d) stride *= static_cast<uint64_t>(t->dims[d].count());
    for (int64_t k = 0; k < count; ++k) {
        const uint8_t* at = p + static_cast<uint64_t>(k) * stride;
        out.push_back(dim + 1 < t->dims.size() ? arrayToJson(t, at, dim + 1) : toJson(t->elem, at));
    }
    return out;
}

void structToJson(const Type* t, const uint8_t* p, Json& out) {
    if (t->parent) structToJson(t->parent, p, out);
    for (const auto& f : t->fields)
        if (included(f.type)) out[f.name] = toJson(f.type, p + f.offset);
}

Json toJson(const Type* t, const uint8_t* p) {
    switch (t->kind) {
        case TK::Bool: return Json(p[0] != 0);
        case TK::SInt: return Json(exec::loadAs<int8_t>(p));
        case TK::Int: return Json(exec::loadAs<int16_t>(p));
        case TK::DInt: return Json(exec::loadAs<int32_t>(p));
        case TK::LInt: return Json(exec::loadAs<int64_t>(p));
        case TK::USInt: case TK::Byte: case TK::Char: return Json(exec::loadAs<uint8_t>(p));
        case TK::UInt: case TK::Word: case TK::WChar: return Json(exec::loadAs<uint16_t>(p));
        case TK::UDInt: case TK::DWord: return Json(exec::loadAs<uint32_t>(p));
        case TK::ULInt: case TK::LWord: return Json(exec::loadAs<uint64_t>(p));
        case TK::Time: case TK::LTime: case TK::Date: case TK::Tod: case TK::Dt: case TK::LDate: case TK::LTod: case TK::LDt:
            return t->size == 4 ? Json(exec::loadAs<uint32_t>(p)) : Json(exec::loadAs<int64_t>(p));
        case TK::Real: {
            const double v = exec::loadAs<float>(p);
            return std::isfinite(v) ? Json(v) : Json();
        }
        case TK::LReal: {
            const double v = exec::loadAs<double>(p);
            return std::isfinite(v) ? Json(v) : Json();
        }
        case TK::String:
            return Json(stdlib::bytesToUtf8(std::string_view(reinterpret_cast<const char*>(p), strnlen(reinterpret_cast<const char*>(p), t->maxLen))));
        case TK::WString: {
            std::u16string s;
            for (uint32_t k = 0; k < t->maxLen; ++k) {
                const char16_t ch = exec::loadAs<char16_t>(p + 2 * k);
                if (!ch) break;
                s.push_back(ch);
            }
            return Json(stdlib::utf16ToUtf8(s));
        }
        case TK::Enum: return toJson(t->base, p);
        case TK::Array: return t->flexible ? Json() : arrayToJson(t, p, 0);
        case TK::Struct: {
            Json out = Json::object();
            structToJson(t, p, out);
            return out;
        }
        default: return Json();
    }
}

void fromJson(const Type* t, uint8_t* p, const Json& j);

void arrayFromJson(const Type* t, uint8_t* p, size_t dim, const Json& j) {
    if (!j.is_array()) return;
    const int64_t count = t->dims[dim].count();
    uint64_t stride = t->elem->size;
    for (size_t d = dim + 1; d < t->dims.size(); ++d) stride *= static_cast<uint64_t>(t->dims[d].count());
    for (int64_t k = 0; k < count && static_cast<size_t>(k) < j.size(); ++k) {
        uint8_t* at = p + static_cast<uint64_t>(k) * stride;
        if (dim + 1 < t->dims.size()) arrayFromJson(t, at, dim + 1, j[static_cast<size_t>(k)]);
        else fromJson(t->elem, at, j[static_cast<size_t>(k)]);
    }
}

void structFromJson(const Type* t, uint8_t* p, const Json& j) {
    if (t->parent) structFromJson(t->parent, p, j);
    for (const auto& f : t->fields) {
        if (!included(f.type)) continue;
        auto it = j.find(f.name);
        if (it != j.end()) fromJson(f.type, p + f.offset, *it);
    }
}

template <typename T>
void storeInteger(uint8_t* p, const Json& j) {
    if (j.is_number_integer()) exec::storeAs<T>(p, static_cast<T>(j.is_number_unsigned() ? static_cast<int64_t>(j.get<uint64_t>()) : j.get<int64_t>()));
    else if (j.is_number_float() && std::isfinite(j.get<double>()) && std::fabs(j.get<double>()) < 9.2e18) exec::storeAs<T>(p, static_cast<T>(static_cast<int64_t>(j.get<double>())));
    else if (j.is_boolean()) exec::storeAs<T>(p, static_cast<T>(j.get<bool>() ? 1 : 0));
}

void fromJson(const Type* t, uint8_t* p, const Json& j) {
    switch (t->kind) {
        case TK::Bool:
            if (j.is_boolean()) p[0] = j.get<bool>() ? 1 : 0;
            else if (j.is_number()) p[0] = j.get<double>() != 0 ? 1 : 0;
            break;
        case TK::SInt: case TK::USInt: case TK::Byte: case TK::Char: storeInteger<uint8_t>(p, j); break;
        case TK::Int: case TK::UInt: case TK::Word: case TK::WChar: storeInteger<uint16_t>(p, j); break;
        case TK::DInt: case TK::UDInt: case TK::DWord: storeInteger<uint32_t>(p, j); break;
        case TK::LInt: case TK::ULInt: case TK::LWord: storeInteger<uint64_t>(p, j); break;
        case TK::Time: case TK::LTime: case TK::Date: case TK::Tod: case TK::Dt: case TK::LDate: case TK::LTod: case TK::LDt:
            if (t->size == 4) storeInteger<uint32_t>(p, j);
            else storeInteger<uint64_t>(p, j);
            break;
        case TK::Real:
            if (j.is_number()) exec::storeAs<float>(p, static_cast<float>(j.get<double>()));
            else if (j.is_null()) exec::storeAs<float>(p, std::nanf(""));
            break;
        case TK::LReal:
            if (j.is_number()) exec::storeAs<double>(p, j.get<double>());
            else if (j.is_null()) exec::storeAs<double>(p, std::nan(""));
            break;
        case TK::String:
            if (j.is_string()) {
                const std::string& s = j.get_ref<const std::string&>();
                const size_t n = std::min<size_t>(s.size(), t->maxLen);
                std::memcpy(p, s.data(), n);
                p[n] = 0;
            }
            break;
        case TK::WString:
            if (j.is_string()) {
                auto wide = stdlib::utf8ToUtf16(j.get_ref<const std::string&>());
                if (!wide) break;
                const std::u16string& w = wide.value();
                const size_t n = std::min<size_t>(w.size(), t->maxLen);
                std::memcpy(p, w.data(), 2 * n);
                exec::storeAs<char16_t>(p + 2 * n, 0);
            }
            break;
        case TK::Enum: fromJson(t->base, p, j); break;
        case TK::Array:
            if (!t->flexible) arrayFromJson(t, p, 0, j);
            break;
        case TK::Struct:
            if (j.is_object()) structFromJson(t, p, j);
            break;
        default: break;
    }
}


struct JsonSymbolNode final : exec::Expr {
    const TypeNames* names;
    Expr *op, *type, *nData, *pData, *pJson, *nJson;
    JsonSymbolNode(const TypeNames* t, Expr* o, Expr* ty, Expr* nd, Expr* pd, Expr* pj, Expr* nj)
        : names(t), op(o), type(ty), nData(nd), pData(pd), pJson(pj), nJson(nj) {}

    int64_t i(Ctx& c) override {
        const int code = static_cast<int>(op->i(c));
        std::string_view typeName;
        if (!readPlcText(c, type->i(c), typeName)) return -kSymbolNotFound;
        auto found = names->find(sema::upper(std::string(typeName)));
        if (found == names->end() || !found->second) return -kSymbolNotFound;
        const Type* t = found->second;
        const int64_t size = nData->i(c);
        uint8_t* data = plcAddress(pData->i(c));
        if (size != static_cast<int64_t>(t->size) || !data || !c.m->memory.contains(data, t->size)) return -kInvalidSize;
        if (code == 1 || code == 3) {
            const std::string text = json::print(toJson(t, data));
            if (code == 3) return static_cast<int64_t>(text.size());
            uint8_t* out = plcAddress(pJson->i(c));
            const int64_t room = nJson->i(c);
            if (!out || room <= 0 || !c.m->memory.contains(out, static_cast<size_t>(room))) return -kInvalidSize;
            if (text.size() + 1 > static_cast<uint64_t>(room)) {
                out[0] = 0;
                return -kInvalidData;
            }
            std::memcpy(out, text.data(), text.size());
            out[text.size()] = 0;
            return static_cast<int64_t>(text.size());
        }
        if (code == 2) {
            std::string_view text;
            if (!readPlcText(c, pJson->i(c), text) || !json::nestingWithin(text)) return -kInvalidData;
            Json parsed = Json::parse(text, nullptr, false);
            if (parsed.is_discarded()) return -kInvalidData;
            fromJson(t, data, parsed);
            return 0;
        }
        return -kInvalidData;
    }
};

}  // namespace

void registerTc3JsonSymbolNatives(Checker& ck) {
    ck.addBuiltin("F_STRUN_JSONSYMBOL", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"OP"}, {"PTYPE"}, {"NDATA"}, {"PDATA"}, {"PJSON"}, {"NJSON"}}, a)) return ck.bad(call.loc);
        const TK kinds[6] = {TK::DInt, TK::ULInt, TK::LInt, TK::ULInt, TK::ULInt, TK::LInt};
        exec::Expr* nodes[6];
        for (int k = 0; k < 6; ++k) {
            Checked v = a[k];
            if (!(v.ok && kinds[k] == TK::ULInt && v.type && v.type->kind == TK::Pointer))
                v = ck.coerce(v, ck.types().elementary(kinds[k]), v.loc, call.name.c_str());
            if (!v.ok) return v;
            nodes[k] = v.node;
        }
        // The project's declared types by name, as the checker resolved them (copied once, for the run).
        auto* names = ck.pool().make<TypeNames>(sema::CheckerAccess::declaredTypes(ck));
        auto* node = ck.pool().make<JsonSymbolNode>(names, nodes[0], nodes[1], nodes[2], nodes[3], nodes[4], nodes[5]);
        return makeResult(ck, node, ck.types().elementary(TK::LInt), call, a, false);
    });
}

}  // namespace strun::stdlib::bind
