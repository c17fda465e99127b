// The C API's errors: the guard that turns every exception into a recorded error before
// it can reach C code, and the checks of the C layer's own arguments.
#pragma once

#include "jostle/error.hpp"

#include <climits>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <new>
#include <string>

namespace jostle::c_api {

// --- Errors (errors.cpp) ------------------------------------------------------------------

/// Records "function: message" as this thread's last error and calls the error handler.
void report(const char* function, const char* message) noexcept;

/// Reports the exception being handled under the C function's name: "out of memory", its
/// what(), or "unknown error". Called from a catch-all, out of line: one handler in each
/// entry point, not one per kind of exception.
void reportCurrentException(const char* function) noexcept;

/// Runs `body` and returns what it returns; if it throws anything, reports it under the
/// C function's name and returns `fallback` instead. Every C entry point runs in one, so
/// no exception ever crosses into C.
template <class Result, class Body>
Result guard(const char* function, Result fallback, Body&& body) noexcept {
    try {
        return body();
    } catch (...) {
        reportCurrentException(function);
    }
    return fallback;
}

/// Misuse found by the C layer itself: thrown inside a guard, reported by it.
[[noreturn]] inline void misuse(const std::string& message) {
    throw Error(message);
}
/// The same for a fixed message, out of line (no string made at each place that checks).
[[noreturn]] void misuse(const char* message);

/// Throws "<name> is NULL" (out of line: every entry point checks its pointers).
[[noreturn]] void nullArgument(const char* name);

template <class T> T& required(T* pointer, const char* name) {
    if (pointer == nullptr) [[unlikely]]
        nullArgument(name);
    return *pointer;
}

/// What jostle_default_*_def() writes into internal_cookie ("jost").
inline constexpr std::uint32_t kCookie = 0x6A6F7374u;

/// Catches a struct that is zeroed or uninitialised instead of made by its maker.
inline void requireCookie(std::uint32_t cookie, const char* what, const char* maker) {
    if (cookie != kCookie)
        misuse(std::string(what) + " was not made by " + maker +
               "() (start from it, then set the fields you need)");
}

/// The buffer rule of every function that returns several things.
inline void checkBuffer(const void* out, int capacity) {
    if (capacity < 0)
        misuse("capacity must be >= 0, got " + std::to_string(capacity));
    if (out == nullptr && capacity > 0)
        misuse("out is NULL but capacity is " + std::to_string(capacity));
}

/// A size as a C count (counts beyond INT_MAX cannot happen in practice: say INT_MAX).
inline int countOf(std::size_t size) {
    return size > static_cast<std::size_t>(INT_MAX) ? INT_MAX : static_cast<int>(size);
}

} // namespace jostle::c_api
