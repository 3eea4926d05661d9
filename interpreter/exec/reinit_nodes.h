// `inst.FB_init(bInitRetains, bInCopyCode)` on a block that declares no
// FB_init (decision 0457): the implicit FB_init, which writes the instance's
// initial values again, as when the application started. Not a hot path:
// code calls it to reset an instance after an error.
#pragma once

#include <cstring>
#include <utility>
#include <vector>

#include "interpreter/exec/call_nodes.h"

namespace strun::exec {

struct ReinitInstance final : Expr {
    // The initial image of each class the instance may have (the static
    // type and every block extending it), with the byte ranges an address
    // initialiser wrote at start-up (`p : POINTER TO INT := ADR(x)`), which
    // keep their values: the image has no address in them.
    struct ClassImage {
        const ClassDesc* desc = nullptr;
        const std::vector<uint8_t>* image = nullptr;
        std::vector<std::pair<uint32_t, uint32_t>> kept;  // [begin, end), sorted
    };
    Expr* instance;  // the instance, a place
    std::vector<ClassImage> classes;
    explicit ReinitInstance(Expr* inst) : instance(inst) {}
    int64_t i(Ctx& c) override {
        uint8_t* p = instance->addr(c);
        if (!p || !c.m->memory.contains(p, sizeof(const ClassDesc*))) return 0;
        const auto* desc = loadAs<const ClassDesc*>(p);
        for (const ClassImage& k : classes) {
            if (k.desc != desc) continue;
            const std::vector<uint8_t>& image = *k.image;
            if (!c.m->memory.contains(p, image.size())) return 0;
            uint32_t from = 0;
            for (const auto& [begin, end] : k.kept) {
                if (begin > from) std::memcpy(p + from, image.data() + from, begin - from);
                from = std::max(from, end);
            }
            if (from < image.size()) std::memcpy(p + from, image.data() + from, image.size() - from);
            return 1;  // FB_init's BOOL result
        }
        return 0;
    }
};

}  // namespace strun::exec
