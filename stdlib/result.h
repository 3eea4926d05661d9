// The outcome of a value function that can fail on bad input: either a value
// or a human-readable error message. The stdlib never throws; callers turn the
// message into a diagnostic ("invalid duration literal: ...") or fall back to
// the documented default value of the IEC function.
#pragma once

#include <string>
#include <utility>

namespace strun::stdlib {

template <typename T>
class Result {
public:
    static Result success(T value) { return Result(std::move(value), {}); }
    // A failure always carries a non-empty message, so ok() can rely on it.
    static Result failure(std::string message) {
        if (message.empty()) message = "invalid value";
        return Result(T{}, std::move(message));
    }

    bool ok() const { return error_.empty(); }
    explicit operator bool() const { return ok(); }

    // The value; T{} when !ok().
    const T& value() const { return value_; }
    T valueOr(T fallback) const { return ok() ? value_ : std::move(fallback); }
    // Empty when ok().
    const std::string& error() const { return error_; }

private:
    Result(T value, std::string error) : value_(std::move(value)), error_(std::move(error)) {}
    T value_;
    std::string error_;
};

}  // namespace strun::stdlib
