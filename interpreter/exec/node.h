// The resolved, typed tree the evaluator walks. The checker (sema) builds it:
// every name is already a storage location (an offset into the current
// instance, the current call frame, or an absolute address), every operator
// is specialised for its operand type. Evaluation allocates nothing and
// throws nothing; faults are reported to the runtime and evaluation goes on
// with the contract's substitute values until the next statement boundary.
#pragma once

#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <string>
#include <vector>

#include "interpreter/sema/types.h"
#include "runtime/machine.h"

namespace strun::exec {

using sema::Type;

// The evaluator's registers while one task runs its programs. One per task:
// a preempting task runs on its own Ctx (and its own frame stack).
// Bytes of the zeroed scratch that faulty accesses are redirected to.
constexpr size_t kFaultSinkSize = 1 << 16;

struct Ctx {
    uint8_t* self = nullptr;       // current PROGRAM / FUNCTION_BLOCK instance
    uint8_t* frame = nullptr;      // current call frame: function locals, VAR_TEMP, temporaries
    uint8_t* stackTop = nullptr;   // first free byte of the frame stack
    uint8_t* stackEnd = nullptr;
    int depth = 0;                 // POU call nesting (program body = 0)
    int jumpLabel = -1;            // pending JMP target while Flow::Jump unwinds
    bool aborting = false;         // the activation is being aborted (watchdog, STOP)
    uint8_t* pending = nullptr;    // frame of the call whose arguments are being bound
    const struct Stmt* stmt = nullptr;           // statement being executed (for WATCHDOG positions)
    const std::string* pouName = nullptr;        // POU being executed
    // While library code (the embedded ST standard library) runs: the user's
    // statement that called into it, and its POU. Faults and watchdog
    // positions are reported there, never inside strun's own sources.
    const struct Stmt* userStmt = nullptr;
    const std::string* userPou = nullptr;
    rt::Machine* m = nullptr;
    uint8_t* faultSink = nullptr;  // zeroed scratch that faulty accesses read from / write to
};

// Where a fault is reported from: the POU and the source line.
struct Site {
    const std::string* pou = nullptr;
    int line = 0;
    int file = -1;  // source index, for the fault report's FILE:LINE:COL
    int col = 0;
};

struct Expr {
    const Type* type = nullptr;
    virtual ~Expr() = default;
    // Integer-represented values (BOOL, integers, bit strings, TIME/DATE, chars, enums):
    // sign- or zero-extended to 64 bits according to the type.
    virtual int64_t i(Ctx&) { return 0; }
    // REAL / LREAL (a REAL is a float widened exactly).
    virtual double f(Ctx&) { return 0; }
    // Storage address: variables, members, elements, aggregates (strings, structs, arrays).
    virtual uint8_t* addr(Ctx&) { return nullptr; }
    // A place whose storage is a single bit (bit access x.3, BOOL AT %IX0.3).
    virtual int bitIndex() const { return -1; }
};

enum class Flow : uint8_t { Next, Exit, Continue, Return, Jump, Abort };

struct Stmt {
    int line = 0;
    int file = -1;  // source index and column: where a WATCHDOG stopped it
    int col = 0;
    virtual ~Stmt() = default;
    virtual Flow exec(Ctx&) = 0;
};

// The checker's test of a node's shape (fuse*.cpp, checker_*.cpp): does `n`
// have class To? Every node class the fusers look for is final, so its
// type_info alone answers, by one comparison of the names' addresses (and a
// string comparison when they differ), where dynamic_cast walked the class
// hierarchy: about 220 instructions a test, 6 % of `check` of a large file
// (decision 0493). Interfaces (FusedArith, Index1Target, ...) keep
// dynamic_cast, which gives the same answers.
template <class To, class From>
inline To* nodeCast(From* n) {
    if constexpr (std::is_final_v<To> && std::is_polymorphic_v<From> && std::is_base_of_v<std::remove_const_t<From>, To>) {
        return n && typeid(*n) == typeid(To) ? static_cast<To*>(n) : nullptr;
    } else {
        return dynamic_cast<To*>(n);
    }
}

// Owns every node of a loaded project: one arena of large blocks the nodes
// are constructed in, destroyed through their virtual destructors (Expr,
// Stmt) when the program is unloaded. No wrapper type per node class: a
// holder template per class was a third of the functions the compiler made
// for the fused nodes (decision 0261).
class NodePool {
public:
    NodePool() = default;
    NodePool(const NodePool&) = delete;
    NodePool& operator=(const NodePool&) = delete;
    ~NodePool();

    template <class T, class... Args>
    T* make(Args&&... args) {
        T* p = new (allocate(sizeof(T), alignof(T))) T(std::forward<Args>(args)...);
        if constexpr (std::is_base_of_v<Expr, T>) exprs_.push_back(p);
        else if constexpr (std::is_base_of_v<Stmt, T>) stmts_.push_back(p);
        else if constexpr (!std::is_trivially_destructible_v<T>) others_.push_back({p, [](void* q) { static_cast<T*>(q)->~T(); }});
        return p;
    }

private:
    void* allocate(size_t size, size_t align);
    static constexpr size_t kBlock = 64 * 1024;
    std::vector<std::unique_ptr<std::byte[]>> blocks_;
    std::byte* next_ = nullptr;
    std::byte* end_ = nullptr;
    std::vector<Expr*> exprs_;
    std::vector<Stmt*> stmts_;
    std::vector<std::pair<void*, void (*)(void*)>> others_;
};

template <class T>
inline T loadAs(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}
template <class T>
inline void storeAs(uint8_t* p, T v) {
    std::memcpy(p, &v, sizeof(T));
}

}  // namespace strun::exec
