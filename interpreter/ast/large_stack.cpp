#include "interpreter/ast/large_stack.h"

#include <pthread.h>

namespace strun::ast {

namespace {

void* trampoline(void* arg) {
    (*static_cast<const std::function<void()>*>(arg))();
    return nullptr;
}

}  // namespace

void runWithLargeStack(const std::function<void()>& work, std::size_t stackBytes) {
    pthread_attr_t attr;
    if (pthread_attr_init(&attr) != 0) {
        work();
        return;
    }
    pthread_t thread;
    const bool started = pthread_attr_setstacksize(&attr, stackBytes) == 0 &&
                         pthread_create(&thread, &attr, trampoline,
                                        const_cast<std::function<void()>*>(&work)) == 0;
    pthread_attr_destroy(&attr);
    if (started)
        pthread_join(thread, nullptr);
    else
        work();
}

}  // namespace strun::ast
