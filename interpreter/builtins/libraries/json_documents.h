// The documents behind Tc3_JsonXml's FB_JsonDomParser and FB_JsonSaxReader
// (stdlib/libraries/Tc3_JsonXml, decision 0285): one JSON tree
// (nlohmann::ordered_json, members kept in insertion order as TwinCAT's
// RapidJSON does) per parser instance, keyed by the instance's address.
//
// An SJsonValue is a handle, never a host pointer: the document's
// generation in the upper 32 bits and 1 + the index of a JSON pointer (the
// value's path) in the lower. A handle of an older document (re-parsed,
// NewDocument) or of a removed value resolves to nothing, so a stale or
// made-up handle is a failed call, never a crash. Iterators
// (SJsonIterator/SJsonAIterator) are (generation, container, position).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

namespace strun::stdlib::json {

using Json = nlohmann::ordered_json;

// Deeper documents are refused before parsing (the tree's recursive
// destruction and printing must not exhaust the stack).
constexpr int kMaxDepth = 256;
// True when `text` nests arrays/objects at most kMaxDepth deep.
bool nestingWithin(std::string_view text);

struct Document {
    Json root = Json::object();
    uint32_t generation = 0;
    std::vector<Json::json_pointer> paths;             // handle index -> path
    std::unordered_map<std::string, uint32_t> byPath;  // path text -> handle index

    void reset(Json value);
    uint64_t handleOf(const Json::json_pointer& path);
    // The value a handle names in this document, or null.
    Json* resolve(uint64_t handle);
    // The path of a handle (valid after a successful resolve).
    const Json::json_pointer* pathOf(uint64_t handle) const;
    uint64_t iterator(uint64_t container, uint64_t position) const;
    // Container handle and position of an iterator; false if it is not this document's.
    bool splitIterator(uint64_t it, uint64_t& container, uint64_t& position) const;
};

// The document of the parser instance at `key` (created empty on first use).
Document& documentFor(uint64_t key);

// One SAX event of FB_JsonSaxReader, in document order.
struct SaxEvent {
    enum Kind : uint8_t { StartObject = 1, EndObject, StartArray, EndArray, Key, String, Null, Bool, Dint, Udint, Lint, Ulint, Lreal };
    Kind kind;
    int64_t integer = 0;  // Bool, the integers (ULINT as its bits), member/element count at the end of a container
    double real = 0;
    std::string text{};   // Key, String ({}: an event built from its kind alone is complete, -Wmissing-field-initializers)
};
// The events of `text`, or false when it is not valid JSON.
bool saxEvents(std::string_view text, std::vector<SaxEvent>& out);
std::vector<SaxEvent>& saxEventsFor(uint64_t key);

// Text of a value as the documents print it (UTF-8, invalid bytes replaced).
std::string print(const Json& value);

}  // namespace strun::stdlib::json
