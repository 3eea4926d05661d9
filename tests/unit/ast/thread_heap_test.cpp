// growThisThreadsHeap (interpreter/ast/thread_heap.h, decision 0494): the
// arena of a new thread holds the room asked for, free, once it returns.
#include <catch2/catch.hpp>

#include <malloc.h>

#include <thread>

#include "interpreter/ast/thread_heap.h"

TEST_CASE("growThisThreadsHeap: a new thread's arena grows by the room asked for, left free", "[thread_heap]") {
    mallopt(M_MMAP_THRESHOLD, 8 << 20);  // as cli/main.cpp sets them
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    struct mallinfo2 before {}, after {};
    std::thread worker([&] {
        before = mallinfo2();
        strun::ast::growThisThreadsHeap(20u << 20);
        after = mallinfo2();
    });
    worker.join();
#ifdef STRUN_SANITIZED
    // ASan's allocator is not glibc's: mallinfo2 says nothing there (all
    // zero), and the call only has to return.
    SUCCEED("sanitizer build: growThisThreadsHeap returned");
#else
    // Three pieces of 7 MiB, from the arena (not mapped one by one), all free again.
    CHECK(after.arena >= before.arena + (20u << 20));
    CHECK(after.fordblks >= before.fordblks + (20u << 20));
    CHECK(after.uordblks <= before.uordblks + (64u << 10));
    CHECK(after.hblks == before.hblks);
#endif
}
