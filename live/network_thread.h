// The priority of the threads that serve the network (Modbus server and
// client connections) against the scan.
#pragma once

namespace strun::live {

// Network threads yield the processor to the scan: nice +10 for the calling
// thread only (Linux applies setpriority to a thread id). A --realtime scan
// runs under SCHED_FIFO and is ahead of them anyway.
void lowerThreadPriority();

}  // namespace strun::live
