#include "interpreter/source/twincat_event_classes.h"
#include "interpreter/source/twincat_global_types.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <pugixml.hpp>

#include "stdlib/literals.h"
#include "stdlib/number_scan.h"

namespace strun::source {

namespace {

std::string ecTrimmed(const std::string& s) {
    const auto blank = [](unsigned char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    size_t first = 0, last = s.size();
    while (first < last && blank(static_cast<unsigned char>(s[first]))) ++first;
    while (last > first && blank(static_cast<unsigned char>(s[last - 1]))) --last;
    return s.substr(first, last - first);
}

bool ecIsIdentifier(const std::string& s) {
    if (s.empty() || s.size() > 127) return false;
    if (!std::isalpha(static_cast<unsigned char>(s[0])) && s[0] != '_') return false;
    return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

int ecHexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// "{A2DF9140-A915-47B1-9901-35CC79B09E92}" (braces optional) -> 16 bytes in
// written order: Data1, Data2, Data3, then Data4[0..7].
bool ecParseGuid(std::string text, std::uint8_t out[16]) {
    text = ecTrimmed(text);
    if (text.size() == 38 && text.front() == '{' && text.back() == '}') text = text.substr(1, 36);
    if (text.size() != 36 || text[8] != '-' || text[13] != '-' || text[18] != '-' || text[23] != '-') return false;
    std::string hex;
    for (char c : text)
        if (c != '-') hex += c;
    for (int k = 0; k < 16; ++k) {
        const int hi = ecHexDigit(hex[2 * k]), lo = ecHexDigit(hex[2 * k + 1]);
        if (hi < 0 || lo < 0) return false;
        out[k] = static_cast<std::uint8_t>(hi * 16 + lo);
    }
    return true;
}

std::string ecSeverity(const std::string& s) {
    static const char* const names[] = {"Verbose", "Info", "Warning", "Error", "Critical"};
    for (const char* n : names)
        if (stdlib::equalsIgnoreCase(s, n)) return n;
    return "Info";
}

// An ST string literal of at most 255 bytes of text.
std::string ecStString(const std::string& text) { return stdlib::quoteStringLiteral(std::string_view(text).substr(0, 255)); }

std::string ecHexByte(std::uint8_t b) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "16#%02X", b);
    return buf;
}

std::string ecGuidInit(const std::uint8_t g[16]) {
    char head[80];
    std::snprintf(head, sizeof head, "(Data1 := 16#%02X%02X%02X%02X, Data2 := 16#%02X%02X, Data3 := 16#%02X%02X, Data4 := [", g[0], g[1],
                  g[2], g[3], g[4], g[5], g[6], g[7]);
    std::string s = head;
    for (int k = 8; k < 16; ++k) s += (k > 8 ? ", " : "") + ecHexByte(g[k]);
    return s + "])";
}

}  // namespace

void readTwinCatEventClasses(const std::string& xml, std::vector<TwinCatEventClass>& out) {
    pugi::xml_document doc;
    if (!doc.load_buffer(xml.data(), xml.size())) return;
    // <TcSmProject><DataTypes> (.tsproj) or <TcModuleClass><DataTypes> (.tmc).
    for (pugi::xml_node dataType : doc.document_element().child("DataTypes").children("DataType")) {
        if (!dataType.child("EventId")) continue;
        TwinCatEventClass cls;
        const pugi::xml_node name = dataType.child("Name");
        cls.name = ecTrimmed(name.text().as_string());
        if (!ecIsIdentifier(cls.name) || !ecParseGuid(name.attribute("GUID").as_string(), cls.guid)) continue;
        const bool known = std::any_of(out.begin(), out.end(), [&](const TwinCatEventClass& c) { return stdlib::equalsIgnoreCase(c.name, cls.name); });
        if (known) continue;
        cls.text = dataType.child("DisplayName").text().as_string();
        for (pugi::xml_node ev : dataType.children("EventId")) {
            TwinCatEvent e;
            const pugi::xml_node evName = ev.child("Name");
            e.name = ecTrimmed(evName.text().as_string());
            const pugi::xml_attribute id = evName.attribute("Id");
            if (!ecIsIdentifier(e.name) || !id) continue;
            const std::string idText = ecTrimmed(id.as_string());
            if (idText.empty() || !std::all_of(idText.begin(), idText.end(), [](unsigned char c) { return std::isdigit(c); }) ||
                idText.size() > 10)
                continue;
            const unsigned long long value = std::stoull(idText);
            if (value > 0xFFFFFFFFull) continue;
            e.id = static_cast<std::uint32_t>(value);
            e.text = ev.child("DisplayName").text().as_string();
            e.severity = ecSeverity(ecTrimmed(ev.child("Severity").text().as_string()));
            const bool twice = std::any_of(cls.events.begin(), cls.events.end(), [&](const TwinCatEvent& o) { return stdlib::equalsIgnoreCase(o.name, e.name); });
            if (!twice) cls.events.push_back(std::move(e));
        }
        out.push_back(std::move(cls));
    }
}

std::string twinCatEventClassesSource(const std::vector<TwinCatEventClass>& classes) {
    if (classes.empty()) return {};
    std::string st =
        "(* TC_EVENT_CLASSES and TC_EVENTS, generated by strun from the event classes of the project's\n"
        "   .tsproj and .tmc files, as TwinCAT generates them (decision 0372). *)\n";
    for (const TwinCatEventClass& c : classes) {
        st += "TYPE ST_" + c.name + " :\nSTRUCT\n";
        for (const TwinCatEvent& e : c.events)
            st += "    " + e.name + " : TcEventEntry := (uuidEventClass := " + ecGuidInit(c.guid) + ", nEventId := " + std::to_string(e.id) +
                  ", eSeverity := TcEventSeverity." + e.severity + ");\n";
        st += "END_STRUCT\nEND_TYPE\n";
    }
    st += "NAMESPACE TC_EVENT_CLASSES\n{attribute 'qualified_only'}\nVAR_GLOBAL CONSTANT\n";
    for (const TwinCatEventClass& c : classes) st += "    " + c.name + " : GUID := " + ecGuidInit(c.guid) + ";\n";
    st += "END_VAR\nEND_NAMESPACE\n";
    st += "NAMESPACE TC_EVENTS\n{attribute 'qualified_only'}\nVAR_GLOBAL CONSTANT\n";
    for (const TwinCatEventClass& c : classes) st += "    " + c.name + " : ST_" + c.name + ";\n";
    st += "END_VAR\nEND_NAMESPACE\n";
    // The texts, for FB_TcEventBase's log lines, RequestEventText, sEventText
    // and sEventClassName: the block hands itself to the library at start-up.
    st +=
        "FUNCTION_BLOCK FB_strun_ProjectEventClasses IMPLEMENTS I_strun_EventClasses\n"
        "METHOD FB_init : BOOL\nVAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR\n"
        "_strun_EventClasses := THIS^;\nEND_METHOD\n"
        "METHOD strun_ClassName : STRING(255)\nVAR_INPUT EventClass : GUID; END_VAR\n";
    for (const TwinCatEventClass& c : classes)
        st += "IF F_strun_SameGuid(EventClass, TC_EVENT_CLASSES." + c.name + ") THEN strun_ClassName := " + ecStString(c.text) +
              "; RETURN; END_IF\n";
    st += "END_METHOD\nMETHOD strun_EventText : STRING(255)\nVAR_INPUT EventClass : GUID; nEventId : UDINT; END_VAR\n";
    for (const TwinCatEventClass& c : classes) {
        if (c.events.empty()) continue;
        st += "IF F_strun_SameGuid(EventClass, TC_EVENT_CLASSES." + c.name + ") THEN\n    CASE nEventId OF\n";
        std::vector<std::uint32_t> seen;
        for (const TwinCatEvent& e : c.events) {
            if (std::find(seen.begin(), seen.end(), e.id) != seen.end()) continue;  // the first of an Id given twice
            seen.push_back(e.id);
            st += "    " + std::to_string(e.id) + ": strun_EventText := " + ecStString(e.text) + ";\n";
        }
        st += "    END_CASE\n    RETURN;\nEND_IF\n";
    }
    st += "END_METHOD\nEND_FUNCTION_BLOCK\nVAR_GLOBAL\n    _strun_ProjectEventClasses : FB_strun_ProjectEventClasses;\nEND_VAR\n";
    return st;
}

bool mentionsTwinCatEventLists(const std::string& text) {
    return mentionsWord(text, "tc_events") || mentionsWord(text, "tc_event_classes");
}

}  // namespace strun::source
