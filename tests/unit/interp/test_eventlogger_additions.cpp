// Session 15's Tc3_EventLogger additions: the query-language filter loads
// only when named (decision 0398), and TwinCAT's own event classes join a
// project's without replacing one it declares itself (decision 0400).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "interpreter/project/library_selection.h"
#include "interpreter/source/twincat_system_event_classes.h"

namespace {

bool selects(const std::string& text, const std::string& path) {
    for (const auto* src : strun::project::embeddedSourcesFor({text}))
        if (src->path == path) return true;
    return false;
}

const strun::source::TwinCatEventClass* find(const std::vector<strun::source::TwinCatEventClass>& classes, const std::string& name) {
    for (const auto& c : classes)
        if (c.name == name) return &c;
    return nullptr;
}

}  // namespace

TEST_CASE("a project using the event logger does not load the event filter", "[library][eventlogger]") {
    const std::string logger = "PROGRAM Main VAR l : FB_TcEventLogger; a : FB_TcAlarm; END_VAR l.ClearAlarms(0, FALSE, 0); END_PROGRAM";
    CHECK(selects(logger, "stdlib/Tc3_EventLogger/Tc3_EventLogger.st"));
    CHECK_FALSE(selects(logger, "stdlib/Tc3_EventLogger/event_filter.st"));
    CHECK_FALSE(selects(logger, "stdlib/Tc3_EventLogger/listeners.st"));
    CHECK_FALSE(selects(logger, "stdlib/Tc3_EventLogger/request_event_class_name.st"));
    const std::string filter = "PROGRAM Main VAR f : FB_TcEventFilter; END_VAR f.IsAlarm(); END_PROGRAM";
    CHECK(selects(filter, "stdlib/Tc3_EventLogger/event_filter.st"));
    CHECK(selects(filter, "stdlib/Tc3_EventLogger/Tc3_EventLogger.st"));
}

TEST_CASE("TwinCAT's own event classes are added beside a project's, never over one", "[eventlogger]") {
    std::vector<strun::source::TwinCatEventClass> classes(1);
    classes[0].name = "win32eventclass";  // the project's own, in another case
    classes[0].guid[0] = 0x11;
    strun::source::addTwinCatSystemEventClasses(classes);
    REQUIRE(classes.size() == 5);
    CHECK(classes[0].guid[0] == 0x11);  // kept as the project declares it
    const auto* system = find(classes, "TcSystemEventClass");
    REQUIRE(system != nullptr);
    REQUIRE(system->events.size() == 20);
    CHECK(system->events[1].name == "NoRTime");
    CHECK(system->events[1].id == 2);
    CHECK(system->events[1].severity == "Error");
    CHECK(find(classes, "TcGeneralAdsEventClass") != nullptr);
    CHECK(find(classes, "TcRouterEventClass") != nullptr);
    CHECK(find(classes, "TcRTimeEventClass") != nullptr);

    std::vector<strun::source::TwinCatEventClass> none;
    strun::source::addTwinCatSystemEventClasses(none);
    const auto* win32 = find(none, "Win32EventClass");
    REQUIRE(win32 != nullptr);
    const std::uint8_t expected[16] = {0x4a, 0xbe, 0xfb, 0xbf, 0x66, 0x20, 0x43, 0x49, 0x91, 0xad, 0xe6, 0x11, 0x0a, 0x3b, 0xe8, 0x51};
    CHECK(std::equal(expected, expected + 16, win32->guid));
}
