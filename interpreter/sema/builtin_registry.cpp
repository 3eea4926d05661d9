#include "interpreter/sema/builtin_registry.h"

#include "interpreter/sema/checker.h"

namespace strun::sema {

Checked BuiltinFn::operator()(Checker& ck, CallArgs& call) const { return check_(ck, call, *this); }

Checked BuiltinFn::callPlain(Checker& ck, CallArgs& call, const BuiltinFn& self) { return self.data<Plain>()(ck, call); }

namespace {

uint64_t hashOf(std::string_view s) {
    uint64_t h = 1469598103934665603ull;  // FNV-1a
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    return h;
}

}  // namespace

uint32_t& BuiltinRegistry::slotFor(std::string_view name, uint64_t hash) {
    const size_t mask = slots_.size() - 1;
    for (size_t i = hash & mask;; i = (i + 1) & mask) {
        uint32_t& s = slots_[i];
        if (s == 0 || nameOf(entries_[s - 1]) == name) return s;
    }
}

const uint32_t* BuiltinRegistry::findSlot(std::string_view name) const {
    if (slots_.empty()) return nullptr;
    const size_t mask = slots_.size() - 1;
    for (size_t i = hashOf(name) & mask;; i = (i + 1) & mask) {
        const uint32_t& s = slots_[i];
        if (s == 0) return nullptr;
        if (nameOf(entries_[s - 1]) == name) return &s;
    }
}

void BuiltinRegistry::grow() {
    // Kept at most half full: the standard library alone registers ~600 names.
    slots_.assign(slots_.empty() ? 2048 : slots_.size() * 2, 0);
    for (uint32_t k = 0; k < entries_.size(); ++k) slotFor(nameOf(entries_[k]), hashOf(nameOf(entries_[k]))) = k + 1;
}

void BuiltinRegistry::add(std::string_view upperName, const BuiltinFn& fn) {
    if ((entries_.size() + 1) * 2 > slots_.size()) grow();
    uint32_t& slot = slotFor(upperName, hashOf(upperName));
    if (slot != 0) {
        entries_[slot - 1].fn = fn;
        return;
    }
    if (names_.empty()) names_.reserve(16 * 1024);
    if (entries_.empty()) entries_.reserve(1024);
    entries_.push_back({static_cast<uint32_t>(names_.size()), static_cast<uint32_t>(upperName.size()), fn});
    names_.append(upperName);
    slot = static_cast<uint32_t>(entries_.size());
}

const BuiltinFn* BuiltinRegistry::find(std::string_view upperName) const {
    const uint32_t* s = findSlot(upperName);
    return s ? &entries_[*s - 1].fn : nullptr;
}

std::vector<std::string> BuiltinRegistry::names() const {
    std::vector<std::string> out;
    out.reserve(entries_.size());
    for (const Entry& e : entries_) out.emplace_back(nameOf(e));
    return out;
}

}  // namespace strun::sema
