#include "runtime/stimulus.h"

#include <algorithm>
#include <cstring>

#include "runtime/duration_text.h"

namespace strun::rt {

void Stimulus::add(StimulusWrite write) {
    writes_.push_back(std::move(write));
    sorted_ = false;
}

void Stimulus::sortOnce() {
    if (sorted_) return;
    sorted_ = true;
    variables_.clear();
    inputs_.clear();
    for (size_t i = 0; i < writes_.size(); ++i)
        (writes_[i].kind == StimulusWrite::Kind::Variable ? variables_ : inputs_).push_back(i);
    auto byTime = [&](size_t a, size_t b) { return writes_[a].at < writes_[b].at; };
    std::stable_sort(variables_.begin(), variables_.end(), byTime);
    std::stable_sort(inputs_.begin(), inputs_.end(), byTime);
    nextVariable_ = nextInput_ = 0;
}

PlcTime Stimulus::nextInputAt() {
    sortOnce();
    return nextInput_ < inputs_.size() ? writes_[inputs_[nextInput_]].at : kNever;
}

void Stimulus::applyVariablesDue(PlcTime now, std::ostream* trace) {
    sortOnce();
    applyDue(StimulusWrite::Kind::Variable, variables_, nextVariable_, now, trace);
}

void Stimulus::applyInputsDue(PlcTime now, std::ostream* trace) {
    sortOnce();
    applyDue(StimulusWrite::Kind::PhysicalInput, inputs_, nextInput_, now, trace);
}

void Stimulus::applyDue(StimulusWrite::Kind kind, std::vector<size_t>& queue, size_t& next, PlcTime now, std::ostream* trace) {
    while (next < queue.size() && writes_[queue[next]].at <= now) {
        const StimulusWrite& w = writes_[queue[next++]];
        bool changed;
        if (w.bit >= 0) {
            uint8_t before = *w.dest;
            uint8_t mask = uint8_t(1u << w.bit);
            *w.dest = (!w.bytes.empty() && w.bytes[0]) ? (before | mask) : (before & uint8_t(~mask));
            changed = *w.dest != before;
        } else {
            changed = std::memcmp(w.dest, w.bytes.data(), w.bytes.size()) != 0;
            std::memcpy(w.dest, w.bytes.data(), w.bytes.size());
        }
        if (trace) {
            // Inputs change at their own time; variables when the activation starts.
            line_.clear();
            appendDuration(line_, kind == StimulusWrite::Kind::PhysicalInput ? w.at : now);
            line_ += " set ";
            line_ += w.text;
            line_ += '\n';
            trace->write(line_.data(), std::streamsize(line_.size()));
        }
        if (kind == StimulusWrite::Kind::PhysicalInput && changed && listener_) listener_(w, w.at);
    }
}

}  // namespace strun::rt
