// The checker's table of built-in functions by upper-case name: an open-
// addressing hash of names kept in one character buffer, each with its
// BuiltinFn (a function pointer and a few values). Filling it with the ~490
// standard, library and test built-ins costs a handful of allocations, not
// one map node, one string and one std::function each (decision 0487).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/sema/builtin_fn.h"

namespace strun::sema {

class BuiltinRegistry {
public:
    // Registers `upperName`; a later registration of the same name replaces
    // the earlier one (the order the registrars run in decides, as before).
    void add(std::string_view upperName, const BuiltinFn& fn);
    const BuiltinFn* find(std::string_view upperName) const;
    // Every registered name, in no particular order.
    std::vector<std::string> names() const;
    size_t size() const { return entries_.size(); }

private:
    struct Entry {
        uint32_t offset, length;  // of the name in names_
        BuiltinFn fn;
    };
    std::string_view nameOf(const Entry& e) const { return std::string_view(names_).substr(e.offset, e.length); }
    // The slot holding `name`'s entry index + 1, or the empty slot where it goes.
    uint32_t& slotFor(std::string_view name, uint64_t hash);
    const uint32_t* findSlot(std::string_view name) const;
    void grow();

    std::vector<Entry> entries_;
    std::vector<uint32_t> slots_;  // entry index + 1; 0 = empty; size a power of two
    std::string names_;
};

}  // namespace strun::sema
