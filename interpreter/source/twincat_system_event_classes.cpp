#include "interpreter/source/twincat_system_event_classes.h"

#include <algorithm>
#include <cstring>

#include "stdlib/number_scan.h"

namespace strun::source {
namespace {

struct SystemEvent {
    const char* name;
    std::uint32_t id;
    const char* text;
};

struct SystemClass {
    const char* name;
    const char* text;
    std::uint8_t guid[16];
    const SystemEvent* events;
    size_t eventCount;
};

// TcSystemEventClass: the events Beckhoff lists (TF6510 manual,
// "ST_TcSystemEventClass", all of severity Error), ids 1 to 20.
const SystemEvent systemEvents[] = {
    {"InternalError", 1, "Internal error"},
    {"NoRTime", 2, "No real-time"},
    {"AllocationLockedMemoryError", 3, "Allocation locked memory error"},
    {"InsertMailboxError", 4, "Mailbox full"},
    {"WrongReceiveHMSG", 5, "Wrong HMSG"},
    {"TargetPortNotFound", 6, "Target port not found"},
    {"TargetMachineNotFound", 7, "Target machine not found"},
    {"UnknownCommandID", 8, "Unknown command ID"},
    {"BadTaskID", 9, "Bad Task ID"},
    {"NoIO", 10, "No IO"},
    {"UnknownAdsCommand", 11, "Unknown ADS command"},
    {"Win32Error", 12, "Win32 error"},
    {"PortNotConnected", 13, "Port not closed"},
    {"InvalidAdsLength", 14, "Invalid ADS length"},
    {"InvalidAdsNetID", 15, "Invalid AMS Net ID"},
    {"LowInstallationLevel", 16, "low installation level"},
    {"NoDebugAvailable", 17, "No debugging available"},
    {"PortDisabled", 18, "Port disabled"},
    {"PortAlreadyConnected", 19, "Port already connected"},
    {"AdsSyncWin32Error", 20, "ADS Sync Win32 error"},
};

// strun's own GUIDs where no public source gives TwinCAT's:
// {5354524E-0000-0000-0000-00000000000n} ('STRN').
#define STRUN_GUID(n) {0x53, 0x54, 0x52, 0x4E, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, n}

const SystemClass systemClasses[] = {
    {"TcSystemEventClass", "TwinCAT System", STRUN_GUID(1), systemEvents, sizeof systemEvents / sizeof systemEvents[0]},
    {"TcGeneralAdsEventClass", "TwinCAT General ADS", STRUN_GUID(2), nullptr, 0},
    {"TcRouterEventClass", "TwinCAT Router", STRUN_GUID(3), nullptr, 0},
    {"TcRTimeEventClass", "TwinCAT Real-Time", STRUN_GUID(4), nullptr, 0},
    // Win32EventClass' GUID as TwinCAT's event logger uses it ({4abefbbf-6620-4349-91ad-e6110a3be851}).
    {"Win32EventClass", "Win32", {0x4a, 0xbe, 0xfb, 0xbf, 0x66, 0x20, 0x43, 0x49, 0x91, 0xad, 0xe6, 0x11, 0x0a, 0x3b, 0xe8, 0x51}, nullptr, 0},
};

#undef STRUN_GUID

}  // namespace

void addTwinCatSystemEventClasses(std::vector<TwinCatEventClass>& classes) {
    for (const SystemClass& s : systemClasses) {
        const bool declared = std::any_of(classes.begin(), classes.end(),
                                          [&](const TwinCatEventClass& c) { return stdlib::equalsIgnoreCase(c.name, s.name); });
        if (declared) continue;
        TwinCatEventClass c;
        c.name = s.name;
        c.text = s.text;
        std::memcpy(c.guid, s.guid, sizeof c.guid);
        for (size_t k = 0; k < s.eventCount; ++k) c.events.push_back({s.events[k].name, s.events[k].id, s.events[k].text, "Error"});
        classes.push_back(std::move(c));
    }
}

}  // namespace strun::source
