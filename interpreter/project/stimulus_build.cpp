#include "interpreter/project/stimulus_build.h"

#include <cctype>

#include "interpreter/project/literal_value.h"
#include "interpreter/project/variable_path.h"
#include "stdlib/literals.h"

namespace strun::project {

using sema::TK;

namespace {

// %IX<byte>.<bit>, %IB<n>, %IW<n>, %ID<n>, %IL<n> (CODESYS: n counts units of
// the access size), and with WriteScope::Anywhere the same for %Q and %M.
// Fills the type, the byte offset and the bit; `ref.addr` points into the
// physical inputs for %I, into the program's image for %Q and %M.
bool parseDirectAddress(sema::ProgramModel& model, const std::string& name, WriteScope scope, VariableRef& ref, size_t& offset,
                        std::string& error) {
    std::string up;
    for (char c : name) up += char(std::toupper(static_cast<unsigned char>(c)));
    if (up.size() < 3 || up[0] != '%') return false;
    const char area = up[1];
    const bool anywhere = scope == WriteScope::Anywhere;
    const char* examples = anywhere ? "(%IX0.3, %IB2, %QW4, %MD1, %QL0)" : "(%IX0.3, %IB2, %IW4, %ID1, %IL0)";
    if (area != 'I' && !(anywhere && (area == 'Q' || area == 'M'))) {
        error = anywhere ? "'" + name + "' is not a direct address " + examples
                         : "'" + name + "': only inputs (%I...) can be set from outside; %Q and %M belong to the program";
        return true;
    }
    char size = up[2];
    std::string rest = up.substr(3);
    if (std::isdigit(static_cast<unsigned char>(size))) {  // %I0.3 = %IX0.3
        rest = up.substr(2);
        size = 'X';
        up.insert(up.begin() + 2, 'X');
    }
    TK kind;
    uint64_t unit;
    switch (size) {
        case 'X': kind = TK::Bool; unit = 1; break;
        case 'B': kind = TK::Byte; unit = 1; break;
        case 'W': kind = TK::Word; unit = 2; break;
        case 'D': kind = TK::DWord; unit = 4; break;
        case 'L': kind = TK::LWord; unit = 8; break;
        default:
            error = "'" + name + "' is not a direct " + std::string(anywhere ? "" : "input ") + "address " + examples;
            return true;
    }
    size_t dot = rest.find('.');
    if ((kind == TK::Bool) != (dot != std::string::npos)) {
        error = "'" + name + "' is not a direct " + std::string(anywhere ? "" : "input ") + "address " + examples;
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
    const char* areaName = area == 'I' ? "input" : area == 'Q' ? "output" : "memory";
    if (!index || index.value() >= rt::ProcessImage::kSize / unit) {
        error = "'" + name + "' is outside the " + areaName + " image (" + std::to_string(rt::ProcessImage::kSize) + " bytes)";
        return true;
    }
    rt::ProcessImage& image = model.machine.image;
    offset = size_t(index.value() * unit);
    ref.path = anywhere ? up : name;  // --trace keeps what the user typed; live names are canonical
    ref.type = model.types->elementary(kind);
    ref.addr = (area == 'I' ? image.physicalInputs : area == 'Q' ? image.outputs : image.memory).data() + offset;
    ref.bit = bit;
    return true;
}

}  // namespace

bool resolveWrite(sema::ProgramModel& model, const StimulusEntry& e, ResolvedWrite& out, std::string& error,
                  const rt::PlcProfile& profile, WriteScope scope) {
    rt::ProcessImage& image = model.machine.image;
    auto fail = [&](const std::string& why) {
        error = e.origin.empty() ? why : e.origin + ": " + why;
        return false;
    };
    VariableRef ref;
    rt::StimulusWrite& w = out.write;
    w = rt::StimulusWrite{};
    w.at = e.at;
    std::string why;
    size_t offset = 0;
    std::string address = e.name;
    if (auto alias = rt::findInputAlias(profile, e.name))
        address = "%IX" + std::to_string(alias->byte) + "." + std::to_string(alias->bit);
    if (parseDirectAddress(model, address, scope, ref, offset, why)) {
        if (!why.empty()) return fail(why);
        if (ref.addr >= image.physicalInputs.data() && ref.addr < image.physicalInputs.data() + rt::ProcessImage::kSize)
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
    if (address != e.name) ref.path = e.name;  // the alias, for --trace
    if (!encodeLiteral(ref.type, e.value, w.bytes, why)) return fail(why);
    if (ref.bit >= 0 || ref.type->kind == TK::Bool) w.bytes.resize(1);
    w.dest = ref.addr;
    w.bit = ref.bit;
    w.inputOffset = offset;
    std::string value = e.value;
    while (!value.empty() && std::isspace(static_cast<unsigned char>(value.back()))) value.pop_back();
    while (!value.empty() && std::isspace(static_cast<unsigned char>(value.front()))) value.erase(value.begin());
    w.text = ref.path + " := " + value;
    out.type = ref.type;
    out.name = ref.path;
    return true;
}

bool buildStimulus(sema::ProgramModel& model, const std::vector<StimulusEntry>& entries, rt::Stimulus& out, std::string& error,
                   const rt::PlcProfile& profile) {
    for (const StimulusEntry& e : entries) {
        ResolvedWrite resolved;
        if (!resolveWrite(model, e, resolved, error, profile, WriteScope::Inputs)) return false;
        out.add(std::move(resolved.write));
    }
    return true;
}

}  // namespace strun::project
