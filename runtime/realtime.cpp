#include "runtime/realtime.h"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>

#include <cstring>

namespace strun::rt {

namespace {

std::string setFifo(pthread_t thread, int priority, const char* which) {
    sched_param param{};
    param.sched_priority = priority;
    int error = pthread_setschedparam(thread, SCHED_FIFO, &param);
    if (error == 0) return "";
    return std::string("cannot use SCHED_FIFO for the ") + which + " (" + std::strerror(error) +
           "); it runs with normal scheduling, so release jitter is not bounded";
}

}  // namespace

std::vector<std::string> enableRealtimeForThisThread(int priority) {
    std::vector<std::string> notes;
    if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
        notes.push_back(std::string("cannot lock memory with mlockall (") + std::strerror(errno) +
                        "); page faults may delay tasks");
    if (std::string note = setFifo(pthread_self(), priority, "PLC thread"); !note.empty()) notes.push_back(note);
    return notes;
}

std::string enableRealtimeForThread(std::thread& thread, int priority) {
    return setFifo(thread.native_handle(), priority, "timer thread");
}

}  // namespace strun::rt
