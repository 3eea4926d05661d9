#include "interpreter/ast/large_stack.h"

#include <pthread.h>

namespace strun::ast {

namespace {

// Set on the threads this file starts: work for a large stack then runs
// where it is, without a thread of its own.
thread_local bool onLargeStack = false;

void* trampoline(void* arg) {
    onLargeStack = true;
    (*static_cast<const std::function<void()>*>(arg))();
    return nullptr;
}

// Starts `work` on a new thread with a stack of `stackBytes`; false if
// the thread could not be made.
bool startWithLargeStack(const std::function<void()>& work, std::size_t stackBytes, pthread_t& thread) {
    pthread_attr_t attr;
    if (pthread_attr_init(&attr) != 0) return false;
    const bool started = pthread_attr_setstacksize(&attr, stackBytes) == 0 &&
                         pthread_create(&thread, &attr, trampoline, const_cast<std::function<void()>*>(&work)) == 0;
    pthread_attr_destroy(&attr);
    return started;
}

}  // namespace

void runWithLargeStack(const std::function<void()>& work, std::size_t stackBytes) {
    if (onLargeStack) {
        work();
        return;
    }
    pthread_t thread;
    if (startWithLargeStack(work, stackBytes, thread))
        pthread_join(thread, nullptr);
    else
        work();
}

void runInParallelWithLargeStacks(const std::function<void()>& a, const std::function<void()>& b, std::size_t stackBytes) {
    pthread_t thread;
    const bool started = startWithLargeStack(a, stackBytes, thread);
    runWithLargeStack(b, stackBytes);
    if (started)
        pthread_join(thread, nullptr);
    else
        runWithLargeStack(a, stackBytes);
}

}  // namespace strun::ast
