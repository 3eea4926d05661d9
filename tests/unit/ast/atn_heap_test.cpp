// grammar/atn_heap.h: what is made while a Scope is open comes from the
// ATN's region and deleting it does nothing; before and after, operator new
// and delete are malloc and free (decision 0499).
#include <catch2/catch.hpp>

#include "grammar/atn_heap.h"

#include <cstdint>
#include <string>
#include <vector>

using strun_grammar::AtnHeap;

#ifndef STRUN_SANITIZED  // there the sanitizers' operator new stays, and a Scope changes nothing
TEST_CASE("objects made in an ATN heap scope are bumped from its region; deleting them costs nothing") {
    // The parser's ATN was built at static initialisation, in the region (and
    // other tests may have built more ATNs in it since).
    const unsigned long atStart = AtnHeap::bytesUsed();
    CHECK(atStart > 50'000);

    std::vector<int>* kept = nullptr;
    std::uintptr_t first = 0, second = 0;
    {
        AtnHeap::Scope scope;
        auto* a = new std::uint64_t(1);
        auto* b = new std::uint64_t(2);
        first = reinterpret_cast<std::uintptr_t>(a);
        second = reinterpret_cast<std::uintptr_t>(b);
        kept = new std::vector<int>(1000, 7);
        delete a;  // nothing happens: the next object does not reuse it
        auto* c = new std::uint64_t(3);
        CHECK(reinterpret_cast<std::uintptr_t>(c) > second);
        delete b;
        delete c;
    }
    CHECK(second - first == alignof(std::max_align_t));  // one after the other, no malloc header between
    const unsigned long afterScope = AtnHeap::bytesUsed();
    CHECK(afterScope >= atStart + 4000 + 3 * alignof(std::max_align_t));

    // Closed: a vector grows through malloc, and what the scope made can still be
    // used and freed outside it.
    std::vector<std::string> grown;
    for (int i = 0; i < 1000; ++i) grown.push_back(std::string(100, char('a' + i % 26)));
    CHECK(AtnHeap::bytesUsed() == afterScope);
    CHECK((*kept)[999] == 7);
    kept->push_back(8);  // reallocates: the old buffer goes back to the region (nothing), the new from malloc
    CHECK(kept->back() == 8);
    delete kept;
    CHECK(AtnHeap::bytesUsed() == afterScope);
}
#endif
