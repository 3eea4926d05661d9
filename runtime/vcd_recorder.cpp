#include "runtime/vcd_recorder.h"

#include <charconv>
#include <cstring>
#include <map>
#include <memory>
#include <unordered_map>

#include "runtime/fnv1a.h"

namespace strun::rt {

namespace {

// VCD identifier codes: printable ASCII '!'..'~', as a base-94 number.
std::string idCode(size_t n) {
    std::string id;
    do {
        id += char('!' + n % 94);
        n /= 94;
    } while (n);
    return id;
}

// A scope tree, so signals of one scope are declared together whatever their order.
// Children are held by pointer: a reference returned by child() stays valid
// while further children are added (and Scope is complete where it is used).
struct Scope {
    std::string name;
    std::vector<std::unique_ptr<Scope>> children;  // declaration order
    std::unordered_map<std::string, Scope*> byName;  // an array of structures has a scope per element
    std::vector<std::string> vars;                 // "$var ... $end" lines
    Scope& child(const std::string& childName) {
        auto [it, fresh] = byName.try_emplace(childName, nullptr);
        if (fresh) {
            children.push_back(std::make_unique<Scope>());
            children.back()->name = childName;
            it->second = children.back().get();
        }
        return *it->second;
    }
    void write(std::FILE* out) const {
        for (const std::string& v : vars) std::fputs(v.c_str(), out);
        for (const auto& c : children) {
            std::fprintf(out, "$scope module %s $end\n", c->name.c_str());
            c->write(out);
            std::fputs("$upscope $end\n", out);
        }
    }
};

// VCD references may not contain blanks.
std::string reference(std::string name) {
    for (char& c : name)
        if (c == ' ' || c == '\t') c = '_';
    return name;
}

}  // namespace

VcdRecorder::VcdRecorder(std::FILE* out, const std::vector<std::string>& taskNames, std::vector<VcdSignal> signals,
                         const std::string& version, const std::vector<bool>& taskWaveforms)
    : out_(out), signals_(std::move(signals)) {
    Scope root;
    for (size_t i = 0; i < taskNames.size(); ++i) {
        if (i < taskWaveforms.size() && !taskWaveforms[i]) {
            taskIds_.emplace_back();
            continue;
        }
        taskIds_.push_back(idCode(i));
        root.child("tasks").vars.push_back("$var wire 1 " + taskIds_.back() + " " + reference(taskNames[i]) + " $end\n");
    }
    byTask_.assign(taskNames.size(), {});
    for (size_t i = 0; i < signals_.size(); ++i) {
        const VcdSignal& s = signals_[i];
        signalIds_.push_back(idCode(taskNames.size() + i));
        Scope* scope = &root;
        if (s.scopes)
            for (const std::string& name : *s.scopes) scope = &scope->child(reference(name));
        std::string decl;
        switch (s.kind) {
            case VcdSignal::Kind::Bit: decl = "$var wire 1 "; break;
            case VcdSignal::Kind::Vector: decl = "$var wire " + std::to_string(s.width) + " "; break;
            case VcdSignal::Kind::Real32:
            case VcdSignal::Kind::Real64: decl = "$var real 64 "; break;
            case VcdSignal::Kind::EnumName:
            case VcdSignal::Kind::Text: decl = "$var string 1 "; break;
        }
        scope->vars.push_back(decl + signalIds_.back() + " " + reference(s.name) + " $end\n");
        if (s.task == VcdSignal::kAfterOutputPhase) physicalOutputs_.push_back(i);
        for (size_t t = 0; t < byTask_.size(); ++t)
            if (s.task == -1 || (s.task >= 0 && size_t(s.task) == t)) byTask_[t].push_back(i);
    }
    std::fprintf(out_, "$version %s $end\n$timescale 1ns $end\n", version.c_str());
    root.write(out_);
    std::fputs("$enddefinitions $end\n#0\n$dumpvars\n", out_);
    stamped_ = 0;
    taskState_.assign(taskNames.size(), 0);
    for (const std::string& id : taskIds_)
        if (!id.empty()) std::fprintf(out_, "0%s\n", id.c_str());
    last_.resize(signals_.size());
    for (size_t i = 0; i < signals_.size(); ++i) {
        last_[i] = read(signals_[i]);
        writeValue(signals_[i], last_[i], signalIds_[i]);
    }
    std::fputs(buffer_.c_str(), out_);
    buffer_.clear();
    std::fputs("$end\n", out_);
}

uint64_t VcdRecorder::read(const VcdSignal& s) const {
    switch (s.kind) {
        case VcdSignal::Kind::Bit: return s.bit >= 0 ? ((*s.addr >> s.bit) & 1) : (*s.addr != 0);
        case VcdSignal::Kind::Real32: {
            uint32_t bits;
            std::memcpy(&bits, s.addr, 4);
            return bits;
        }
        case VcdSignal::Kind::Real64: {
            uint64_t bits;
            std::memcpy(&bits, s.addr, 8);
            return bits;
        }
        case VcdSignal::Kind::Text: {
            // A change of the characters is a change of this hash (FNV-1a up to the NUL).
            uint64_t h = kFnv1aBasis;
            for (uint32_t i = 0; i < s.size && s.addr[i] != 0; ++i) h = fnv1aStep(h, s.addr[i]);
            return h;
        }
        case VcdSignal::Kind::EnumName:
        case VcdSignal::Kind::Vector: break;
    }
    uint64_t raw = 0;
    std::memcpy(&raw, s.addr, s.size);  // little-endian host: the low bytes
    if (s.isSigned && s.size < 8) {
        unsigned shift = 64 - 8 * s.size;
        raw = uint64_t(int64_t(raw << shift) >> shift);
    }
    return s.scale == 1 ? raw : uint64_t(int64_t(raw) * s.scale);
}

void VcdRecorder::writeValue(const VcdSignal& s, uint64_t value, const std::string& id) {
    char text[80];
    switch (s.kind) {
        case VcdSignal::Kind::Bit:
            buffer_ += value ? '1' : '0';
            break;
        case VcdSignal::Kind::Real32:
        case VcdSignal::Kind::Real64: {
            // Shortest text that reads back as the same value (to_chars: no printf on the sampling path).
            text[0] = 'r';
            std::to_chars_result r;
            if (s.kind == VcdSignal::Kind::Real32) {
                float f;
                uint32_t bits = uint32_t(value);
                std::memcpy(&f, &bits, 4);
                r = std::to_chars(text + 1, text + sizeof text - 1, f);
            } else {
                double d;
                std::memcpy(&d, &value, 8);
                r = std::to_chars(text + 1, text + sizeof text - 1, d);
            }
            buffer_.append(text, r.ptr);
            buffer_ += ' ';
            break;
        }
        case VcdSignal::Kind::EnumName: {
            buffer_ += 's';
            bool named = false;
            for (const auto& [v, name] : s.names)
                if (uint64_t(v) == value) {
                    buffer_ += name;
                    named = true;
                    break;
                }
            if (!named) buffer_ += std::to_string(int64_t(value));  // a value without a name
            buffer_ += ' ';
            break;
        }
        case VcdSignal::Kind::Text: {
            // VCD values are blank-separated tokens: blanks, controls and '\\' as \xNN.
            buffer_ += 's';
            for (uint32_t i = 0; i < s.size && s.addr[i] != 0; ++i) {
                unsigned char c = s.addr[i];
                if (c <= ' ' || c == '\\' || c == 0x7f) {
                    static const char hex[] = "0123456789ABCDEF";
                    buffer_ += "\\x";
                    buffer_ += hex[c >> 4];
                    buffer_ += hex[c & 15];
                } else {
                    buffer_ += char(c);
                }
            }
            buffer_ += ' ';
            break;
        }
        case VcdSignal::Kind::Vector: {
            // Leading zeros left out (VCD extends a value with 0 to the left).
            if (s.width < 64) value &= (uint64_t(1) << s.width) - 1;
            buffer_ += 'b';
            int top = 63;
            while (top > 0 && !((value >> top) & 1)) --top;
            for (int b = top; b >= 0; --b) buffer_ += ((value >> b) & 1) ? '1' : '0';
            buffer_ += ' ';
            break;
        }
    }
    buffer_ += id;
    buffer_ += '\n';
}

void VcdRecorder::stampTime(PlcTime now) {
    if (now <= stamped_) return;  // VCD times only increase; same-time changes share a stamp
    stamped_ = now;
    buffer_ += '#';
    buffer_ += std::to_string(now);
    buffer_ += '\n';
}

void VcdRecorder::taskRunning(size_t task, bool running, PlcTime now) {
    if (task >= taskState_.size() || taskState_[task] == uint8_t(running) || taskIds_[task].empty()) return;
    taskState_[task] = running;
    stampTime(now);
    buffer_ += running ? '1' : '0';
    buffer_ += taskIds_[task];
    buffer_ += '\n';
    flushIfLarge();
}

void VcdRecorder::activationEnded(size_t task, PlcTime now) {
    if (task < byTask_.size()) sample(byTask_[task], now);
    flushIfLarge();
}

void VcdRecorder::outputsWritten(PlcTime now) {
    sample(physicalOutputs_, now);
}

void VcdRecorder::flushIfLarge() {
    if (buffer_.size() < (1u << 16)) return;
    std::fwrite(buffer_.data(), 1, buffer_.size(), out_);
    buffer_.clear();
}

void VcdRecorder::sample(const std::vector<size_t>& which, PlcTime now) {
    for (size_t i : which) {
        uint64_t value = read(signals_[i]);
        if (value == last_[i]) continue;
        last_[i] = value;
        stampTime(now);
        writeValue(signals_[i], value, signalIds_[i]);
    }
}

void VcdRecorder::runEnded(PlcTime end) {
    for (size_t t = 0; t < taskState_.size(); ++t) taskRunning(t, false, end);
    stampTime(end);  // the waveform reaches the end of the run
    std::fwrite(buffer_.data(), 1, buffer_.size(), out_);
    buffer_.clear();
    std::fflush(out_);
}

}  // namespace strun::rt
