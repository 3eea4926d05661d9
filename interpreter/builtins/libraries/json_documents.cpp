#include "interpreter/builtins/libraries/json_documents.h"

#include <limits>
#include <map>

namespace strun::stdlib::json {

namespace {

uint32_t nextGeneration() {
    static uint32_t generation = 0;
    generation = generation == std::numeric_limits<uint32_t>::max() ? 1 : generation + 1;
    return generation;
}

}  // namespace

bool nestingWithin(std::string_view text) {
    int depth = 0;
    bool inString = false;
    for (size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (inString) {
            if (c == '\\') ++k;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxDepth) return false;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return true;
}

void Document::reset(Json value) {
    root = std::move(value);
    generation = nextGeneration();
    paths.clear();
    byPath.clear();
}

uint64_t Document::handleOf(const Json::json_pointer& path) {
    if (generation == 0) generation = nextGeneration();
    std::string text = path.to_string();
    auto found = byPath.find(text);
    uint32_t index;
    if (found != byPath.end()) {
        index = found->second;
    } else {
        index = static_cast<uint32_t>(paths.size());
        paths.push_back(path);
        byPath.emplace(std::move(text), index);
    }
    return (static_cast<uint64_t>(generation) << 32) | (index + 1u);
}

const Json::json_pointer* Document::pathOf(uint64_t handle) const {
    const uint32_t index = static_cast<uint32_t>(handle & 0xFFFFFFFFu);
    if (handle == 0 || (handle >> 32) != generation || index == 0 || index > paths.size()) return nullptr;
    return &paths[index - 1];
}

Json* Document::resolve(uint64_t handle) {
    const Json::json_pointer* path = pathOf(handle);
    if (!path) return nullptr;
    // Walk the path without exceptions: every step must exist.
    Json* at = &root;
    std::vector<std::string> steps;
    for (Json::json_pointer p = *path; !p.empty(); p = p.parent_pointer()) steps.push_back(p.back());
    for (auto step = steps.rbegin(); step != steps.rend(); ++step) {
        if (at->is_object()) {
            auto it = at->find(*step);
            if (it == at->end()) return nullptr;
            at = &*it;
        } else if (at->is_array()) {
            if (step->empty() || step->size() > 9 || step->find_first_not_of("0123456789") != std::string::npos) return nullptr;
            const size_t index = std::stoul(*step);
            if (index >= at->size()) return nullptr;
            at = &(*at)[index];
        } else {
            return nullptr;
        }
    }
    return at;
}

// Iterators: generation (16 bits) | container handle index (24 bits) | position (24 bits).
uint64_t Document::iterator(uint64_t container, uint64_t position) const {
    return (static_cast<uint64_t>(generation & 0xFFFFu) << 48) | ((container & 0xFFFFFFu) << 24) | (position & 0xFFFFFFu);
}

bool Document::splitIterator(uint64_t it, uint64_t& container, uint64_t& position) const {
    if ((it >> 48) != (generation & 0xFFFFu)) return false;
    container = (static_cast<uint64_t>(generation) << 32) | ((it >> 24) & 0xFFFFFFu);
    position = it & 0xFFFFFFu;
    return true;
}

Document& documentFor(uint64_t key) {
    static std::map<uint64_t, Document> documents;
    return documents[key];
}

std::vector<SaxEvent>& saxEventsFor(uint64_t key) {
    static std::map<uint64_t, std::vector<SaxEvent>> events;
    return events[key];
}

namespace {

// nlohmann's SAX interface -> the event list, with member/element counts.
struct Collector final : nlohmann::json_sax<Json> {
    std::vector<SaxEvent>& out;
    std::vector<int64_t> counts;  // values seen in each open container
    explicit Collector(std::vector<SaxEvent>& o) : out(o) {}
    void value(SaxEvent e) {
        if (!counts.empty()) ++counts.back();
        out.push_back(std::move(e));
    }
    bool null() override { value({SaxEvent::Null}); return true; }
    bool boolean(bool v) override { value({SaxEvent::Bool, v ? 1 : 0}); return true; }
    bool number_integer(number_integer_t v) override {
        value({v >= std::numeric_limits<int32_t>::min() ? SaxEvent::Dint : SaxEvent::Lint, v});
        return true;
    }
    bool number_unsigned(number_unsigned_t v) override {
        value({v <= std::numeric_limits<uint32_t>::max() ? SaxEvent::Udint : SaxEvent::Ulint, static_cast<int64_t>(v)});
        return true;
    }
    bool number_float(number_float_t v, const string_t&) override {
        SaxEvent e{SaxEvent::Lreal};
        e.real = v;
        value(std::move(e));
        return true;
    }
    bool string(string_t& v) override {
        SaxEvent e{SaxEvent::String};
        e.text = v;
        value(std::move(e));
        return true;
    }
    bool binary(binary_t&) override { return false; }
    bool start_object(std::size_t) override {
        value({SaxEvent::StartObject});
        counts.push_back(0);
        return true;
    }
    bool key(string_t& k) override {
        SaxEvent e{SaxEvent::Key};
        e.text = k;
        out.push_back(std::move(e));  // the member's value is counted, not its key
        return true;
    }
    bool end_object() override {
        out.push_back({SaxEvent::EndObject, counts.back()});
        counts.pop_back();
        return true;
    }
    bool start_array(std::size_t) override {
        value({SaxEvent::StartArray});
        counts.push_back(0);
        return true;
    }
    bool end_array() override {
        out.push_back({SaxEvent::EndArray, counts.back()});
        counts.pop_back();
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
};

}  // namespace

bool saxEvents(std::string_view text, std::vector<SaxEvent>& out) {
    out.clear();
    if (!nestingWithin(text)) return false;
    Collector collector(out);
    const bool ok = Json::sax_parse(text.begin(), text.end(), &collector, nlohmann::detail::input_format_t::json, true, false);
    if (!ok) out.clear();
    return ok;
}

std::string print(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

}  // namespace strun::stdlib::json
