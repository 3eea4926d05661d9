// TwinCAT's own event classes (TcSystemEventClass, TcGeneralAdsEventClass,
// TcRouterEventClass, TcRTimeEventClass, Win32EventClass): TwinCAT puts them
// into TC_EVENT_CLASSES and TC_EVENTS on every system, but they are in no
// project file. strun adds them to a project's event classes (decision
// 0400) with what public sources show: Win32EventClass' GUID, the events of
// TcSystemEventClass that Beckhoff lists; the other GUIDs are strun's own.
#pragma once

#include <vector>

#include "interpreter/source/twincat_event_classes.h"

namespace strun::source {

// Appends each system class whose name is not in `classes` yet (a project
// that declares a class of the same name keeps its own).
void addTwinCatSystemEventClasses(std::vector<TwinCatEventClass>& classes);

}  // namespace strun::source
