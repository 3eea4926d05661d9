#include "interpreter/project/dump_json.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <set>

#include "interpreter/exec/node.h"
#include "stdlib/number_scan.h"
#include "stdlib/text_encoding.h"
#include "stdlib/value_format.h"

namespace strun::project {

using sema::TK;
using sema::Type;
using json = nlohmann::ordered_json;

namespace {

json realJson(double v, bool single) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    // The shortest text that reads back as the same REAL, as a JSON number
    // (0.1 rather than the 0.10000000149011612 a float widened to double prints).
    std::string text = single ? stdlib::formatRealJson(static_cast<float>(v)) : stdlib::formatLRealJson(v);
    return std::strtod(text.c_str(), nullptr);
}

int64_t loadSigned(const uint8_t* p, uint32_t size) {
    switch (size) {
        case 1: return exec::loadAs<int8_t>(p);
        case 2: return exec::loadAs<int16_t>(p);
        case 4: return exec::loadAs<int32_t>(p);
        default: return exec::loadAs<int64_t>(p);
    }
}
uint64_t loadUnsigned(const uint8_t* p, uint32_t size) {
    switch (size) {
        case 1: return exec::loadAs<uint8_t>(p);
        case 2: return exec::loadAs<uint16_t>(p);
        case 4: return exec::loadAs<uint32_t>(p);
        default: return exec::loadAs<uint64_t>(p);
    }
}

json arrayJson(const Type* t, const uint8_t* p, size_t dim, uint64_t stride) {
    json arr = json::array();
    const auto& d = t->dims[dim];
    uint64_t inner = stride / static_cast<uint64_t>(d.count());
    for (int64_t k = 0; k < d.count(); ++k) {
        const uint8_t* q = p + static_cast<uint64_t>(k) * inner;
        if (dim + 1 < t->dims.size()) arr.push_back(arrayJson(t, q, dim + 1, inner));
        else arr.push_back(valueToJson(t->elem, q));
    }
    return arr;
}

bool omitted(const Type* t) {
    if (t->kind == TK::Array) return omitted(t->elem);  // an array of pointers is as opaque as one pointer
    return t->kind == TK::Pointer || t->kind == TK::Reference || t->kind == TK::Interface;
}

// Appends a member whose name the checker already made unique in its scope.
// ordered_json's operator[] searches linearly, which made dumping 100 000
// variables quadratic (11 s); appending to the underlying vector is O(1).
void append(json& obj, const std::string& key, json value) {
    auto& members = static_cast<json::object_t::Container&>(obj.get_ref<json::object_t&>());
    members.emplace_back(key, std::move(value));
}

// `shadowed`: the names a derived class declares again (a base's PRIVATE
// member, decision 0393); the base's member is written `Base.name` then.
void membersJson(json& obj, const Type* t, const uint8_t* p, const std::set<std::string>* shadowed = nullptr) {
    if (t->parent) {
        std::set<std::string> names;
        if (shadowed) names = *shadowed;
        for (const auto& f : t->fields) names.insert(stdlib::upperAscii(f.name));
        membersJson(obj, t->parent, p, &names);
    }
    for (const auto& f : t->fields) {
        if (omitted(f.type) || f.hidden) continue;
        const bool hidden = shadowed && shadowed->count(stdlib::upperAscii(f.name));
        append(obj, hidden ? t->name + "." + f.name : f.name, valueToJson(f.type, p + f.offset));
    }
}

}  // namespace

void appendMember(json& obj, const std::string& key, json value) { append(obj, key, std::move(value)); }

json valueToJson(const Type* t, const uint8_t* p) {
    switch (t->kind) {
        case TK::Bool: return *p != 0;
        case TK::SInt: case TK::Int: case TK::DInt: case TK::LInt: return loadSigned(p, t->size);
        case TK::USInt: case TK::UInt: case TK::UDInt: case TK::ULInt:
        case TK::Byte: case TK::Word: case TK::DWord: case TK::LWord: return loadUnsigned(p, t->size);
        case TK::Real: return realJson(exec::loadAs<float>(p), true);
        case TK::LReal: return realJson(exec::loadAs<double>(p), false);
        case TK::Time:  // unsigned in a TwinCAT project (decision 0367)
            if (t->unsignedDuration) return stdlib::formatUnsignedDuration(uint64_t{exec::loadAs<uint32_t>(p)} * 1000000u, "T#");
            return stdlib::formatDuration(static_cast<int64_t>(exec::loadAs<int32_t>(p)) * 1000000);
        case TK::LTime:  // unsigned in a TwinCAT project (decision 0367)
            return t->unsignedDuration ? stdlib::formatUnsignedDuration(exec::loadAs<uint64_t>(p), "T#") : stdlib::formatDuration(exec::loadAs<int64_t>(p));
        case TK::Date: return stdlib::formatDate(static_cast<int64_t>(exec::loadAs<uint32_t>(p)) * 1000000000);
        case TK::Tod: return stdlib::formatTimeOfDay(static_cast<int64_t>(exec::loadAs<uint32_t>(p)) * 1000000);
        case TK::Dt: return stdlib::formatDateTime(static_cast<int64_t>(exec::loadAs<uint32_t>(p)) * 1000000000);
        case TK::LDate: return stdlib::formatDate(exec::loadAs<int64_t>(p));
        case TK::LTod: return stdlib::formatTimeOfDay(exec::loadAs<int64_t>(p));
        case TK::LDt: return stdlib::formatDateTime(exec::loadAs<int64_t>(p));
        case TK::Char: return stdlib::bytesToUtf8(std::string_view(reinterpret_cast<const char*>(p), *p ? 1 : 0));
        case TK::WChar: {
            char16_t ch = exec::loadAs<char16_t>(p);
            return stdlib::utf16ToUtf8(std::u16string_view(&ch, ch ? 1 : 0));
        }
        case TK::String: {
            const char* s = reinterpret_cast<const char*>(p);
            return stdlib::bytesToUtf8(std::string_view(s, strnlen(s, t->maxLen)));
        }
        case TK::WString: {
            std::u16string w;
            for (uint32_t k = 0; k < t->maxLen; ++k) {
                char16_t ch = exec::loadAs<char16_t>(p + 2 * k);
                if (!ch) break;
                w.push_back(ch);
            }
            return stdlib::utf16ToUtf8(w);
        }
        case TK::Enum: {
            int64_t v = sema::isSignedInt(t->base->kind) ? loadSigned(p, t->size) : static_cast<int64_t>(loadUnsigned(p, t->size));
            for (const auto& e : t->enumerators)
                if (e.value == v) return e.name;
            return v;
        }
        case TK::Array: return arrayJson(t, p, 0, t->size);
        case TK::Struct:
        case TK::FunctionBlock: {
            json obj = json::object();
            membersJson(obj, t, p);
            return obj;
        }
        default: return nullptr;
    }
}

json globalsJson(const sema::ProgramModel& model) {
    json obj = json::object();
    for (const sema::VarSym* g : model.globals) {
        if (omitted(g->type) || g->hidden) continue;
        append(obj, g->globalKey(), g->bit >= 0 ? json(((*g->abs >> g->bit) & 1) != 0) : valueToJson(g->type, g->abs));
    }
    return obj;
}

json programsJson(const sema::ProgramModel& model) {
    json obj = json::object();
    for (const auto& inst : model.programs) {
        json vars = json::object();
        for (const auto& v : inst.pou->ownedVars) {
            if (v->section == ast::VarSection::Temp || v->byRef || v->hidden || omitted(v->type)) continue;
            const uint8_t* p = v->storage == sema::Storage::Self ? inst.memory + v->offset : v->abs;
            if (!p) continue;
            append(vars, v->name, v->bit >= 0 ? json(((*p >> v->bit) & 1) != 0) : valueToJson(v->type, p));
        }
        append(obj, inst.name, std::move(vars));
    }
    return obj;
}

nlohmann::ordered_json physicalOutputsJson(const sema::ProgramModel& model) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    const rt::ProcessImage& image = model.machine.image;
    const size_t extent = std::min(image.outputExtent, rt::ProcessImage::kSize);
    for (size_t i = 0; i < extent; ++i)
        if (image.physicalOutputs[i] != 0) out["%QB" + std::to_string(i)] = image.physicalOutputs[i];
    return out;
}

}  // namespace strun::project
