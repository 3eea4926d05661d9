// The heap the parser's ATN is built in (decision 0499).
//
// The generated parser builds its ATN once, at static initialisation: about
// 4 000 small objects (states, transitions, their vectors and sets) that
// live until the process ends. From malloc each cost about 140
// instructions, a fresh heap's slow path: a sixth of a one-line `strun run`.
// While an AtnHeap::Scope is open on the thread that builds it, the global
// operator new bumps through one block instead; operator delete of a pointer
// into the block does nothing (the ATN is never freed before exit, and the
// few vectors that grow while it is built leave their old buffers behind).
// Everything else goes to malloc and free as before.
#pragma once

namespace strun_grammar {

class AtnHeap {
public:
    // Opens the heap for the objects made while it lives (one at a time).
    class Scope {
    public:
        Scope();
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;
    };
    // Bytes handed out from the heap's blocks so far (for tests).
    static unsigned long bytesUsed();
};

}  // namespace strun_grammar
