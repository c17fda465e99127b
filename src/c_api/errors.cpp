// The C API's error state: the last message of each thread and the process's handler.
#include "c_api.hpp"

#include <cstdio>
#include <mutex>

namespace {

// A fixed buffer, not a std::string: recording an error must work when memory has run
// out, and must not throw.
constexpr std::size_t kMessageSize = 512;
thread_local char lastMessage[kMessageSize] = "";
/// Set while this thread runs the handler, so that a misuse inside it is only recorded.
thread_local bool inHandler = false;

std::mutex handlerMutex;
jostle_error_fn handler = nullptr;
void* handlerContext = nullptr;

} // namespace

namespace jostle::c_api {

void report(const char* function, const char* message) noexcept {
    std::snprintf(lastMessage, kMessageSize, "%s: %s", function, message);
    if (inHandler)
        return;
    jostle_error_fn fn = nullptr;
    void* context = nullptr;
    try {
        const std::lock_guard lock(handlerMutex);
        fn = handler;
        context = handlerContext;
    } catch (...) {
        return; // the mutex failed: the message is recorded, the handler is skipped
    }
    if (fn == nullptr)
        return;
    // The handler gets its own copy: a misuse inside it overwrites lastMessage.
    char message_copy[kMessageSize];
    std::snprintf(message_copy, kMessageSize, "%s", lastMessage);
    inHandler = true;
    try {
        fn(message_copy, context);
    } catch (...) {
        // A C++ handler threw: it must not cross the C function that is returning.
    }
    inHandler = false;
}

void reportCurrentException(const char* function) noexcept {
    try {
        throw;
    } catch (const std::bad_alloc&) {
        report(function, "out of memory");
    } catch (const std::exception& e) {
        report(function, e.what());
    } catch (...) {
        report(function, "unknown error");
    }
}

void misuse(const char* message) {
    throw Error(message);
}

void nullArgument(const char* name) {
    misuse(std::string(name) + " is NULL");
}

} // namespace jostle::c_api

extern "C" {

const char* jostle_last_error(void) {
    return lastMessage;
}

void jostle_clear_error(void) {
    lastMessage[0] = '\0';
}

void jostle_set_error_handler(jostle_error_fn fn, void* context) {
    try {
        const std::lock_guard lock(handlerMutex);
        handler = fn;
        handlerContext = context;
    } catch (...) {
        jostle::c_api::report(__func__, "could not lock the handler's mutex");
    }
}

} // extern "C"
