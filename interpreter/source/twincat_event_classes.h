// The event classes of a TwinCAT project and the globals TwinCAT generates
// from them (decision 0372). TwinCAT keeps an event class as a data type of
// its type system: a <DataType> with <EventId> children in the .tsproj
// (System > Type System > Event Classes) and in the .tmc files of the PLC
// project (its own .tmc, or an additional one the .tsproj names). From them
// TwinCAT generates the global lists TC_EVENT_CLASSES (one GUID per class)
// and TC_EVENTS (one structure per class, one TcEventEntry per event), which
// PLC code names as `TC_EVENTS.MyClass.MyEvent`. strun generates the same
// lists as ST, plus the texts of the classes for the event logger.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace strun::source {

struct TwinCatEvent {
    std::string name;         // <Name Id="2">Alarm</Name>
    std::uint32_t id = 0;     // its Id
    std::string text;         // <DisplayName>: the event text, with {0} ... for arguments
    std::string severity;     // Verbose, Info, Warning, Error or Critical (Info when missing or unknown)
};

struct TwinCatEventClass {
    std::string name;         // <Name GUID="{...}">MyClass</Name>
    std::uint8_t guid[16] = {};  // Data1 (4 bytes), Data2, Data3 (2 each), Data4 (8), as written
    std::string text;         // <DisplayName>: the class' display name
    std::vector<TwinCatEvent> events;
};

// The event classes declared in one .tsproj or .tmc text, appended to `out`
// (a class whose name is already there is skipped: the .tsproj and the .tmc
// repeat each other). Text that is not XML, or XML without event classes,
// adds nothing. A class needs a name that is an identifier and a GUID; an
// event needs a name that is an identifier and an Id.
void readTwinCatEventClasses(const std::string& xml, std::vector<TwinCatEventClass>& out);

// The ST of TC_EVENT_CLASSES, TC_EVENTS (and their structure types
// ST_<Class>) and of the block that gives the event logger the classes'
// texts (Tc3_EventLogger's I_strun_EventClasses). Empty for no classes.
std::string twinCatEventClassesSource(const std::vector<TwinCatEventClass>& classes);

// Whether ST text names TC_EVENTS or TC_EVENT_CLASSES (a lexical test, any case).
bool mentionsTwinCatEventLists(const std::string& text);

}  // namespace strun::source
