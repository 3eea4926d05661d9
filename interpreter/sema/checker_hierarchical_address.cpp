// IEC 61131-3 hierarchical direct addresses (decision 0390): `%IW2.5.7`,
// `%QX1.2.3.4`, `%MD0.1.2`. The standard reads the fields from the highest
// level (rack, module, channel, ...) and leaves their meaning to the
// implementation; Beremiz/matiec give each such address a location of its
// own, named by the whole path. strun has one flat image per area and no
// racks, so it does the same: every distinct path (area, size and all fields
// but a BOOL's bit) is one location, placed at the top end of its area and
// shared by every declaration at that path; `%MX7.1.5` is bit 5 of the byte
// `%MB7.1`, as `%MX7.5` is of `%MB7`. Flat addresses (%IW7, %IX3.2) keep CODESYS addressing
// below them, and the two never overlap (an overlap is an error).
#include <algorithm>

#include <fmt/format.h>

#include "interpreter/sema/checker.h"

namespace strun::sema {

uint8_t* Checker::mapHierarchicalAddress(rt::ImageArea& area, const std::string& address, const std::vector<uint64_t>& parts,
                                         uint64_t unit, const Type* t, const ast::Loc& loc, int& bit) {
    auto fail = [&](const std::string& why) -> uint8_t* {
        error(diag::E0408, loc, fmt::format("bad direct address '{}': {}", address, why));
        return nullptr;
    };
    std::string a = upper(address);
    const char size = unit == 0 ? 'B' : a[2];  // %MX7.1.5 is bit 5 of %MB7.1
    std::string key = fmt::format("{}{}", a[1], size);
    const size_t pathFields = unit == 0 ? parts.size() - 1 : parts.size();
    for (size_t k = 0; k < pathFields; ++k) {
        if (k) key += '.';
        key += std::to_string(parts[k]);
    }
    if (unit == 0) {
        bit = static_cast<int>(parts.back());
        if (bit > 7) return fail("bit number above 7");
        if (t->kind != TK::Bool) return fail("a bit address needs a BOOL variable");
    } else {
        bit = -1;
        // `x AT %MW1.3 : BOOL` most likely means bit 3 of %MW1, which is %MX2.3.
        if (t->kind == TK::Bool) return fail("a bit number only goes with X addresses");
        if (t->size > unit && t->kind != TK::Array && t->kind != TK::Struct && !isStringType(t->kind))
            log_.warning(diag::W0008, loc, fmt::format("{} is larger than the {}-byte address '{}'", typeName(t), unit, address));
    }
    const size_t bytes = std::max<size_t>({size_t(1), size_t(unit), size_t(t->size)});
    if (auto it = hierarchicalSlots_.find(key); it != hierarchicalSlots_.end()) {
        if (bytes > it->second.size)
            return fail(fmt::format("{} needs {} bytes where an earlier declaration at this address took {}", typeName(t), bytes, it->second.size));
        return area.data() + it->second.offset;
    }
    // Downwards from the top of the area, aligned to the access size.
    size_t& used = hierarchicalUsed_[&area];
    const size_t align = std::max<size_t>(1, std::min<size_t>(size_t(unit), 8));
    if (used + bytes + align > area.size() - flatEnd_[&area])
        return fail("the hierarchical addresses need more room than the process image leaves above its flat addresses");
    size_t offset = (area.size() - used - bytes) / align * align;
    used = area.size() - offset;
    hierarchicalSlots_[key] = {offset, bytes};
    // Tasks copy the addressed part of %I / %Q: it now reaches the top.
    auto& image = model_.machine.image;
    if (&area == &image.inputs) image.inputExtent = area.size();
    if (&area == &image.outputs) image.outputExtent = area.size();
    return area.data() + offset;
}

}  // namespace strun::sema
