#pragma once
// Error handling without exceptions across the public API (many engines build with them off).
// A Result<T> holds either a value or an Error whose message names the object and the problem.
#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace caustics {

struct Error {
    std::string message;
};

template <typename T>
class [[nodiscard]] Result {
public:
    Result(T value) : state_(std::move(value)) {}
    Result(Error error) : state_(std::move(error)) {}

    bool ok() const { return state_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { assert(ok()); return std::get<0>(state_); }
    const T& value() const& { assert(ok()); return std::get<0>(state_); }
    T&& value() && { assert(ok()); return std::get<0>(std::move(state_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }

    const Error& error() const { assert(!ok()); return std::get<1>(state_); }
    const std::string& message() const { return error().message; }

private:
    std::variant<T, Error> state_;
};

// Result of an operation that yields nothing but may fail.
struct Ok {};
using Status = Result<Ok>;
inline Status okStatus() { return Ok{}; }

inline Error makeError(std::string message) { return Error{std::move(message)}; }

}  // namespace caustics

// Propagates an error from an expression returning Result/Status: `CAUSTICS_TRY(x, makeThing());`
#define CAUSTICS_CONCAT_INNER(a, b) a##b
#define CAUSTICS_CONCAT(a, b) CAUSTICS_CONCAT_INNER(a, b)
#define CAUSTICS_TRY(lhs, expr)                                              \
    auto CAUSTICS_CONCAT(tryResult_, __LINE__) = (expr);                      \
    if (!CAUSTICS_CONCAT(tryResult_, __LINE__)) return CAUSTICS_CONCAT(tryResult_, __LINE__).error(); \
    lhs = std::move(CAUSTICS_CONCAT(tryResult_, __LINE__)).value()
#define CAUSTICS_CHECK(expr)                                                  \
    do {                                                                      \
        auto checkResult_ = (expr);                                           \
        if (!checkResult_) return checkResult_.error();                       \
    } while (0)
