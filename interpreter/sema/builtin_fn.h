// One built-in function's check as data: a plain function pointer and the
// few values it was registered with (an enum, a type kind, a pointer to a
// static table), instead of a std::function around a capturing lambda.
// Registering one then allocates nothing, and the registration code compiles
// without a std::function instantiation per lambda (decision 0487).
#pragma once

#include <cstring>
#include <type_traits>

namespace strun::sema {

class Checker;
struct CallArgs;
struct Checked;

class BuiltinFn {
public:
    // A check that reads what it was registered with through `self.data<D>()`.
    using Check = Checked (*)(Checker&, CallArgs&, const BuiltinFn& self);
    // A check that needs nothing else.
    using Plain = Checked (*)(Checker&, CallArgs&);
    static constexpr size_t kDataBytes = 32;

    BuiltinFn() = default;
    BuiltinFn(Plain f) : check_(&callPlain) { store(f); }  // NOLINT: a function is a BuiltinFn
    // A capture-less lambda (or function template specialization) of the plain shape.
    template <class F>
        requires(std::is_convertible_v<F, Plain> && !std::is_same_v<std::decay_t<F>, Plain>)
    BuiltinFn(F f) : BuiltinFn(static_cast<Plain>(f)) {}  // NOLINT
    // `check` with its data `d` (trivially copyable, at most kDataBytes).
    template <class D>
    BuiltinFn(Check check, const D& d) : check_(check) {
        store(d);
    }

    template <class D>
    D data() const {
        static_assert(std::is_trivially_copyable_v<D> && sizeof(D) <= kDataBytes);
        D d;
        std::memcpy(static_cast<void*>(&d), bytes_, sizeof d);
        return d;
    }
    Checked operator()(Checker& ck, CallArgs& call) const;
    explicit operator bool() const { return check_ != nullptr; }

private:
    template <class D>
    void store(const D& d) {
        static_assert(std::is_trivially_copyable_v<D> && sizeof(D) <= kDataBytes,
                      "a built-in's data is a few plain values (point to a static table for more)");
        std::memcpy(bytes_, static_cast<const void*>(&d), sizeof d);
    }
    static Checked callPlain(Checker& ck, CallArgs& call, const BuiltinFn& self);

    Check check_ = nullptr;
    alignas(8) unsigned char bytes_[kDataBytes] = {};
};

}  // namespace strun::sema
