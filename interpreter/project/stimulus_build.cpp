#include "interpreter/project/stimulus_build.h"

#include <cctype>

#include "interpreter/project/literal_value.h"
#include "interpreter/project/variable_path.h"
#include "stdlib/literals.h"

namespace strun::project {

using sema::TK;

namespace {

// %IX<byte>.<bit>, %IB<n>, %IW<n>, %ID<n>, %IL<n> (CODESYS: n counts units of
// the access size). Fills the type, the byte offset and the bit.
bool parseInputAddress(sema::ProgramModel& model, const std::string& name, VariableRef& ref, size_t& offset, std::string& error) {
    std::string up;
    for (char c : name) up += char(std::toupper(static_cast<unsigned char>(c)));
    if (up.size() < 3 || up[0] != '%') return false;
    if (up[1] != 'I') {
        error = "'" + name + "': only inputs (%I...) can be set from outside; %Q and %M belong to the program";
        return true;
    }
    char size = up[2];
    std::string rest = up.substr(3);
    if (std::isdigit(static_cast<unsigned char>(size))) {  // %I0.3 = %IX0.3
        rest = up.substr(2);
        size = 'X';
    }
    TK kind;
    uint64_t unit;
    switch (size) {
        case 'X': kind = TK::Bool; unit = 1; break;
        case 'B': kind = TK::Byte; unit = 1; break;
        case 'W': kind = TK::Word; unit = 2; break;
        case 'D': kind = TK::DWord; unit = 4; break;
        case 'L': kind = TK::LWord; unit = 8; break;
        default: error = "'" + name + "' is not a direct input address (%IX0.3, %IB2, %IW4, %ID1, %IL0)"; return true;
    }
    size_t dot = rest.find('.');
    if ((kind == TK::Bool) != (dot != std::string::npos)) {
        error = "'" + name + "' is not a direct input address (%IX0.3, %IB2, %IW4, %ID1, %IL0)";
        return true;
    }
    auto index = stdlib::parseIntegerLiteral(rest.substr(0, dot));
    int bit = -1;
    if (dot != std::string::npos) {
        auto b = stdlib::parseIntegerLiteral(rest.substr(dot + 1));
        if (!b || b.value() > 7) {
            error = "'" + name + "': the bit number must be 0..7";
            return true;
        }
        bit = int(b.value());
    }
    if (!index || index.value() >= rt::ProcessImage::kSize / unit) {
        error = "'" + name + "' is outside the input image (" + std::to_string(rt::ProcessImage::kSize) + " bytes)";
        return true;
    }
    offset = size_t(index.value() * unit);
    ref.path = name;
    ref.type = model.types->elementary(kind);
    ref.addr = model.machine.image.physicalInputs.data() + offset;
    ref.bit = bit;
    return true;
}

}  // namespace

bool buildStimulus(sema::ProgramModel& model, const std::vector<StimulusEntry>& entries, rt::Stimulus& out, std::string& error) {
    rt::ProcessImage& image = model.machine.image;
    for (const StimulusEntry& e : entries) {
        auto fail = [&](const std::string& why) {
            error = e.origin + ": " + why;
            return false;
        };
        VariableRef ref;
        rt::StimulusWrite w;
        w.at = e.at;
        std::string why;
        size_t offset = 0;
        if (parseInputAddress(model, e.name, ref, offset, why)) {
            if (!why.empty()) return fail(why);
            w.kind = rt::StimulusWrite::Kind::PhysicalInput;
        } else {
            auto found = resolveVariablePath(model, e.name, why);
            if (!found) return fail(why);
            ref = *found;
            if (ref.constant) return fail("'" + ref.path + "' is a CONSTANT and cannot be set");
            const uint8_t* inputs = image.inputs.data();
            if (ref.addr >= inputs && ref.addr < inputs + rt::ProcessImage::kSize) {
                // AT %I...: set the physical input the variable shows.
                offset = size_t(ref.addr - inputs);
                ref.addr = image.physicalInputs.data() + offset;
                w.kind = rt::StimulusWrite::Kind::PhysicalInput;
            }
        }
        if (!encodeLiteral(ref.type, e.value, w.bytes, why)) return fail(why);
        if (ref.bit >= 0 || ref.type->kind == TK::Bool) w.bytes.resize(1);
        w.dest = ref.addr;
        w.bit = ref.bit;
        w.inputOffset = offset;
        std::string value = e.value;
        while (!value.empty() && std::isspace(static_cast<unsigned char>(value.back()))) value.pop_back();
        while (!value.empty() && std::isspace(static_cast<unsigned char>(value.front()))) value.erase(value.begin());
        w.text = ref.path + " := " + value;
        out.add(std::move(w));
    }
    return true;
}

}  // namespace strun::project
