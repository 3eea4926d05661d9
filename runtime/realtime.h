// --realtime: SCHED_FIFO for the PLC threads and mlockall, where the system
// permits it. Never fatal: what could not be done is returned as
// human-readable notes, which the scheduler prints as warnings.
#pragma once

#include <string>
#include <thread>
#include <vector>

namespace strun::rt {

// Locks the process memory and gives the calling thread SCHED_FIFO priority
// `priority`. Returns one note per thing that failed (empty: all granted).
std::vector<std::string> enableRealtimeForThisThread(int priority);
// SCHED_FIFO for another thread (the attention timer); "" or a note.
std::string enableRealtimeForThread(std::thread& thread, int priority);

}  // namespace strun::rt
