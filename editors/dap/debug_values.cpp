#include "editors/dap/debug_values.h"

#include <cstdio>
#include <memory>

#include "interpreter/project/dump_json.h"
#include "stdlib/literals.h"

namespace strun::editors::dap {

using sema::TK;

bool expandable(const sema::Type* t) {
    return t && (t->kind == TK::Array || t->kind == TK::Struct || t->kind == TK::FunctionBlock);
}

std::string stLiteral(const sema::Type* t, const uint8_t* p, int bit) {
    if (!t || !p) return "?";
    if (bit >= 0) return ((*p >> bit) & 1) ? "TRUE" : "FALSE";
    switch (t->kind) {
        case TK::Bool: return *p ? "TRUE" : "FALSE";
        case TK::Real:
        case TK::LReal: {
            const auto j = project::valueToJson(t, p);
            if (j.is_string()) {
                const std::string s = j.get<std::string>();
                return s == "nan" ? "NAN" : s == "inf" ? "INF" : "-INF";
            }
            std::string s = j.dump();
            if (s.find_first_of(".eE") == std::string::npos) s += ".0";
            return s;
        }
        case TK::String: return stdlib::quoteStringLiteral(project::valueToJson(t, p).get<std::string>());
        case TK::WString: return stdlib::quoteStringLiteral(project::valueToJson(t, p).get<std::string>(), true);
        case TK::Char: return stdlib::quoteStringLiteral(project::valueToJson(t, p).get<std::string>());
        case TK::WChar: return stdlib::quoteStringLiteral(project::valueToJson(t, p).get<std::string>(), true);
        case TK::Enum: {
            const auto j = project::valueToJson(t, p);
            return j.is_string() ? t->name + "#" + j.get<std::string>() : t->name + "#" + j.dump();
        }
        case TK::Array:
        case TK::Struct:
        case TK::FunctionBlock: return sema::typeName(t);
        case TK::Pointer:
        case TK::Reference: {
            uintptr_t a = 0;
            for (unsigned k = 0; k < sizeof(uintptr_t) && k < t->size; ++k) a |= static_cast<uintptr_t>(p[k]) << (8 * k);
            if (!a) return "0";
            char buf[32];
            std::snprintf(buf, sizeof buf, "16#%llX", static_cast<unsigned long long>(a));
            return buf;
        }
        case TK::Interface: return sema::typeName(t);
        case TK::Void: return "";
        default: {
            const auto j = project::valueToJson(t, p);
            return j.is_string() ? j.get<std::string>() : j.dump();
        }
    }
}

std::vector<Member> membersOf(const sema::Type* t, uint8_t* p, size_t limit) {
    std::vector<Member> out;
    if (!t || !p) return out;
    if (t->kind == TK::Array) {
        if (t->dims.empty() || !t->elem) return out;
        // The first dimension; a multi-dimensional array's rows are arrays of the rest.
        const sema::ArrayDim first = t->dims.front();
        const uint64_t rows = static_cast<uint64_t>(first.count());
        const uint64_t rowSize = rows ? t->size / rows : 0;
        sema::Type* rest = nullptr;
        static thread_local std::vector<std::unique_ptr<sema::Type>> rowTypes;  // the row types of multi-dimensional arrays
        if (t->dims.size() > 1) {
            auto row = std::make_unique<sema::Type>(*t);
            row->dims.erase(row->dims.begin());
            row->size = static_cast<uint32_t>(rowSize);
            row->name = "ARRAY";
            rest = row.get();
            rowTypes.push_back(std::move(row));
        }
        for (uint64_t k = 0; k < rows && out.size() < limit; ++k) {
            const std::string index = "[" + std::to_string(first.lo + static_cast<int64_t>(k)) + "]";
            out.push_back({index, index, rest ? rest : t->elem, p + k * rowSize});
        }
        return out;
    }
    std::vector<const sema::Type*> chain;
    for (const sema::Type* s = t; s; s = s->parent) chain.insert(chain.begin(), s);
    for (const sema::Type* s : chain)
        for (const sema::Field& f : s->fields) {
            if (out.size() >= limit) return out;
            if (f.hidden) continue;  // a graphical translation's own (decision 0290)
            out.push_back({f.name, "." + f.name, f.type, p + f.offset});
        }
    return out;
}

}  // namespace strun::editors::dap
